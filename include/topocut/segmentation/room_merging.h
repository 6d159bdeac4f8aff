#pragma once
// Pieces -> rooms: DuDe cuts a free-space component into nearly convex pieces, but rooms are not
// convex pieces (an L-shaped corridor is at least two). This stage merges pieces across cuts that
// are not door-like and folds pieces too small to be rooms into their neighbours. Everything is
// measured in metres, so one set of options fits every map resolution.
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/core/option_table.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/segmentation/door_like_cut.h"
#include "topocut/segmentation/merge_features.h"
#include "topocut/segmentation/merge_model.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut {

struct RoomMergeOptions {
  // false: the pieces are the rooms (the reference behaviour).
  bool enabled = true;
  // true: rooms merge where the learned model (merge_model.h) finds them one room; false: by the
  // hand rules below (door_like, width steps, furniture). Folding applies either way.
  bool learned = true;
  SharedMergeModel model;  // the shipped model unless given one (merge_model.h)
  // (Learned merging) a corridor continued across a cut is one room whatever the model says: both
  // sides strips of about one thickness (at most 2.5 m), the cut across the narrower, each side at
  // least 3 times as long as thick (--no-corridor-rule: the model decides alone).
  bool corridor_rule = true;
  // (Hand rules) a door-like cut (door_like_cut.h: narrower than 0.7 times the room on each side)
  // stays; one closer to the narrower side's width (a corridor cut across) merges its rooms, clearest
  // first. Its width_depth is also where the learned criterion and min_room_width measure widths.
  DoorLikeCut door_like{.ratio = 0.7, .width_depth = 1.0};
  // m²: smaller rooms (slivers between cuts, leaks through doors) fold into the neighbour sharing
  // the longest cut. Half a square metre: the smallest closets people draw are larger.
  double min_room_area = 0.5;
  // (Learned merging, after the folding) Fragments: a room smaller than fragment_area m², bounded
  // more by never-seen cells than by walls, whose longest cut to the room it shares the most cut with
  // is narrower than fragment_gap (no door a person walks through) joins that room: the corner of a
  // room seen through a gap between furniture, the ray-lit floor behind a narrow opening. Closets and
  // WCs of that size are walled and entered through a door. 2 m² and 0.6 m (a person's width, as the
  // cleaning's thin free space and the defect count): every such scrap on the real maps is smaller,
  // the rooms people drew on them larger. Only where the grid holds occupied cells (walls drawn in the
  // never-seen grey cannot be told from the dark). 0: off (--no-fragments).
  double fragment_area = 2.0;
  double fragment_gap = 0.6;
  // (Learned merging, after the fragments) Bays: a room at most bay_area_ratio of a neighbour's area
  // whose cuts to it (door rules' cuts left out: a door or a room's open front stays a boundary) are at
  // least bay_share of its outline joins it: a bay, a wedge or a strip cut off a room along a diagonal
  // or a wall line. A room beside a corridor or a hall shares a fifth of its outline with it only when
  // it is shallow. 0: off (--no-bays).
  double bay_share = 0.2;
  double bay_area_ratio = 0.25;
  // Fragments and bays join their neighbour only where the model's probability of one room across
  // their longest cut to it is at least this and at most its threshold (above, a criterion before the
  // model kept the cut): the model leaning that way without deciding. The scraps and bays of the real
  // maps lie at 0.39 to 0.49, the rooms the sketches' people drew beside a hall below 0.07.
  double hang_probability = 0.35;
  // Metres: rooms whose widest chord along any cut stays below this fold the same way (a strip of
  // rays through a gap). 0 (default) disables: leaks are mostly components of their own.
  double min_room_width = 0.0;
  // (Hand rules) metres of thickness (2 area / perimeter): thinner rooms (slivers, roots of ray fans)
  // fold the same way. 0.6 m is a person's width, the disc the defect count uses. The learned
  // criterion weighs thin rooms itself (closets behind a door are thin and are rooms).
  double min_room_thickness = 0.6;
  // (Learned merging) metres of thickness: thinner rooms fold the same way. A sliver thinner than half
  // a person (a ragged scrap beside a door, the rim of a room between two cuts) is no room, however
  // sure the model is of the door-like cut beside it; a closet, thin as it is, is thicker (a 0.5 m x
  // 2 m one is 0.4 m). 0: off.
  double sliver_thickness = 0.3;
  // Metres: an obstacle whose box is at most this long both ways is furniture: a feature of the
  // learned criterion, and for the hand rules a cut ending on it separates no rooms (a room does not
  // end at a table). 0: no obstacle is furniture.
  double furniture_size = 2.5;
  // Width steps (hand rules): a room narrower than step_ratio ([0, 1); 0 off) times the space it
  // opens onto stays apart when that space is step_min_wide_depth metres deep and both are
  // step_min_area m²; the depth keeps a corridor with what opens onto it.
  double step_ratio = 0.6;
  double step_min_area = 6.0;
  double step_min_wide_depth = 5.0;
  // Across a wall line the wider side need only be this many times the narrow width deep (> 0): an
  // L corridor's corner is as deep as the corridor is wide, so it stays one room.
  double step_wall_line_depth = 1.25;
};

// The fields of RoomMergeOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<RoomMergeOptions>>& room_merge_option_rows();

// Throws Error unless the options are usable (finite, non-negative, door_like.ratio > 0).
void validate(const RoomMergeOptions& options);

struct SegmentOptions;
struct SegmentationRule;

// Merges the pieces of one free-space component (grid coordinates; resolution converts the options'
// metres) into rooms by the rows of rules that act on one component and are on in options, in list
// order (segmentation_rules(): the merges the criteria decide, then the folding): each room the exact
// union of its pieces, in order of their first piece, with the cuts between two rooms in input order
// (keyhole cuts dropped); the pieces unchanged when no such row is on. component.polygon's small holes
// are the furniture; cells, the grid it was traced from (OccupancyGrid::cells; empty: not known), tell
// walls from never-seen space along the rooms' outlines. trace, if given, receives every merge the
// learned criterion weighed. options.merge must be valid (validate(); not checked here: segment() and
// the incremental segmenter check their options once, not per component).
PieceSet merge_rooms(const FreeSpaceComponent& component, const PieceSet& pieces, const cv::Mat& cells, double resolution,
                     const SegmentOptions& options, const std::vector<SegmentationRule>& rules,
                     std::vector<MergeStep>* trace = nullptr);

// merge_rooms() by segmentation_rules() with these merge options (the other options at their defaults);
// throws Error unless validate(options) accepts them.
PieceSet merge_rooms(const FreeSpaceComponent& component, const PieceSet& pieces, const cv::Mat& cells, double resolution,
                     const RoomMergeOptions& options = {}, std::vector<MergeStep>* trace = nullptr);

// The union of pieces that tile a region without overlapping and meet only along whole shared
// edges (as DuDe's pieces do): every edge traversed in both directions is removed and the rest is
// linked into rings, outer ring counter-clockwise, holes clockwise. Vertices where a removed edge
// met the boundary stay, even where the boundary goes straight on through them.
// Throws Error if the pieces do not form one connected region.
PolygonWithHoles union_of_pieces(const std::vector<PolygonWithHoles>& pieces);

}  // namespace topocut
