#include "topocut/segmentation/door_cuts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "topocut/core/error.h"
#include "topocut/segmentation/polygon_split.h"
#include "segmentation/plane_vectors.h"

namespace topocut {

using namespace plane;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kSmallestRoom = 1.0;  // m²: no room is smaller than a square metre

struct Edge {
  Point2 a, b;
  int ring = 0;
  int index = 0;  // the edge from vertex index to index + 1 of its ring
};

// A uniform grid over the edges, for "edges near this point" and "first edge along this ray".
class EdgeGrid {
 public:
  EdgeGrid(const std::vector<Edge>& edges, double cell) : edges_(edges), cell_(cell) {
    x0_ = y0_ = kInfinity;
    double x1 = -kInfinity, y1 = -kInfinity;
    for (const Edge& e : edges) {
      x0_ = std::min({x0_, e.a.x, e.b.x});
      y0_ = std::min({y0_, e.a.y, e.b.y});
      x1 = std::max({x1, e.a.x, e.b.x});
      y1 = std::max({y1, e.a.y, e.b.y});
    }
    x0_ -= cell_;
    y0_ -= cell_;
    nx_ = static_cast<int>((x1 - x0_) / cell_) + 2;
    ny_ = static_cast<int>((y1 - y0_) / cell_) + 2;
    // Compressed rows: count, then fill. An edge goes into every cell its segment passes through.
    std::vector<int> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    auto for_cells = [&](const Edge& e, auto&& f) {
      const int cx0 = column(std::min(e.a.x, e.b.x)), cx1 = column(std::max(e.a.x, e.b.x));
      const int cy0 = row(std::min(e.a.y, e.b.y)), cy1 = row(std::max(e.a.y, e.b.y));
      const Point2 d = minus(e.b, e.a);
      for (int cy = cy0; cy <= cy1; ++cy) {
        for (int cx = cx0; cx <= cx1; ++cx) {
          if (cx1 > cx0 && cy1 > cy0) {
            // Skip cells the segment's line misses (all four corners on one side).
            const double bx = x0_ + cx * cell_, by = y0_ + cy * cell_;
            const double s0 = cross(d, minus({bx, by}, e.a)), s1 = cross(d, minus({bx + cell_, by}, e.a));
            const double s2 = cross(d, minus({bx, by + cell_}, e.a)), s3 = cross(d, minus({bx + cell_, by + cell_}, e.a));
            if ((s0 > 0 && s1 > 0 && s2 > 0 && s3 > 0) || (s0 < 0 && s1 < 0 && s2 < 0 && s3 < 0)) continue;
          }
          f(cy * nx_ + cx);
        }
      }
    };
    for (const Edge& e : edges) for_cells(e, [&](int c) { ++count[static_cast<std::size_t>(c) + 1]; });
    for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
    start_ = count;
    items_.resize(static_cast<std::size_t>(count.back()));
    for (std::size_t i = 0; i < edges.size(); ++i)
      for_cells(edges[i], [&](int c) { items_[static_cast<std::size_t>(count[static_cast<std::size_t>(c)]++)] = static_cast<int>(i); });
  }

  template <class F>
  void visit_box(double x0, double y0, double x1, double y1, F&& f) const {
    const int cx0 = std::max(0, column(x0)), cx1 = std::min(nx_ - 1, column(x1));
    const int cy0 = std::max(0, row(y0)), cy1 = std::min(ny_ - 1, row(y1));
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx) {
        const int c = cy * nx_ + cx;
        for (int k = start_[static_cast<std::size_t>(c)]; k < start_[static_cast<std::size_t>(c) + 1]; ++k) f(items_[static_cast<std::size_t>(k)]);
      }
  }

  // Calls f(edge) for the edges registered in the cells around p, ring of cells by ring of cells
  // outward, while keep_going(d) holds for d = the least distance from p to the next ring's cells
  // (an edge in several cells is visited several times).
  template <class F, class G>
  void visit_nearest(const Point2& p, double reach, F&& f, G&& keep_going) const {
    const int cx = column(p.x), cy = row(p.y);
    const int rings = static_cast<int>(std::ceil(reach / cell_)) + 1;
    for (int k = 0; k <= rings; ++k) {
      if (k > 0 && !keep_going((k - 1) * cell_)) return;
      for (int y = cy - k; y <= cy + k; ++y) {
        if (y < 0 || y >= ny_) continue;
        const bool edge_row = y == cy - k || y == cy + k;
        for (int x = cx - k; x <= cx + k; x += edge_row ? 1 : 2 * k) {
          if (x >= 0 && x < nx_) {
            const int c = y * nx_ + x;
            for (int i = start_[static_cast<std::size_t>(c)]; i < start_[static_cast<std::size_t>(c) + 1]; ++i) f(items_[static_cast<std::size_t>(i)]);
          }
          if (k == 0) break;
        }
      }
    }
  }

  // Distance along the ray p + t·u (u unit) to the first edge it meets, t in (0, t_max]; infinity
  // if none.
  double cast(const Point2& p, const Point2& u, double t_max, int* hit_edge = nullptr) const {
    int cx = column(p.x), cy = row(p.y);
    const int step_x = u.x > 0 ? 1 : -1, step_y = u.y > 0 ? 1 : -1;
    const double next_x = x0_ + (cx + (step_x > 0 ? 1 : 0)) * cell_;
    const double next_y = y0_ + (cy + (step_y > 0 ? 1 : 0)) * cell_;
    double t_x = u.x != 0.0 ? (next_x - p.x) / u.x : kInfinity;
    double t_y = u.y != 0.0 ? (next_y - p.y) / u.y : kInfinity;
    const double d_x = u.x != 0.0 ? cell_ / std::abs(u.x) : kInfinity;
    const double d_y = u.y != 0.0 ? cell_ / std::abs(u.y) : kInfinity;
    double best = kInfinity;
    double entry = 0.0;
    while (cx >= 0 && cy >= 0 && cx < nx_ && cy < ny_ && entry <= t_max) {
      const int c = cy * nx_ + cx;
      for (int k = start_[static_cast<std::size_t>(c)]; k < start_[static_cast<std::size_t>(c) + 1]; ++k) {
        const Edge& e = edges_[static_cast<std::size_t>(items_[static_cast<std::size_t>(k)])];
        const Point2 d = minus(e.b, e.a);
        const double denominator = cross(u, d);
        if (denominator == 0.0) continue;
        const Point2 w = minus(e.a, p);
        const double t = cross(w, d) / denominator;
        const double s = cross(w, u) / denominator;
        if (t > 1e-9 && s >= 0.0 && s <= 1.0 && t < best) {
          best = t;
          if (hit_edge) *hit_edge = items_[static_cast<std::size_t>(k)];
        }
      }
      const double exit = std::min(t_x, t_y);
      if (best <= exit) break;
      entry = exit;
      if (t_x < t_y) {
        t_x += d_x;
        cx += step_x;
      } else {
        t_y += d_y;
        cy += step_y;
      }
    }
    return best <= t_max ? best : kInfinity;
  }

 private:
  int column(double x) const { return static_cast<int>(std::floor((x - x0_) / cell_)); }
  int row(double y) const { return static_cast<int>(std::floor((y - y0_) / cell_)); }

  const std::vector<Edge>& edges_;
  double cell_;
  double x0_, y0_;
  int nx_ = 0, ny_ = 0;
  std::vector<int> start_, items_;
};

struct Candidate {
  Segment2 segment;
  double width = 0.0;  // cells
  int ring = 0;
  CutRule rule = CutRule::kDoor;
};

// Widest chord parallel to u beside the segment's midpoint on the side of normal n, sampled up to
// depth; capped at cap (enough to call the side wide).
double side_width(const EdgeGrid& grid, const Point2& mid, const Point2& u, const Point2& n, double depth, double cap) {
  const double inside = grid.cast(mid, n, depth);  // the side ends at the first wall along n
  const int samples = 8;
  double widest = 0.0;
  for (int k = 1; k <= samples; ++k) {
    const double d = depth * k / samples;
    if (d >= inside) break;
    const Point2 p{mid.x + d * n.x, mid.y + d * n.y};
    const double chord = std::min(grid.cast(p, u, cap), cap) + std::min(grid.cast(p, {-u.x, -u.y}, cap), cap);
    widest = std::max(widest, chord);
    if (widest >= cap) break;
  }
  return widest;
}

// Proper crossing or touching of two segments other than at shared end points. Not the
// decomposition's conflict test (candidates.cpp), on purpose: that one uses exact predicates on
// polygon corners (shared ends by vertex id) and counts a segment running along another from a
// shared end, or the same segment, as a conflict; this one is floating point on loose points and
// lets segments with a shared end overlap (narrowest_compatible's distance test drops those).
bool segments_conflict(const Segment2& s, const Segment2& t) {
  auto orient = [](const Point2& a, const Point2& b, const Point2& c) { return cross(minus(b, a), minus(c, a)); };
  const bool shared = s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b;
  const double d1 = orient(t.a, t.b, s.a), d2 = orient(t.a, t.b, s.b);
  const double d3 = orient(s.a, s.b, t.a), d4 = orient(s.a, s.b, t.b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  if (shared) return false;
  auto on = [&](const Point2& a, const Point2& b, const Point2& p, double o) {
    return o == 0.0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
  };
  return on(t.a, t.b, s.a, d1) || on(t.a, t.b, s.b, d2) || on(s.a, s.b, t.a, d3) || on(s.a, s.b, t.b, d4);
}

}  // namespace

void validate(const DoorOptions& options) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(options.max_width) || !positive(options.door_ratio) || !positive(options.width_depth))
    throw Error("the door width, ratio and depth must be positive numbers");
  if (!std::isfinite(options.min_turn) || options.min_turn < 0.0) throw Error("the door corner turn must be a non-negative angle");
  if (!positive(options.max_gap) || !positive(options.max_wall_thickness) || !std::isfinite(options.min_wall_length) ||
      options.min_wall_length < 0.0 || !std::isfinite(options.gap_alignment) || options.gap_alignment < 0.0 ||
      !std::isfinite(options.min_side_width) || options.min_side_width < 0.0 || !positive(options.wall_end_probe))
    throw Error("the wall opening gap, wall thickness and wall end probe must be positive, the other opening options non-negative");
  if (!positive(options.max_wall_line) || !positive(options.wall_line_wall) || !std::isfinite(options.wall_line_straightness) ||
      options.wall_line_straightness < 0.0 || !std::isfinite(options.wall_line_spacing) || options.wall_line_spacing < 0.0 ||
      !std::isfinite(options.wall_line_side) || options.wall_line_side < 0.0)
    throw Error("the wall line length and wall length must be positive, the straightness, spacing and side width non-negative");
  if (!positive(options.max_island_thickness) || !std::isfinite(options.min_island_length) || options.min_island_length < 0.0)
    throw Error("the wall island thickness must be positive, its length non-negative");
}

namespace {

// A door cut joins two points of one ring; around a small obstacle (furniture) the region it could
// cut off lies within the obstacle's bounding box, too small to be a room.
bool too_small_for_a_room(const Ring& hole, double resolution) {
  const Box box = bounding_box(hole);
  return (box.x1 - box.x0) * (box.y1 - box.y0) * resolution * resolution < kSmallestRoom;
}

// A piece of wall standing free in the map (a partition whose joint to the next wall the sensor
// missed, a wall between two doors): longer than furniture but thin all along, unlike furniture
// (solid or small) and clutter. 2 area / perimeter is the mean thickness of a thin shape.
bool is_wall_island(const Ring& hole, double resolution, const DoorOptions& options) {
  const Box box = bounding_box(hole);
  const double around = perimeter(hole);
  return std::max(box.x1 - box.x0, box.y1 - box.y0) * resolution > options.min_island_length && around > 0.0 &&
         2.0 * std::abs(signed_area(hole)) / around * resolution <= options.max_island_thickness;
}

// What every phase of the door search reads: the polygon's rings, their edges, and the option
// lengths in cells.
struct DoorSearch {
  const DoorOptions& options;
  double resolution = 1.0;
  std::vector<const Ring*> rings;
  std::vector<Edge> edges;
  double reach = 0.0;  // widest door, cells
  double depth = 0.0;  // how far beside a cut the sides are measured, cells
  // Per ring, for the island search only: may a cut join it to another such ring (the outline, and
  // islands of wall).
  std::vector<bool> joinable;
};

DoorSearch door_search(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                       std::vector<bool> joinable) {
  DoorSearch search{options, resolution, {&polygon.outer}, {}, options.max_width / resolution, options.width_depth / resolution,
                    std::move(joinable)};
  for (const Ring& hole : polygon.holes) search.rings.push_back(&hole);
  for (std::size_t r = 0; r < search.rings.size(); ++r) {
    const Ring& ring = *search.rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i)
      search.edges.push_back({ring[i], ring[(i + 1) % ring.size()], static_cast<int>(r), static_cast<int>(i)});
  }
  return search;
}

// The nearest boundary point within reach from the reflex corner v (vertex i of ring r, between p
// and q), inside the cone that resolves the corner; nullopt unless it lies on ring r itself (or,
// across, on another ring, both joinable: such a cut separates nothing alone, only with the cuts
// on the island's other sides).
std::optional<Candidate> nearest_across_corner(const DoorSearch& search, const EdgeGrid& grid, int r, int i,
                                               const Point2& p, const Point2& v, const Point2& q, bool across) {
  // Directions that resolve the corner: between the continuations of its two edges.
  const Point2 e1 = minus(v, p), e2 = minus(v, q);
  const double l1 = length(e1), l2 = length(e2);
  const Point2 u1{e1.x / l1, e1.y / l1}, u2{e2.x / l2, e2.y / l2};
  auto in_cone = [&](const Point2& x) {
    const Point2 d = minus(x, v);
    const double tolerance = 1e-9 * (std::abs(d.x) + std::abs(d.y));
    return cross(u1, d) >= -tolerance && cross(d, u2) >= -tolerance;
  };
  const int n = static_cast<int>(search.rings[static_cast<std::size_t>(r)]->size());
  const int before = (i + n - 1) % n;
  double best2 = search.reach * search.reach;  // squared distance of the nearest point so far
  Point2 best_point;
  int best_ring = -1;
  grid.visit_nearest(v, search.reach, [&](int id) {
    const Edge& e = search.edges[static_cast<std::size_t>(id)];
    if (e.ring == r && (e.index == i || e.index == before)) return;
    // No point of the edge can beat the best so far if its bounding box is farther.
    const double gx = std::max({std::min(e.a.x, e.b.x) - v.x, 0.0, v.x - std::max(e.a.x, e.b.x)});
    const double gy = std::max({std::min(e.a.y, e.b.y) - v.y, 0.0, v.y - std::max(e.a.y, e.b.y)});
    if (gx * gx + gy * gy >= best2) return;
    auto consider = [&](const Point2& x) {
      const Point2 d = minus(x, v);
      const double d2 = dot(d, d);
      if (d2 > 0.0 && d2 < best2 && in_cone(x)) {
        best2 = d2;
        best_point = x;
        best_ring = e.ring;
      }
    };
    consider(e.a);
    consider(e.b);
    const Point2 d = minus(e.b, e.a);
    const double dd = dot(d, d);
    if (dd > 0.0) {
      const double t = dot(minus(v, e.a), d) / dd;
      if (t > 0.0 && t < 1.0) consider({e.a.x + t * d.x, e.a.y + t * d.y});
    }
    for (const Point2& ray : {u1, u2}) {
      const double denominator = cross(ray, d);
      if (denominator == 0.0) continue;
      const Point2 w = minus(e.a, v);
      const double t = cross(w, d) / denominator, s = cross(w, ray) / denominator;
      if (t > 0.0 && s > 0.0 && s < 1.0) consider({v.x + t * ray.x, v.y + t * ray.y});
    }
  }, [&](double d) { return d * d < best2; });
  if (best_ring < 0 || (best_ring != r) != across) return std::nullopt;
  if (across && !(search.joinable[static_cast<std::size_t>(r)] && search.joinable[static_cast<std::size_t>(best_ring)]))
    return std::nullopt;
  return Candidate{{v, best_point}, std::sqrt(best2), r};
}

// Calls visit(r, i, p, v, q) for every reflex corner v (vertex i of ring r, between p and q) that
// turns by at least min_turn, skipping holes for which skip_hole(r, hole) is true.
template <typename SkipHole, typename Visit>
void for_each_reflex_corner(const DoorSearch& search, SkipHole&& skip_hole, Visit&& visit) {
  for (std::size_t r = 0; r < search.rings.size(); ++r) {
    const Ring& ring = *search.rings[r];
    if (r > 0 && skip_hole(r, ring)) continue;
    const int n = static_cast<int>(ring.size());
    for (int i = 0; i < n; ++i) {
      const Point2& p = ring[static_cast<std::size_t>((i + n - 1) % n)];
      const Point2& v = ring[static_cast<std::size_t>(i)];
      const Point2& q = ring[static_cast<std::size_t>((i + 1) % n)];
      // Free space lies left of every ring (outer CCW, holes CW): a right turn is a reflex corner.
      if (turn_angle(p, v, q) > -search.options.min_turn) continue;
      visit(static_cast<int>(r), i, p, v, q);
    }
  }
}

// Door candidates: from every reflex corner, the shortest cut across it, to its own ring or (across)
// to another joinable one.
std::vector<Candidate> corner_cuts(const DoorSearch& search, const EdgeGrid& grid, bool across) {
  std::vector<Candidate> candidates;
  for_each_reflex_corner(
      search,
      [&](std::size_t r, const Ring& hole) {
        return too_small_for_a_room(hole, search.resolution) || (across && !search.joinable[r]);
      },
      [&](int r, int i, const Point2& p, const Point2& v, const Point2& q) {
        if (auto c = nearest_across_corner(search, grid, r, i, p, v, q, across)) candidates.push_back(*c);
      });
  return candidates;
}

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

// Door test: both sides much wider than the passage.
bool has_wide_sides(const DoorSearch& search, const EdgeGrid& grid, const Candidate& c) {
  const Point2 d = minus(c.segment.b, c.segment.a);
  const Point2 u{d.x / c.width, d.y / c.width};
  const Point2 mid{(c.segment.a.x + c.segment.b.x) / 2.0, (c.segment.a.y + c.segment.b.y) / 2.0};
  const double cap = c.width / search.options.door_ratio;
  return side_width(grid, mid, u, {-u.y, u.x}, search.depth, cap) >= cap &&
         side_width(grid, mid, u, {u.y, -u.x}, search.depth, cap) >= cap;
}

// Narrowest first; a door found from both of its jambs (or from two corners of one wall end) is
// kept once; crossing cuts are not allowed.
std::vector<Candidate> narrowest_compatible(std::vector<Candidate> doors, double resolution) {
  std::sort(doors.begin(), doors.end(), [](const Candidate& x, const Candidate& y) {
    return std::tie(x.width, x.segment.a.x, x.segment.a.y, x.segment.b.x, x.segment.b.y) <
           std::tie(y.width, y.segment.a.x, y.segment.a.y, y.segment.b.x, y.segment.b.y);
  });
  const double duplicate = 0.3 / resolution;
  std::vector<Candidate> accepted;
  for (const Candidate& c : doors) {
    bool ok = true;
    for (const Candidate& taken : accepted) {
      const Segment2& s = taken.segment;
      if (segments_conflict(c.segment, s) ||
          (distance_to_segment(c.segment.a, s) < duplicate && distance_to_segment(c.segment.b, s) < duplicate) ||
          (distance_to_segment(s.a, c.segment) < duplicate && distance_to_segment(s.b, c.segment) < duplicate)) {
        ok = false;
        break;
      }
    }
    if (ok) accepted.push_back(c);
  }
  return accepted;
}

std::vector<Segment2> segments_of(const std::vector<Candidate>& candidates) {
  std::vector<Segment2> out;
  out.reserve(candidates.size());
  for (const Candidate& c : candidates) out.push_back(c.segment);
  return out;
}

// The direction (unit) of the wall that arrives at corner v (vertex i), read from the first vertex
// at least `reach` cells behind v (step -1) or ahead of it (step +1): a straight wall, every vertex
// in between within `tolerance` cells of that line, so a jagged hand-drawn or noisy wall gives the
// direction of the wall, not of its last pixel step, and a short edge (a desk, a door frame) none.
std::optional<Point2> wall_direction(const Ring& ring, int i, int step, double reach, double tolerance) {
  const int n = static_cast<int>(ring.size());
  const Point2& v = ring[static_cast<std::size_t>(i)];
  // The index one vertex further from v (step is +1 or -1), without a division per vertex.
  auto further = [&](int index) {
    index -= step;
    return index < 0 ? index + n : (index >= n ? index - n : index);
  };
  // Squared lengths well below reach² skip hypot (the walk passes many vertices of a noisy wall);
  // the margin leaves every decision near reach to the exact test below.
  const double surely_short = reach * reach * (1.0 - 1e-9);
  for (int k = 1, index_k = further(i); k < n; ++k, index_k = further(index_k)) {
    const Point2& end = ring[static_cast<std::size_t>(index_k)];
    const Point2 d = minus(v, end);
    if (dot(d, d) < surely_short) continue;
    const double l = length(d);
    if (l < reach) continue;
    for (int j = 1, index_j = further(i); j < k; ++j, index_j = further(index_j))
      if (std::abs(cross(d, minus(ring[static_cast<std::size_t>(index_j)], end))) / l > tolerance) return std::nullopt;
    return Point2{d.x / l, d.y / l};
  }
  return std::nullopt;
}

// Counter-clockwise angle from direction `from` to direction `to`, in [0, 2 pi).
double ccw_angle(const Point2& from, const Point2& to) {
  const double a = std::atan2(cross(from, to), dot(from, to));
  return a < 0.0 ? a + 2.0 * M_PI : a;
}

// The wall line of corner v (on ring r, between p and q) along dir: from v to the first
// wall met (a vertex when the hit is within a cell of one), if it starts into free space, ends on
// ring r, is at least wall_line_side long, and leaves both sides that wide.
std::optional<Candidate> wall_line(const DoorSearch& search, const EdgeGrid& grid, int r, const Point2& p, const Point2& v,
                                   const Point2& q, const Point2& dir) {
  // Free space at v is the sweep counter-clockwise from the edge to q round to the edge to p.
  const double a = ccw_angle(minus(q, v), dir);
  if (a < 0.05 || a > ccw_angle(minus(q, v), minus(p, v)) - 0.05) return std::nullopt;
  const double cap = search.options.wall_line_side / search.resolution;
  int hit_edge = -1;
  const double hit = grid.cast(v, dir, search.options.max_wall_line / search.resolution, &hit_edge);
  if (!std::isfinite(hit) || hit < cap) return std::nullopt;
  const Edge& e = search.edges[static_cast<std::size_t>(hit_edge)];
  if (e.ring != r) return std::nullopt;
  Point2 h{v.x + hit * dir.x, v.y + hit * dir.y};
  for (const Point2& end : {e.a, e.b}) {
    const Point2 g = minus(end, v);
    const double gl = length(g);
    if (length(minus(end, h)) < 1.0 && grid.cast(v, {g.x / gl, g.y / gl}, gl) >= gl - 1e-6) h = end;
  }
  const Point2 mid{(v.x + h.x) / 2.0, (v.y + h.y) / 2.0};
  if (side_width(grid, mid, dir, {-dir.y, dir.x}, search.depth, cap) < cap) return std::nullopt;
  if (side_width(grid, mid, dir, {dir.y, -dir.x}, search.depth, cap) < cap) return std::nullopt;
  const double cut = length(minus(h, v));
  return Candidate{{v, h}, cut, r};
}

// Wall lines: from every reflex corner, each of its two walls continued straight on across the free
// space, as a person closes an opening between two rooms by drawing the wall on.
std::vector<Candidate> wall_line_cuts(const DoorSearch& search, const EdgeGrid& grid) {
  std::vector<Candidate> cuts;
  const double reach = search.options.wall_line_wall / search.resolution;
  const double tolerance = search.options.wall_line_straightness / search.resolution;
  for_each_reflex_corner(
      search, [&](std::size_t, const Ring& hole) { return too_small_for_a_room(hole, search.resolution); },
      [&](int r, int i, const Point2& p, const Point2& v, const Point2& q) {
        const Ring& ring = *search.rings[static_cast<std::size_t>(r)];
        for (const int step : {1, -1}) {
          const std::optional<Point2> dir = wall_direction(ring, i, step, reach, tolerance);
          if (!dir) continue;
          if (const std::optional<Candidate> c = wall_line(search, grid, r, p, v, q, *dir)) cuts.push_back(*c);
        }
      });
  return cuts;
}

// Validates the options and the resolution, then returns find(search, grid) over the polygon's
// edges (joinable: DoorSearch::joinable), or nothing when the search is off or the polygon has no
// edge.
template <typename Find>
auto search_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options, bool on,
                 std::vector<bool> joinable, Find&& find) -> decltype(find(std::declval<const DoorSearch&>(), std::declval<const EdgeGrid&>())) {
  validate(options);
  if (!std::isfinite(resolution) || resolution <= 0.0) throw Error("the map resolution must be a positive number");
  if (!on) return {};
  const DoorSearch search = door_search(polygon, resolution, options, std::move(joinable));
  if (search.edges.empty()) return {};
  const EdgeGrid grid(search.edges, std::max(4.0, search.reach / 4.0));
  return find(search, grid);
}

// The doors as candidates that go first and stay: narrowest_compatible keeps later cuts off them.
std::vector<Candidate> doors_first(const std::vector<Segment2>& doors) {
  std::vector<Candidate> all;
  for (const Segment2& d : doors) all.push_back({d, -1.0, 0});
  return all;
}

// cuts without the doors (which went first only to keep the other cuts clear of them).
std::vector<Segment2> without_doors(std::vector<Segment2> cuts, const std::vector<Segment2>& doors) {
  std::erase_if(cuts, [&](const Segment2& s) { return std::find(doors.begin(), doors.end(), s) != doors.end(); });
  return cuts;
}

}  // namespace

std::vector<Segment2> find_wall_line_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                                          const std::vector<Segment2>& doors) {
  return search_cuts(polygon, resolution, options, options.wall_lines, {}, [&](const DoorSearch& search, const EdgeGrid& grid) {
    std::vector<Candidate> all = doors_first(doors);
    for (const Candidate& c : wall_line_cuts(search, grid)) all.push_back(c);
    const std::vector<Segment2> kept = segments_of(narrowest_compatible(std::move(all), resolution));
    // Two lines closer than wall_line_spacing along their whole length (the two faces of one
    // partition continued across a corridor) would enclose a strip no room is: the shorter stays.
    const double near = options.wall_line_spacing / resolution;
    std::vector<Segment2> out;
    for (const Segment2& s : kept) {
      const bool sliver = std::any_of(out.begin(), out.end(), [&](const Segment2& o) {
        return (distance_to_segment(s.a, o) < near && distance_to_segment(s.b, o) < near) ||
               (distance_to_segment(o.a, s) < near && distance_to_segment(o.b, s) < near);
      });
      if (!sliver) out.push_back(s);
    }
    return without_doors(std::move(out), doors);
  });
}

std::vector<RuledCut> find_ruled_door_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options) {
  return search_cuts(polygon, resolution, options, options.enabled, {}, [&](const DoorSearch& search, const EdgeGrid& grid) {
    std::vector<Candidate> doors;
    if (options.extend_walls) doors = wall_openings(search, grid);
    for (const Candidate& c : corner_cuts(search, grid, false)) {
      if (has_wide_sides(search, grid, c)) doors.push_back(c);
    }
    std::vector<RuledCut> out;
    for (const Candidate& c : narrowest_compatible(std::move(doors), resolution)) out.push_back({c.segment, c.rule});
    return out;
  });
}

std::vector<Segment2> find_door_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options) {
  std::vector<Segment2> out;
  for (const RuledCut& c : find_ruled_door_cuts(polygon, resolution, options)) out.push_back(c.segment);
  return out;
}

std::vector<Segment2> find_island_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                                       const std::vector<Segment2>& doors) {
  // The outline, then each hole; most maps have no wall island, and then there is nothing to search.
  std::vector<bool> joinable{true};
  bool any = false;
  if (options.island_cuts) {
    for (const Ring& hole : polygon.holes) {
      joinable.push_back(is_wall_island(hole, resolution, options));
      any = any || joinable.back();
    }
  }
  return search_cuts(polygon, resolution, options, any, std::move(joinable), [&](const DoorSearch& search, const EdgeGrid& grid) {
    std::vector<Candidate> all = doors_first(doors);
    for (const Candidate& c : corner_cuts(search, grid, true)) {
      if (has_wide_sides(search, grid, c)) all.push_back(c);
    }
    // Only the cuts that, with the doors and each other, close a part off.
    return without_doors(separating_chords(polygon, segments_of(narrowest_compatible(std::move(all), resolution))), doors);
  });
}

}  // namespace topocut
