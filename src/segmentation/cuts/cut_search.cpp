#include "segmentation/cuts/cut_search.h"

#include <map>

#include "segmentation/side_width.h"

namespace topocut::cut_search {

// Widest chord parallel to u beside the segment's midpoint on the side of normal n (side_width.h),
// sampled up to depth; capped at cap (enough to call the side wide).
double side_width(const EdgeGrid& grid, const Point2& mid, const Point2& u, const Point2& n, double depth, double cap) {
  const double inside = grid.cast(mid, n, depth);  // the side ends at the first wall along n
  return std::min(cap, sampled_side_width(depth, cap, [&](double d) -> std::optional<double> {
    if (d >= inside) return std::nullopt;
    const Point2 p{mid.x + d * n.x, mid.y + d * n.y};
    const double one_way = std::min(grid.cast(p, u, cap), cap);
    if (one_way >= cap) return cap;
    // The other way only as far as the chord needs to reach cap, and a little beyond for rounding: a
    // wall found there is the same wall, and none found leaves the chord at least cap.
    const double other_way = grid.cast(p, {-u.x, -u.y}, cap - one_way + 1e-9 * cap);
    return std::isfinite(other_way) ? one_way + std::min(other_way, cap) : cap;
  }));
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

namespace {

std::vector<const Ring*> rings_of(const PolygonWithHoles& polygon) {
  std::vector<const Ring*> rings{&polygon.outer};
  for (const Ring& hole : polygon.holes) rings.push_back(&hole);
  return rings;
}

std::vector<Edge> edges_of(const std::vector<const Ring*>& rings) {
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = *rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i)
      edges.push_back({ring[i], ring[(i + 1) % ring.size()], static_cast<int>(r), static_cast<int>(i)});
  }
  return edges;
}

// Free space lies left of every ring (outer CCW, holes CW): a right turn by at least min_turn is a
// reflex corner. A left turn (positive cross product) has a positive angle, above -min_turn: no atan2.
std::vector<Corner> reflex_corners(const std::vector<const Ring*>& rings, double min_turn) {
  std::vector<Corner> corners;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = *rings[r];
    const int n = static_cast<int>(ring.size());
    for (int i = 0; i < n; ++i) {
      const Point2& p = ring[static_cast<std::size_t>((i + n - 1) % n)];
      const Point2& v = ring[static_cast<std::size_t>(i)];
      const Point2& q = ring[static_cast<std::size_t>((i + 1) % n)];
      if (cross(minus(v, p), minus(q, v)) > 0.0 || turn_angle(p, v, q) > -min_turn) continue;
      corners.push_back({static_cast<int>(r), i});
    }
  }
  return corners;
}

std::vector<Box> boxes_of(const std::vector<Edge>& edges) {
  std::vector<Box> boxes;
  boxes.reserve(edges.size());
  for (const Edge& e : edges)
    boxes.push_back({std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y), std::max(e.a.x, e.b.x), std::max(e.a.y, e.b.y)});
  return boxes;
}

std::vector<int> first_edges(const std::vector<const Ring*>& rings) {
  std::vector<int> first(rings.size() + 1, 0);
  for (std::size_t r = 0; r < rings.size(); ++r) first[r + 1] = first[r] + static_cast<int>(rings[r]->size());
  return first;
}

}  // namespace

PolygonEdges::PolygonEdges(const PolygonWithHoles& polygon, double cell, double min_turn)
    : rings(rings_of(polygon)), edges(edges_of(rings)), grid(edges, cell), reflex(reflex_corners(rings, min_turn)),
      boxes(boxes_of(edges)), first_edge(first_edges(rings)) {}

double search_cell(const DoorOptions& options, double resolution) { return std::max(4.0, options.max_width / resolution / 4.0); }

DoorSearch door_search(const PolygonEdges& polygon, double resolution, const DoorOptions& options,
                       std::vector<bool> joinable) {
  return DoorSearch{options, resolution, polygon.rings, polygon.edges, polygon.reflex, polygon.boxes, polygon.first_edge,
                    options.max_width / resolution,
                    options.door_like.width_depth / resolution, std::move(joinable)};
}

namespace {

// The nearest boundary point within reach from the reflex corner v (vertex i of ring r, between p
// and q), inside the cone that resolves the corner; nullopt unless it lies on ring r itself (or,
// across, on another ring, both joinable: such a cut separates nothing alone, only with the cuts
// on the island's other sides).
// The corner's own two edges are edges[own_before] and edges[own].
std::optional<Candidate> nearest_across_corner(const DoorSearch& search, const EdgeGrid& grid, int r, int own_before,
                                               int own, const Point2& p, const Point2& v,
                                               const Point2& q, bool across, std::vector<unsigned>& seen, unsigned stamp) {
  // Directions that resolve the corner: between the continuations of its two edges.
  const Point2 e1 = minus(v, p), e2 = minus(v, q);
  const double l1 = length(e1), l2 = length(e2);
  const Point2 u1{e1.x / l1, e1.y / l1}, u2{e2.x / l2, e2.y / l2};
  auto in_cone = [&](const Point2& x) {
    const Point2 d = minus(x, v);
    const double tolerance = 1e-9 * (std::abs(d.x) + std::abs(d.y));
    return cross(u1, d) >= -tolerance && cross(d, u2) >= -tolerance;
  };
  // Whether no point of the box passes in_cone(): all four corners beyond one side of the cone by
  // more than the tolerance any point of the box is given (it is linear over the box). Each side's
  // largest value over the corners is at the corner its signs pick (every rounded step is monotone
  // in it), and so is the largest |dx| + |dy|: the same numbers as trying all four corners.
  auto box_outside_cone = [&](const Box& b) {
    const double side1 = u1.x * ((u1.x > 0.0 ? b.y1 : b.y0) - v.y) - u1.y * ((u1.y > 0.0 ? b.x0 : b.x1) - v.x);
    const double side2 = ((u2.y > 0.0 ? b.x1 : b.x0) - v.x) * u2.y - ((u2.x > 0.0 ? b.y0 : b.y1) - v.y) * u2.x;
    if (side1 >= 0.0 && side2 >= 0.0) return false;  // the margin is positive: no need to know it
    const double reach = std::max(std::abs(b.x0 - v.x), std::abs(b.x1 - v.x)) + std::max(std::abs(b.y0 - v.y), std::abs(b.y1 - v.y));
    const double margin = 2e-9 * reach + 1e-12;
    return side1 < -margin || side2 < -margin;
  };
  double best2 = search.reach * search.reach;  // squared distance of the nearest point so far
  Point2 best_point;
  int best_ring = -1;
  // The corner's own edges count as met already: they are skipped without a test per edge.
  seen[static_cast<std::size_t>(own)] = seen[static_cast<std::size_t>(own_before)] = stamp;
  grid.visit_nearest(v, search.reach, [&](int id) {
    // An edge in several cells is met again: its points cannot beat the best so far a second time.
    if (seen[static_cast<std::size_t>(id)] == stamp) return;
    seen[static_cast<std::size_t>(id)] = stamp;
    // No point of the edge can beat the best so far if its bounding box is farther, or lie in the
    // cone if its box lies outside.
    const Box& b = search.boxes[static_cast<std::size_t>(id)];
    const double gx = std::max(std::max(b.x0 - v.x, v.x - b.x1), 0.0);
    const double gy = std::max(std::max(b.y0 - v.y, v.y - b.y1), 0.0);
    if (gx * gx + gy * gy >= best2) return;
    if (box_outside_cone(b)) return;
    const Edge& e = search.edges[static_cast<std::size_t>(id)];
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

// Where on the outline a cut across to a joinable hole (a wall island) could start: a grid of cells
// of the door reach over the outline's box, marking the cells near some joinable hole's box. A corner
// of the outline in an unmarked cell has no island within reach, so its search could only end on the
// outline, which the island search drops: most of the outline's corners, as islands are few and small.
class IslandReach {
 public:
  explicit IslandReach(const DoorSearch& search) {
    const Box outline = bounding_box(*search.rings[0]);
    cell_ = std::max(search.reach, 1.0);
    x0_ = outline.x0;
    y0_ = outline.y0;
    nx_ = cell_of(outline.x1, x0_) + 1;
    ny_ = cell_of(outline.y1, y0_) + 1;
    near_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), 0);
    // A cell beyond the reach keeps rounding (of the box distance, of the points the search
    // considers on an edge) on the safe side.
    const double grow = search.reach + 1.0;
    for (std::size_t r = 1; r < search.rings.size(); ++r) {
      if (!search.joinable[r]) continue;
      const Box b = bounding_box(*search.rings[r]);
      const int cx0 = std::max(cell_of(b.x0 - grow, x0_), 0), cx1 = std::min(cell_of(b.x1 + grow, x0_), nx_ - 1);
      const int cy0 = std::max(cell_of(b.y0 - grow, y0_), 0), cy1 = std::min(cell_of(b.y1 + grow, y0_), ny_ - 1);
      for (int cy = cy0; cy <= cy1; ++cy)
        for (int cx = cx0; cx <= cx1; ++cx) near_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(cx)] = 1;
    }
  }

  // Whether some joinable hole may lie within the door reach of v (a vertex of the outline).
  bool near(const Point2& v) const {
    const int cx = cell_of(v.x, x0_), cy = cell_of(v.y, y0_);
    if (cx < 0 || cy < 0 || cx >= nx_ || cy >= ny_) return true;
    return near_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(cx)] != 0;
  }

 private:
  int cell_of(double x, double origin) const { return static_cast<int>(std::floor((x - origin) / cell_)); }

  double cell_ = 1.0, x0_ = 0.0, y0_ = 0.0;
  int nx_ = 0, ny_ = 0;
  std::vector<unsigned char> near_;
};

}  // namespace

// Door candidates: from every reflex corner, the shortest cut across it, to its own ring or (across)
// to another joinable one.
std::vector<Candidate> corner_cuts(const DoorSearch& search, const EdgeGrid& grid, bool across) {
  std::vector<Candidate> candidates;
  std::vector<unsigned> seen(search.edges.size(), 0);  // per edge: the last corner that looked at it
  unsigned stamp = 0;
  std::optional<IslandReach> islands;
  if (across) islands.emplace(search);
  for_each_reflex_corner(
      search,
      [&](std::size_t r, const Ring& hole) {
        return too_small_for_a_room(hole, search.resolution) || (across && !search.joinable[r]);
      },
      [&](int r, int i, const Point2& p, const Point2& v, const Point2& q) {
        if (islands && r == 0 && !islands->near(v)) return;
        // Edge i of a ring runs from its vertex i (PolygonEdges lists them ring by ring).
        const int first = search.first_edge[static_cast<std::size_t>(r)];
        const int n = search.first_edge[static_cast<std::size_t>(r) + 1] - first;
        if (auto c = nearest_across_corner(search, grid, r, first + (i + n - 1) % n, first + i, p, v, q, across, seen, ++stamp))
          candidates.push_back(*c);
      });
  return candidates;
}

// Door test: both sides much wider than the passage.
bool has_wide_sides(const DoorSearch& search, const EdgeGrid& grid, const Candidate& c) {
  const Point2 d = minus(c.segment.b, c.segment.a);
  const Point2 u{d.x / c.width, d.y / c.width};
  const Point2 mid{(c.segment.a.x + c.segment.b.x) / 2.0, (c.segment.a.y + c.segment.b.y) / 2.0};
  const double cap = c.width / search.options.door_like.ratio;
  return side_width(grid, mid, u, {-u.y, u.x}, search.depth, cap) >= cap &&
         side_width(grid, mid, u, {u.y, -u.x}, search.depth, cap) >= cap;
}

// Narrowest first; a door found from both of its jambs (or from two corners of one wall end) is
// kept once; crossing cuts are not allowed. Each candidate is tested against the accepted cuts near
// it only (a grid of their boxes), not against all of them; keep last, as a candidate it rejects
// would not have blocked any other.
std::vector<Candidate> narrowest_compatible(std::vector<Candidate> doors, double resolution,
                                           const std::function<bool(const Candidate&)>& keep) {
  std::sort(doors.begin(), doors.end(), [](const Candidate& x, const Candidate& y) {
    return std::tie(x.width, x.segment.a.x, x.segment.a.y, x.segment.b.x, x.segment.b.y) <
           std::tie(y.width, y.segment.a.x, y.segment.a.y, y.segment.b.x, y.segment.b.y);
  });
  const double duplicate = 0.3 / resolution;
  std::vector<Candidate> accepted;
  CutGrid near(duplicate);
  for (const Candidate& c : doors) {
    const bool conflict = near.any_near(c.segment, [&](int i) {
      const Segment2& s = accepted[static_cast<std::size_t>(i)].segment;
      return segments_conflict(c.segment, s) ||
             (distance_to_segment(c.segment.a, s) < duplicate && distance_to_segment(c.segment.b, s) < duplicate) ||
             (distance_to_segment(s.a, c.segment) < duplicate && distance_to_segment(s.b, c.segment) < duplicate);
    });
    if (conflict || (keep && !keep(c))) continue;
    accepted.push_back(c);
    near.add(c.segment);
  }
  return accepted;
}

std::vector<Segment2> segments_of(const std::vector<Candidate>& candidates) {
  std::vector<Segment2> out;
  out.reserve(candidates.size());
  for (const Candidate& c : candidates) out.push_back(c.segment);
  return out;
}

// The doors as candidates that go first and stay: narrowest_compatible keeps later cuts off them.
std::vector<Candidate> doors_first(const std::vector<Segment2>& doors) {
  std::vector<Candidate> all;
  for (const Segment2& d : doors) all.push_back({d, -1.0, 0});
  return all;
}

bool is_door_first(const Candidate& c) { return c.width < 0.0; }

// cuts without the doors (which went first only to keep the other cuts clear of them).
std::vector<Segment2> without_doors(std::vector<Segment2> cuts, const std::vector<Segment2>& doors) {
  std::erase_if(cuts, [&](const Segment2& s) { return std::find(doors.begin(), doors.end(), s) != doors.end(); });
  return cuts;
}

}  // namespace topocut::cut_search

namespace topocut {

CutSearchIndex::CutSearchIndex(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options)
    : polygon_(polygon), resolution_(resolution), cell_(cut_search::search_cell(options, resolution)), min_turn_(options.min_turn) {}

CutSearchIndex::~CutSearchIndex() = default;

const cut_search::PolygonEdges* CutSearchIndex::edges_for(const PolygonWithHoles& polygon, double resolution,
                                                          const DoorOptions& options) const {
  if (&polygon != &polygon_ || resolution != resolution_ || cut_search::search_cell(options, resolution) != cell_ ||
      options.min_turn != min_turn_)
    return nullptr;
  if (!edges_) edges_ = std::make_unique<cut_search::PolygonEdges>(polygon_, cell_, min_turn_);
  return edges_.get();
}

}  // namespace topocut
