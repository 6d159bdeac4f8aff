#pragma once
// The pieces of one free-space component as rooms in the making (internal to the module): which
// pieces form each room (union-find), which cuts separate two rooms, and the measures that merging
// decides by (chords, widths and depths beside a cut, areas, thickness, convex hulls). Grid
// coordinates (one unit per cell); every measure it returns is in metres.
#include <map>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/cut_rule.h"
#include "topocut/core/geometry.h"
#include "topocut/segmentation/merge_criteria.h"
#include "topocut/segmentation/room_merging.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut {

class RoomGraph {
 public:
  // One cut between two pieces; left < 0 for a cut that separates no two pieces (a keyhole).
  struct Side {
    int left = -1, right = -1;  // pieces left and right of the cut (a -> b)
    double length = 0.0;        // metres
    CutRule rule = CutRule::kDecomposition;
    bool furniture = false;     // an end lies on a furniture-sized obstacle
    // The free space's angle at each end (radians summed over the pieces meeting there: pi in a
    // straight wall, 3 pi / 2 at a door jamb, 2 pi at a wall's end, pi / 2 in a room's corner), smaller first.
    double end_angle[2] = {0.0, 0.0};
    double wall_continued = 0.0;  // m: the longest wall edge at an end that the cut continues straight on
    int ends_on_holes = 0;        // ends that lie on an obstacle inside the component (a hole)
    double hole_extent = 0.0;     // m: the largest bounding-box side of those obstacles
    // The larger over both ends of the angle between the cut and the nearest wall direction there,
    // folded into [0, pi / 4]: 0 when the cut runs along or across the walls it ends on (a door, a
    // wall continued), pi / 4 for a diagonal across a corner.
    double skew = 0.0;
  };

  // polygon is the component (its small holes are furniture); furniture_size in metres, 0: none.
  // cells are the grid the component was traced from (OccupancyGrid::cells, the pieces' frame), to
  // tell walls from never-seen space along the outlines; empty: every outline counts as wall.
  RoomGraph(const PolygonWithHoles& polygon, const PieceSet& set, const cv::Mat& cells, double resolution,
            double furniture_size);

  const PieceSet& set() const { return set_; }
  double resolution() const { return resolution_; }
  const std::vector<Side>& sides() const { return sides_; }
  std::size_t piece_count() const { return parent_.size(); }
  // The component's own scale, measured before any merge, for features that read the same whatever
  // a kind's sizes (a home's closet and an office beside an office's corridor): the area-weighted
  // median thickness (2 area / perimeter) of its pieces, and the median length of its cuts (m).
  double piece_scale() const { return piece_scale_; }
  double cut_scale() const { return cut_scale_; }

  // The room (root piece) holding piece i.
  int root(int i);
  // Merges the rooms of pieces a and b; the room keeps its first piece as root.
  void unite(int a, int b);
  // The pieces of room r (r a root).
  const std::vector<int>& members(int r) const { return members_[static_cast<std::size_t>(r)]; }
  // Whether cut k now separates two different rooms.
  bool separates(std::size_t k);

  double room_area(int r);       // m²
  double room_perimeter(int r);  // m, without the cuts inside the room
  double room_thickness(int r);  // 2 area / perimeter, m: a strip's width, half a square's side
  double convex_hull_area(const std::vector<int>& rooms);  // m², of the rooms' pieces together
  // The rooms' elongation together: the square root of the ratio of the principal second moments
  // of their area (1 for a square or a disc, about L / W for an L x W strip).
  double elongation(const std::vector<int>& rooms);
  // Share of room r's own outline (own_outline(): its perimeter but the cuts to other rooms) that runs
  // along occupied cells (walls, furniture), and along never-seen cells (the sensor saw no wall there:
  // a ray fan's rim, an opening to the dark).
  double wall_share(int r);
  double unknown_share(int r);
  double own_outline(int r);  // m
  // Whether the grid holds an occupied cell (or is not known): without, the map draws its walls in the
  // never-seen grey, and walls cannot be told from the dark. Looked at when first asked.
  bool walls_seen();
  // Length of the cuts between rooms r and s (m); s < 0: between r and every other room.
  double shared_cut_length(int r, int s);
  // The cuts with a piece of room r on a side, ascending, each once: what a measure of r reads
  // instead of every cut of the component (which made merging quadratic in the cuts). The reference
  // holds until the next unite().
  const std::vector<std::size_t>& room_sides(int r);

  // Width of room r beside cut k (m): the longest chord parallel to the cut within depth metres on
  // r's side (left: the cut's left), measured as the cut rules measure it (side_width.h).
  double side_width(std::size_t k, int r, bool left, double depth);
  // Depth of room r behind cut k (m): its chord along the cut's normal through the cut's middle.
  double side_depth(std::size_t k, int r, bool left);

  // The rooms in the order of their first piece, each the union of its pieces, and the cuts between
  // two rooms in input order.
  PieceSet result();

 private:
  struct Edges;  // the pieces' edges, looked up by the measures below
  void find_sides(const Edges& edges);
  void measure_cut_ends(const Edges& edges);
  void mark_furniture(const PolygonWithHoles& polygon, double furniture_size);
  void measure_scales();
  void measure_outlines(const Edges& edges, const cv::Mat& cells);
  // The lengths (m) of room r's outline along occupied and along never-seen cells: the shares' numerators.
  double wall_length(int r);
  double unknown_length(int r);
  double chord(int r, const Point2& p, const Point2& u);
  std::vector<double> chord_ts_;  // chord()'s crossings and spans, kept to spare their allocations
  std::vector<std::pair<double, double>> chord_spans_;
  double measure_side_width(std::size_t k, int r, bool left, double depth);

  const PieceSet& set_;
  double resolution_;
  double piece_scale_ = 0.0, cut_scale_ = 0.0;
  std::vector<int> parent_;
  std::vector<std::vector<int>> members_;  // room root -> its pieces
  std::vector<Box> boxes_;
  std::vector<std::vector<std::vector<Box>>> chunks_;  // per piece, outer ring then holes: ring_chunks() for chord()
  std::vector<double> areas_;       // m² per piece
  std::vector<double> perimeters_;  // m per piece
  cv::Mat cells_;                     // the grid (a header: no copy of the cells)
  std::optional<bool> walls_seen_;
  std::vector<double> wall_lengths_, unknown_lengths_;  // m per piece: outline along walls, along never-seen cells
  struct Moments {
    double a = 0.0, x = 0.0, y = 0.0, xx = 0.0, xy = 0.0, yy = 0.0;  // integrals of 1, x, y, x², xy, y² (cells)
  };
  std::vector<Moments> moments_;    // per piece
  std::vector<Side> sides_;
  std::vector<std::vector<std::size_t>> piece_sides_;  // piece -> the cuts it lies beside, ascending
  std::map<int, double> area_sum_;  // room root -> area (m², rooms of 2+ pieces)
  // Room root -> the convex hull of its pieces (cells), kept through merges: a room's hull is the hull
  // of its parts' hulls, so growing a long corridor does not take the hull of all its vertices again.
  std::map<int, std::vector<Point2>> hulls_;
  const std::vector<Point2>& room_hull(int r);
  // side_width's last answer per cut and side, with the room it was measured in: a room only grows,
  // so the same root with as many pieces is the same room, and a cut measured again after the room
  // across it grew reads the unchanged side here.
  struct SideWidth {
    int room = -1;
    std::size_t pieces = 0;
    double depth = 0.0, width = 0.0;
  };
  std::vector<SideWidth> side_widths_;  // 2 k: left of cut k, 2 k + 1: right
  // side_depth's last answer per cut and side, kept as side_widths_ are.
  std::vector<SideWidth> side_depths_;
  // What the measures of a room read, per room root, kept while the room has as many pieces (a room
  // only grows, so that is the same room): its cuts, perimeter and cuts to other rooms, which every
  // feature of every cut beside the room asked for again (each a walk over the room's pieces and cuts).
  struct RoomMeasures {
    std::size_t pieces = 0;  // 0: not measured yet
    std::vector<std::size_t> sides;
    double perimeter = 0.0, open = 0.0;  // m: room_perimeter(), shared_cut_length(r, -1)
    std::optional<double> hull_area;     // m²: convex_hull_area({r}), when first asked
  };
  std::vector<RoomMeasures> room_measures_;
  RoomMeasures& measures(int r);  // r's, measured again when it grew
};

}  // namespace topocut

namespace topocut {

// One component's rooms while the rows after the decomposition (segmentation_rules.h) act on them.
struct ComponentMerge {
  RoomGraph& graph;
  const RoomMergeOptions& options;
  std::vector<const MergeCriterion*> criteria;  // the list's criteria that are on, in its order
  std::vector<MergeStep>* trace = nullptr;       // learned merging: receives every merge weighed
};

// Merges across the cuts the criteria decide to merge (merge_criteria.h), the highest priority first;
// the grown room's cuts are judged again.
void merge_by_criteria(ComponentMerge& merge);

// Rooms too small or too thin to be rooms join the neighbour they share the longest cut with.
void fold_small_rooms(ComponentMerge& merge);

// Small rooms walled along little of their outline (RoomMergeOptions::fragment_area) join the
// neighbour they share the longest cut with: scraps of floor the cuts left, not closets.
void fold_fragments(ComponentMerge& merge);

// A room much smaller than a neighbour (RoomMergeOptions::bay_area_ratio) whose cuts to it, door rules'
// cuts left out, are a large share of its outline (bay_share) joins it: a bay, a wedge or a strip cut
// off a room along a diagonal or a wall line.
void fold_bays(ComponentMerge& merge);

// The features (merge_features.h) of merging the two rooms on the sides of cut k of graph.
std::vector<double> merge_features(RoomGraph& graph, std::size_t k, const RoomMergeOptions& options);

}  // namespace topocut
