#include "topocut/segmentation/wall_lines.h"

#include "segmentation/cuts/cut_search.h"

namespace topocut {

using namespace cut_search;

namespace {

// The length along the ring from vertex 0 to each vertex j (at[j]), and round the whole ring (at[n]).
std::vector<double> arc_lengths(const Ring& ring) {
  const std::size_t n = ring.size();
  std::vector<double> at(n + 1, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    const Point2 d = minus(ring[(j + 1) % n], ring[j]);
    at[j + 1] = at[j] + std::sqrt(dot(d, d));
  }
  return at;
}

// The direction (unit) of the wall that arrives at corner v (vertex i), read from the first vertex
// at least `reach` cells behind v (step -1) or ahead of it (step +1): a straight wall, every vertex
// in between within `tolerance` cells of that line, so a jagged hand-drawn or noisy wall gives the
// direction of the wall, not of its last pixel step, and a short edge (a desk, a door frame) none.
// at: the ring's arc_lengths().
std::optional<Point2> wall_direction(const Ring& ring, const std::vector<double>& at, int i, int step, double reach,
                                     double tolerance) {
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
  auto far = [&](int index) {
    const Point2 d = minus(v, ring[static_cast<std::size_t>(index)]);
    return dot(d, d) >= surely_short && length(d) >= reach;
  };
  // The first vertex at least reach from v, k vertices away (k < n), walking the ring as two runs
  // of indices (up to its end, then on from its other end) with no wrap test per vertex. A vertex
  // less than reach along the ring from v is nearer than reach: each run starts at the first vertex
  // that is not (found by bisection in at), less a margin far above the sums' rounding.
  const double along = reach - 1e-6 * (reach + at[static_cast<std::size_t>(n)]);
  const double* a = at.data();
  int k = 0, index_k = -1;
  if (step < 0) {  // i + 1 .. n - 1, then 0 .. i - 1
    for (int index = static_cast<int>(std::lower_bound(a + i + 1, a + n, a[i] + along) - a); index < n; ++index)
      if (far(index)) {
        index_k = index;
        k = index - i;
        break;
      }
    const double wrap = a[n] - a[i];  // along the ring from v to vertex 0
    for (int index = static_cast<int>(std::lower_bound(a, a + i, along - wrap) - a); index_k < 0 && index < i; ++index)
      if (far(index)) {
        index_k = index;
        k = n - i + index;
      }
  } else {  // i - 1 .. 0, then n - 1 .. i + 1
    for (int index = static_cast<int>(std::upper_bound(a, a + i, a[i] - along) - a) - 1; index >= 0; --index)
      if (far(index)) {
        index_k = index;
        k = i - index;
        break;
      }
    for (int index = static_cast<int>(std::upper_bound(a + i + 1, a + n, a[i] + a[n] - along) - a) - 1; index_k < 0 && index > i; --index)
      if (far(index)) {
        index_k = index;
        k = i + n - index;
      }
  }
  if (index_k < 0) return std::nullopt;
  const Point2& end = ring[static_cast<std::size_t>(index_k)];
  const Point2 d = minus(v, end);
  const double l = length(d);
  for (int j = 1, index_j = further(i); j < k; ++j, index_j = further(index_j))
    if (std::abs(cross(d, minus(ring[static_cast<std::size_t>(index_j)], end))) / l > tolerance) return std::nullopt;
  return Point2{d.x / l, d.y / l};
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
  std::vector<std::vector<double>> arcs(search.rings.size());  // per ring, made when a corner first needs it
  for_each_reflex_corner(
      search, [&](std::size_t, const Ring& hole) { return too_small_for_a_room(hole, search.resolution); },
      [&](int r, int i, const Point2& p, const Point2& v, const Point2& q) {
        const Ring& ring = *search.rings[static_cast<std::size_t>(r)];
        std::vector<double>& at = arcs[static_cast<std::size_t>(r)];
        if (at.empty()) at = arc_lengths(ring);
        for (const int step : {1, -1}) {
          const std::optional<Point2> dir = wall_direction(ring, at, i, step, reach, tolerance);
          if (!dir) continue;
          if (const std::optional<Candidate> c = wall_line(search, grid, r, p, v, q, *dir)) cuts.push_back(*c);
        }
      });
  return cuts;
}

}  // namespace

std::vector<Segment2> find_wall_line_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                                          const std::vector<Segment2>& doors, const CutSearchIndex* index) {
  return search_cuts(polygon, resolution, options, options.wall_lines, {}, index, [&](const DoorSearch& search, const EdgeGrid& grid) {
    std::vector<Candidate> all = doors_first(doors);
    for (const Candidate& c : wall_line_cuts(search, grid)) all.push_back(c);
    const std::vector<Segment2> kept = segments_of(narrowest_compatible(std::move(all), resolution));
    // Two lines closer than wall_line_spacing along their whole length (the two faces of one
    // partition continued across a corridor) would enclose a strip no room is: the shorter stays.
    const double near = options.wall_line_spacing / resolution;
    std::vector<Segment2> out;
    CutGrid taken(near);
    for (const Segment2& s : kept) {
      const bool sliver = taken.any_near(s, [&](int i) {
        const Segment2& o = out[static_cast<std::size_t>(i)];
        return (distance_to_segment(s.a, o) < near && distance_to_segment(s.b, o) < near) ||
               (distance_to_segment(o.a, s) < near && distance_to_segment(o.b, s) < near);
      });
      if (sliver) continue;
      out.push_back(s);
      taken.add(s);
    }
    return without_doors(std::move(out), doors);
  });
}

}  // namespace topocut
