#pragma once
// The search the cut rules share (internal to the module): the free-space polygon's edges in a grid for
// "nearest edge" and "first edge along a ray", reflex corners, the width of the space beside a cut, and
// the narrowest-first choice of compatible cuts. door_cuts.cpp, wall_openings.cpp, island_cuts.cpp and
// wall_lines.cpp each build one rule's candidates on it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "segmentation/cuts/edge_grid.h"
#include "segmentation/cuts/plane_vectors.h"
#include "topocut/core/cut_rule.h"
#include "topocut/core/error.h"
#include "topocut/core/geometry.h"
#include "topocut/core/infinity.h"
#include "topocut/segmentation/cut_search_index.h"
#include "topocut/segmentation/door_cuts.h"

namespace topocut::cut_search {

using namespace plane;

constexpr double kSmallestRoom = 1.0;  // m²: no room is smaller than a square metre

struct Candidate {
  Segment2 segment;
  double width = 0.0;  // cells
  int ring = 0;
  CutRule rule = CutRule::kDoor;
};

// Widest chord parallel to u beside the segment's midpoint on the side of normal n, sampled up to
// depth; capped at cap (enough to call the side wide).
double side_width(const EdgeGrid& grid, const Point2& mid, const Point2& u, const Point2& n, double depth, double cap);

// Proper crossing or touching of two segments other than at shared end points. Not the
// decomposition's conflict test (candidates.cpp), on purpose: that one uses exact predicates on
// polygon corners (shared ends by vertex id) and counts a segment running along another from a
// shared end, or the same segment, as a conflict; this one is floating point on loose points and
// lets segments with a shared end overlap (narrowest_compatible's distance test drops those).
bool segments_conflict(const Segment2& s, const Segment2& t);

// A door cut joins two points of one ring; around a small obstacle (furniture) the region it could
// cut off lies within the obstacle's bounding box, too small to be a room.
bool too_small_for_a_room(const Ring& hole, double resolution);

// A piece of wall standing free in the map (a partition whose joint to the next wall the sensor
// missed, a wall between two doors): longer than furniture but thin all along, unlike furniture
// (solid or small) and clutter. 2 area / perimeter is the mean thickness of a thin shape.
bool is_wall_island(const Ring& hole, double resolution, const DoorOptions& options);

// A reflex corner: vertex i of ring r.
struct Corner {
  int ring = 0, index = 0;
};

// The polygon's rings, their edges, the edges' grid and the reflex corners: what every rule searches,
// the same for all. The grid refers to the edges, so the whole neither moves nor copies.
struct PolygonEdges {
  // cell: the grid's; min_turn: the least right turn (radians, not negative) of a reflex corner.
  PolygonEdges(const PolygonWithHoles& polygon, double cell, double min_turn);
  PolygonEdges(const PolygonEdges&) = delete;
  PolygonEdges& operator=(const PolygonEdges&) = delete;

  std::vector<const Ring*> rings;  // the outline, then the holes
  std::vector<Edge> edges;         // ring by ring, edge i of a ring from its vertex i
  EdgeGrid grid;
  std::vector<Corner> reflex;    // ring by ring, in vertex order
  std::vector<Box> boxes;        // per edge, its bounding box
  std::vector<int> first_edge;   // per ring, where its edges start in edges; then edges.size()
};

// The cell of the rules' edge grid: a quarter of the widest door, at least 4 cells.
double search_cell(const DoorOptions& options, double resolution);

// What every phase of the door search reads: the polygon's rings, their edges, and the option
// lengths in cells.
struct DoorSearch {
  const DoorOptions& options;
  double resolution = 1.0;
  const std::vector<const Ring*>& rings;
  const std::vector<Edge>& edges;
  const std::vector<Corner>& reflex;  // corners turning right by at least options.min_turn
  const std::vector<Box>& boxes;      // per edge
  const std::vector<int>& first_edge; // per ring, where its edges start; then edges.size()
  double reach = 0.0;  // widest door, cells
  double depth = 0.0;  // how far beside a cut the sides are measured, cells
  // Per ring, for the island search only: may a cut join it to another such ring (the outline, and
  // islands of wall).
  std::vector<bool> joinable;
};

DoorSearch door_search(const PolygonEdges& polygon, double resolution, const DoorOptions& options,
                       std::vector<bool> joinable);

// Calls visit(r, i, p, v, q) for every reflex corner v (vertex i of ring r, between p and q) that
// turns by at least min_turn, skipping holes for which skip_hole(r, hole) is true.
// (The corners are PolygonEdges' list, found once for every rule; each hole is asked about once.)
template <typename SkipHole, typename Visit>
void for_each_reflex_corner(const DoorSearch& search, SkipHole&& skip_hole, Visit&& visit) {
  int asked = 0;  // the ring skip was last decided for
  bool skip = false;
  for (const Corner& c : search.reflex) {
    if (c.ring != asked) {
      asked = c.ring;
      skip = skip_hole(static_cast<std::size_t>(c.ring), *search.rings[static_cast<std::size_t>(c.ring)]);
    }
    if (skip) continue;
    const Ring& ring = *search.rings[static_cast<std::size_t>(c.ring)];
    const int n = static_cast<int>(ring.size()), i = c.index;
    visit(c.ring, i, ring[static_cast<std::size_t>((i + n - 1) % n)], ring[static_cast<std::size_t>(i)],
          ring[static_cast<std::size_t>((i + 1) % n)]);
  }
}

// Door candidates: from every reflex corner, the shortest cut across it, to its own ring or (across)
// to another joinable one.
std::vector<Candidate> corner_cuts(const DoorSearch& search, const EdgeGrid& grid, bool across);

// Door test: both sides much wider than the passage.
bool has_wide_sides(const DoorSearch& search, const EdgeGrid& grid, const Candidate& c);

// Cuts in a uniform grid, each in the cells its box grown by margin covers: a cut that crosses a
// segment, or lies within margin of it at an end (or has an end within margin of it), is registered in
// a cell that the segment's own box covers. Lets a choice of cuts test a candidate against the cuts
// near it only, not against all of them.
class CutGrid {
 public:
  explicit CutGrid(double margin) : margin_(margin), cell_(std::max(8.0, 4.0 * margin)) {}

  // Registers s under the next index (0, 1, ...).
  void add(const Segment2& s) {
    const int index = static_cast<int>(seen_.size());
    seen_.push_back(0);
    // A margin beyond margin keeps rounding at a cell's edge on the safe side.
    for_cells(s, margin_ * 1.001 + 1e-9, [&](std::int64_t key) { cells_[key].push_back(index); });
  }

  // Calls f(index) once for every registered cut in a cell that s's box covers, until f returns
  // true; whether it did.
  template <typename F>
  bool any_near(const Segment2& s, F&& f) {
    ++stamp_;
    bool found = false;
    for_cells(s, 0.0, [&](std::int64_t key) {
      const auto cell = cells_.find(key);
      if (found || cell == cells_.end()) return;
      for (const int i : cell->second) {
        if (seen_[static_cast<std::size_t>(i)] == stamp_) continue;
        seen_[static_cast<std::size_t>(i)] = stamp_;
        if (f(i)) {
          found = true;
          return;
        }
      }
    });
    return found;
  }

 private:
  template <typename F>
  void for_cells(const Segment2& s, double grow, F&& f) const {
    const long long x0 = cell_of(std::min(s.a.x, s.b.x) - grow), x1 = cell_of(std::max(s.a.x, s.b.x) + grow);
    const long long y0 = cell_of(std::min(s.a.y, s.b.y) - grow), y1 = cell_of(std::max(s.a.y, s.b.y) + grow);
    for (long long y = y0; y <= y1; ++y)
      for (long long x = x0; x <= x1; ++x) f(static_cast<std::int64_t>((x << 32) ^ (y & 0xffffffffLL)));
  }
  long long cell_of(double v) const { return static_cast<long long>(std::floor(v / cell_)); }

  double margin_, cell_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
  std::vector<unsigned> seen_;  // per cut: the last query that met it
  unsigned stamp_ = 0;
};

// Narrowest first; a door found from both of its jambs (or from two corners of one wall end) is
// kept once; crossing cuts are not allowed. Each candidate is tested against the accepted cuts near
// it (CutGrid), not against all of them. keep (when given) is a further test a candidate must pass, asked
// only of those no accepted cut conflicts with: the same cuts as keeping only the candidates it passes
// beforehand, without testing the many a narrower cut rules out anyway.
std::vector<Candidate> narrowest_compatible(std::vector<Candidate> doors, double resolution,
                                           const std::function<bool(const Candidate&)>& keep = {});

// The segments of candidates, in order.
std::vector<Segment2> segments_of(const std::vector<Candidate>& candidates);

// Validates the options and the resolution, then returns find(search, grid) over the polygon's
// edges (joinable: DoorSearch::joinable), or nothing when the search is off or the polygon has no
// edge. The edges are index's when it holds this polygon's (else built here).
template <typename Find>
auto search_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options, bool on,
                 std::vector<bool> joinable, const CutSearchIndex* index, Find&& find)
    -> decltype(find(std::declval<const DoorSearch&>(), std::declval<const EdgeGrid&>())) {
  validate(options);
  if (!std::isfinite(resolution) || resolution <= 0.0) throw Error("the map resolution must be a positive number");
  if (!on) return {};
  std::unique_ptr<PolygonEdges> own;
  const PolygonEdges* edges = index ? index->edges_for(polygon, resolution, options) : nullptr;
  if (!edges) {
    own = std::make_unique<PolygonEdges>(polygon, search_cell(options, resolution), options.min_turn);
    edges = own.get();
  }
  if (edges->edges.empty()) return {};
  const DoorSearch search = door_search(*edges, resolution, options, std::move(joinable));
  return find(search, edges->grid);
}

// The doors as candidates that go first and stay: narrowest_compatible keeps later cuts off them.
std::vector<Candidate> doors_first(const std::vector<Segment2>& doors);

// Whether c is one of doors_first()'s doors (their width is -1; a corner's cut is never narrower than 0).
bool is_door_first(const Candidate& c);

// cuts without the doors (which went first only to keep the other cuts clear of them).
std::vector<Segment2> without_doors(std::vector<Segment2> cuts, const std::vector<Segment2>& doors);

}  // namespace topocut::cut_search
