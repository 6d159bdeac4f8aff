#include "topocut/segmentation/wall_openings.h"

#include <map>

#include "segmentation/cuts/cut_search.h"

namespace topocut {

using namespace cut_search;

namespace {

// The end of a thin wall: where it ends, the direction it points in, its ring.
struct WallEnd {
  Point2 v, dir;
  int ring;
};

// Ends of walls at least min_wall_length long whose obstacle, just behind the end, is no thicker
// than max_wall_thickness (a partition, not furniture or the building's outline).
std::vector<WallEnd> thin_wall_ends(const DoorSearch& search, const EdgeGrid& grid) {
  const double min_wall = search.options.min_wall_length / search.resolution;
  const double max_thickness = search.options.max_wall_thickness / search.resolution;
  std::vector<WallEnd> ends;
  for_each_reflex_corner(search, [](std::size_t, const Ring&) { return false; },
                         [&](int r, int, const Point2& p, const Point2& v, const Point2& q) {
    for (const bool from_p : {true, false}) {
      const Point2 e = minus(v, from_p ? p : q);
      const double l = length(e);
      if (l < min_wall) continue;
      const Point2 dir{e.x / l, e.y / l};
      // Thin: across the wall, just behind its end, free space of this component lies within
      // the thickness limit. Free space is left of ring edges, so the obstacle lies right of a
      // wall arriving at v (dir along p -> v) and left of one leaving it (dir along q -> v).
      const Point2 into = from_p ? Point2{dir.y, -dir.x} : Point2{-dir.y, dir.x};
      const double back = std::min(0.5 * l, search.options.wall_end_probe / search.resolution);
      const Point2 x{v.x - back * dir.x + 1e-3 * into.x, v.y - back * dir.y + 1e-3 * into.y};
      if (!std::isfinite(grid.cast(x, into, max_thickness))) continue;
      ends.push_back({v, dir, r});
    }
  });
  return ends;
}

using WallEndIndex = std::map<std::pair<double, double>, std::vector<std::size_t>>;

// The wall end near the hit h whose wall points back along e's ray with nothing in between, or null.
const WallEnd* facing_wall_end(const DoorSearch& search, const EdgeGrid& grid, const std::vector<WallEnd>& ends,
                               const WallEndIndex& at, const WallEnd& e, const Point2& h) {
  const double near = 0.15 / search.resolution;
  const double cos_tolerance = std::cos(search.options.gap_alignment);
  const WallEnd* best = nullptr;
  double best_d = near;
  for (auto it = at.lower_bound({h.x - near, -kInfinity}); it != at.end() && it->first.first <= h.x + near; ++it) {
    for (const std::size_t k : it->second) {
      const WallEnd& o = ends[k];
      const double d = length(minus(o.v, h));
      if (o.ring != e.ring || d > best_d || dot(o.dir, e.dir) > -cos_tolerance) continue;
      const Point2 g = minus(o.v, e.v);
      const double gl = length(g);
      if (gl <= 0.0 || dot(g, e.dir) < cos_tolerance * gl) continue;
      // Nothing in between: the first wall along v -> o is o's own.
      if (grid.cast(e.v, {g.x / gl, g.y / gl}, gl) < gl - 1e-6) continue;
      best = &o;
      best_d = d;
    }
  }
  return best;
}

// Openings in a wall: from the end of a thin wall, along the wall, to the first obstacle (a room
// front open to a corridor, a gap between partitions, a wall that stops short of the next). Such an
// opening may be as wide as the room behind it, so the width test is replaced by the wall: it is thin
// and points across, and both sides are at least min_side_width wide.
std::vector<Candidate> wall_openings(const DoorSearch& search, const EdgeGrid& grid) {
  const double max_gap = search.options.max_gap / search.resolution;
  const std::vector<WallEnd> ends = thin_wall_ends(search, grid);
  WallEndIndex at;
  for (std::size_t k = 0; k < ends.size(); ++k) at[{ends[k].v.x, ends[k].v.y}].push_back(k);
  std::vector<Candidate> openings;
  for (const WallEnd& e : ends) {
    int hit_edge = -1;
    const double hit = grid.cast(e.v, e.dir, max_gap, &hit_edge);
    if (!std::isfinite(hit) || search.edges[static_cast<std::size_t>(hit_edge)].ring != e.ring) continue;
    const Point2 h{e.v.x + hit * e.dir.x, e.v.y + hit * e.dir.y};
    // The opening ends at the wall end met, or else where the ray meets the wall.
    const WallEnd* facing = facing_wall_end(search, grid, ends, at, e, h);
    const Point2 target = facing ? facing->v : h;
    const Point2 g = minus(target, e.v);
    const double gl = length(g);
    const Point2 u{g.x / gl, g.y / gl};
    const Point2 mid{(e.v.x + target.x) / 2.0, (e.v.y + target.y) / 2.0};
    const double cap = search.options.min_side_width / search.resolution;
    if (side_width(grid, mid, u, {-u.y, u.x}, search.depth, cap) < cap) continue;
    if (side_width(grid, mid, u, {u.y, -u.x}, search.depth, cap) < cap) continue;
    // Openings come after every door: a narrow passage is the stronger evidence.
    openings.push_back({{e.v, target}, gl + max_gap, e.ring, CutRule::kWallOpening});
  }
  return openings;
}

}  // namespace

std::vector<Segment2> find_wall_openings(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                                         const std::vector<Segment2>& doors, const CutSearchIndex* index) {
  return search_cuts(polygon, resolution, options, options.extend_walls, {}, index,
                     [&](const DoorSearch& search, const EdgeGrid& grid) {
                       std::vector<Candidate> all = doors_first(doors);
                       for (const Candidate& c : wall_openings(search, grid)) all.push_back(c);
                       return without_doors(segments_of(narrowest_compatible(std::move(all), resolution)), doors);
                     });
}

}  // namespace topocut
