#include "decomposition/validate.h"

#include "topocut/decomposition/ring_intersections.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <sstream>
#include <string>
#include <vector>

#include "core/cgal_geometry.h"
#include "topocut/core/error.h"
#include "topocut/core/value_ranges.h"

namespace topocut::dude {

namespace {

using cgal::Kernel;
using CPoint = cgal::Point;

std::string ring_name(std::size_t ring) {
  return ring == 0 ? std::string("the outer ring") : "hole " + std::to_string(ring - 1);
}

std::string point_text(const Point2& p) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << p.x << ", " << p.y << ")";
  return out.str();
}

Ring without_repeats(const Ring& ring, std::size_t index) {
  Ring out;
  out.reserve(ring.size());
  for (const Point2& p : ring) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      throw Error(ring_name(index) + " has a non-finite coordinate");
    }
    if (out.empty() || !(out.back() == p)) out.push_back(p);
  }
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  if (out.size() < 3) throw Error(ring_name(index) + " has fewer than 3 distinct vertices");
  return out;
}

struct Edge {
  int ring;
  int index;  // edge from vertex index to index+1 of that ring
};

struct VInfo {
  int id = -1;  // global vertex index; -1 for points CGAL creates where constraints cross
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VInfo, Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

// The same check with a constrained triangulation, for inputs (long spikes) whose edge boxes overlap
// so much that testing box pairs would be quadratic: every ring edge must survive as an edge of the
// triangulation, without points inserted where constraints cross and without repeated points.
void check_with_triangulation(const std::vector<std::vector<CPoint>>& rings) {
  std::vector<std::pair<CPoint, VInfo>> points;
  std::vector<int> ring_of;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (const CPoint& p : rings[r]) {
      points.emplace_back(p, VInfo{static_cast<int>(points.size())});
      ring_of.push_back(static_cast<int>(r));
    }
  }
  CDT cdt;
  cdt.insert(points.begin(), points.end());
  std::vector<CDT::Vertex_handle> handle(points.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[v->info().id] = v;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (handle[i] == CDT::Vertex_handle()) {
      throw Error(ring_name(ring_of[i]) + " repeats a point or touches another ring at " +
                  point_text(cgal::from_cgal(points[i].first)));
    }
  }
  std::size_t first = 0;
  for (const auto& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      cdt.insert_constraint(handle[first + i], handle[first + (i + 1) % ring.size()]);
    }
    first += ring.size();
  }
  first = 0;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (std::size_t i = 0; i < rings[r].size(); ++i) {
      if (!cdt.is_edge(handle[first + i], handle[first + (i + 1) % rings[r].size()])) {
        throw Error(ring_name(r) + " intersects itself or another ring near " +
                    point_text(cgal::from_cgal(rings[r][i])));
      }
    }
    first += rings[r].size();
  }
}

// A uniform grid over the edges of all rings: each edge is listed in every cell its bounding box
// covers. Cells are about as large as the edges, so pixel-traced rings give a few edges per cell.
class EdgeGrid {
 public:
  // Returns false (and stays empty) when the edges would fill more than `budget` cell slots.
  bool build(const std::vector<std::vector<CPoint>>& rings, std::size_t budget) {
    rings_ = &rings;
    CGAL::Bbox_2 box;
    std::size_t n = 0;
    double length = 0.0;
    for (const auto& ring : rings) {
      box += CGAL::bbox_2(ring.begin(), ring.end());
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const CPoint& a = ring[i];
        const CPoint& b = ring[(i + 1) % ring.size()];
        length += std::abs(a.x() - b.x()) + std::abs(a.y() - b.y());
        edges_.push_back({static_cast<int>(&ring - rings.data()), static_cast<int>(i)});
        ++n;
      }
    }
    x0_ = box.xmin();
    y0_ = box.ymin();
    const double w = std::max(box.xmax() - box.xmin(), 1e-300), h = std::max(box.ymax() - box.ymin(), 1e-300);
    // Cell side: twice the mean edge extent, but at most about 4 n cells in all.
    double side = std::max(2.0 * length / static_cast<double>(n), std::sqrt(w * h / (4.0 * static_cast<double>(n))));
    if (!(side > 0.0) || !std::isfinite(side)) side = std::max(w, h);
    nx_ = static_cast<int>(std::min(w / side, 1e6)) + 1;
    ny_ = static_cast<int>(std::min(h / side, 1e6)) + 1;
    side_ = side;
    std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    std::size_t slots = 0;
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      const auto [ix0, iy0, ix1, iy1] = cells_of(e);
      slots += static_cast<std::size_t>(ix1 - ix0 + 1) * (iy1 - iy0 + 1);
      if (slots > budget) return false;
      for (int y = iy0; y <= iy1; ++y) {
        for (int x = ix0; x <= ix1; ++x) ++count[static_cast<std::size_t>(y) * nx_ + x + 1];
      }
    }
    for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
    start_ = count;
    items_.resize(slots);
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      const auto [ix0, iy0, ix1, iy1] = cells_of(e);
      for (int y = iy0; y <= iy1; ++y) {
        for (int x = ix0; x <= ix1; ++x) items_[count[static_cast<std::size_t>(y) * nx_ + x]++] = static_cast<int>(e);
      }
    }
    return true;
  }

  // Calls f(e, g) once for every pair of edges whose bounding boxes overlap; stops early (returns
  // false) once more than `budget` candidate pairs were seen.
  template <class F>
  bool for_each_overlapping_pair(std::size_t budget, F f) const {
    std::size_t pairs = 0;
    for (int cell = 0; cell < nx_ * ny_; ++cell) {
      const int cx = cell % nx_, cy = cell / nx_;
      for (std::uint32_t i = start_[cell]; i < start_[cell + 1]; ++i) {
        const int e = items_[i];
        const CGAL::Bbox_2 be = box(e);
        for (std::uint32_t j = i + 1; j < start_[cell + 1]; ++j) {
          if (++pairs > budget) return false;
          const int g = items_[j];
          const CGAL::Bbox_2 bg = box(g);
          if (!CGAL::do_overlap(be, bg)) continue;
          // Test each pair only in the cell holding the lower-left corner of the boxes' overlap.
          if (cell_x(std::max(be.xmin(), bg.xmin())) != cx || cell_y(std::max(be.ymin(), bg.ymin())) != cy) continue;
          f(edges_[e], edges_[g]);
        }
      }
    }
    return true;
  }

  // Calls f(edge) once for every edge whose box meets the ray from p towards +x.
  template <class F>
  void for_each_on_ray(const CPoint& p, F f) const {
    const int cy = cell_y(p.y());
    for (int cx = cell_x(p.x()); cx < nx_; ++cx) {
      const int cell = cy * nx_ + cx;
      for (std::uint32_t i = start_[cell]; i < start_[cell + 1]; ++i) {
        const int e = items_[i];
        const CGAL::Bbox_2 be = box(e);
        if (be.ymin() > p.y() || be.ymax() < p.y() || be.xmax() < p.x()) continue;
        if (cell_x(std::max(p.x(), be.xmin())) != cx) continue;  // first cell of the ray inside the box
        f(edges_[e]);
      }
    }
  }

 private:
  int cell_x(double x) const { return std::clamp(static_cast<int>((x - x0_) / side_), 0, nx_ - 1); }
  int cell_y(double y) const { return std::clamp(static_cast<int>((y - y0_) / side_), 0, ny_ - 1); }
  CGAL::Bbox_2 box(int e) const {
    const auto& ring = (*rings_)[edges_[e].ring];
    return ring[edges_[e].index].bbox() + ring[(edges_[e].index + 1) % ring.size()].bbox();
  }
  std::array<int, 4> cells_of(std::size_t e) const {
    const CGAL::Bbox_2 b = box(static_cast<int>(e));
    return {cell_x(b.xmin()), cell_y(b.ymin()), cell_x(b.xmax()), cell_y(b.ymax())};
  }

  const std::vector<std::vector<CPoint>>* rings_ = nullptr;
  std::vector<Edge> edges_;
  std::vector<std::uint32_t> start_;
  std::vector<int> items_;
  double x0_ = 0, y0_ = 0, side_ = 1;
  int nx_ = 1, ny_ = 1;
};

// Whether two edges whose boxes overlap share a point they must not: any point, unless they are
// consecutive edges of one ring, which may share their common vertex but not fold back onto each other.
bool edges_meet(const std::vector<std::vector<CPoint>>& rings, const Edge& e, const Edge& f) {
  const auto& re = rings[e.ring];
  const auto& rf = rings[f.ring];
  const int ne = static_cast<int>(re.size());
  const int nf = static_cast<int>(rf.size());
  const CPoint& a = re[e.index];
  const CPoint& b = re[(e.index + 1) % ne];
  const CPoint& c = rf[f.index];
  const CPoint& d = rf[(f.index + 1) % nf];
  if (e.ring == f.ring && (f.index == (e.index + 1) % ne || e.index == (f.index + 1) % nf)) {
    const bool e_first = f.index == (e.index + 1) % ne;
    const CPoint& p = e_first ? a : c;  // start of the first edge
    const CPoint& q = e_first ? b : d;  // shared vertex
    const CPoint& s = e_first ? d : b;  // end of the second edge
    return CGAL::orientation(p, q, s) == CGAL::COLLINEAR && !CGAL::collinear_are_strictly_ordered_along_line(p, q, s);
  }
  return CGAL::do_intersect(cgal::Segment(a, b), cgal::Segment(c, d));
}

// Checks that no two edges of any rings share a point other than the common vertex of two
// consecutive edges of the same ring (and that such neighbours do not fold back onto each other).
// Returns false when the grid is unsuitable (long edges) and the check must be done otherwise.
bool check_no_intersections(const std::vector<std::vector<CPoint>>& rings, const EdgeGrid& grid, std::size_t budget) {
  bool failed = false;
  std::string message;
  auto report = [&](const Edge& e, const Edge& f) {
    if (failed || !edges_meet(rings, e, f)) return;
    failed = true;
    const CPoint& a = rings[e.ring][e.index];
    if (e.ring == f.ring) {
      message = ring_name(e.ring) + " intersects itself near " + point_text(cgal::from_cgal(a));
    } else {
      message = ring_name(e.ring) + " and " + ring_name(f.ring) + " intersect or touch near " +
                point_text(cgal::from_cgal(a));
    }
  };
  if (!grid.for_each_overlapping_pair(budget, report)) return false;
  if (failed) throw Error(message);
  return true;
}

// For each hole, the parity of crossings of a ray from its first vertex towards +x with every other
// ring: odd means inside that ring. Rings must not intersect (checked before).
std::unordered_map<std::uint64_t, int> ray_parities(const std::vector<std::vector<CPoint>>& rings, const EdgeGrid& grid) {
  std::unordered_map<std::uint64_t, int> parity;
  for (std::size_t h = 1; h < rings.size(); ++h) {
    const CPoint& p = rings[h][0];
    grid.for_each_on_ray(p, [&](const Edge& edge) {
      const int r = edge.ring;
      if (r == static_cast<int>(h)) return;
      const auto& ring = rings[r];
      const CPoint& a = ring[edge.index];
      const CPoint& b = ring[(edge.index + 1) % ring.size()];
      if ((a.y() > p.y()) == (b.y() > p.y())) return;  // half-open rule: each crossing counted once
      const bool up = a.y() < b.y();
      if (CGAL::orientation(up ? a : b, up ? b : a, p) == CGAL::LEFT_TURN) {
        parity[(static_cast<std::uint64_t>(h) << 32) | static_cast<std::uint32_t>(r)] ^= 1;
      }
    });
  }
  return parity;
}

// Containment parities without the grid: every hole's ray against every edge (fallback path).
std::unordered_map<std::uint64_t, int> ray_parities_brute(const std::vector<std::vector<CPoint>>& rings) {
  std::unordered_map<std::uint64_t, int> parity;
  for (std::size_t h = 1; h < rings.size(); ++h) {
    const CPoint& p = rings[h][0];
    for (std::size_t r = 0; r < rings.size(); ++r) {
      if (r == h) continue;
      const auto& ring = rings[r];
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const CPoint& a = ring[i];
        const CPoint& b = ring[(i + 1) % ring.size()];
        if ((a.y() > p.y()) == (b.y() > p.y())) continue;
        const bool up = a.y() < b.y();
        if (CGAL::orientation(up ? a : b, up ? b : a, p) == CGAL::LEFT_TURN) {
          parity[(static_cast<std::uint64_t>(h) << 32) | static_cast<std::uint32_t>(r)] ^= 1;
        }
      }
    }
  }
  return parity;
}

}  // namespace

namespace {

// The rings as CGAL points: the outer ring first, then the holes.
std::vector<std::vector<CPoint>> cgal_rings(const PolygonWithHoles& polygon) {
  std::vector<std::vector<CPoint>> rings;
  rings.reserve(1 + polygon.holes.size());
  auto add = [&](const Ring& ring) {
    std::vector<CPoint> points;
    points.reserve(ring.size());
    for (const Point2& p : ring) points.push_back(cgal::to_cgal(p));
    rings.push_back(std::move(points));
  };
  add(polygon.outer);
  for (const Ring& hole : polygon.holes) add(hole);
  return rings;
}

// Cell slots and box pairs the edge grid may use before the check falls back (spiky inputs).
std::size_t grid_budget(const std::vector<std::vector<CPoint>>& rings) {
  std::size_t edges = 0;
  for (const auto& ring : rings) edges += ring.size();
  return 32 * edges + 100000;
}

}  // namespace

void check_rings_by_triangulation(const PolygonWithHoles& polygon) { check_with_triangulation(cgal_rings(polygon)); }

bool is_counter_clockwise(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return true;
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (ring[i].x < ring[m].x || (ring[i].x == ring[m].x && ring[i].y < ring[m].y)) m = i;
  }
  // The extreme vertex of a simple ring is convex, so the turn there gives the orientation.
  const CPoint a = cgal::to_cgal(ring[(m + n - 1) % n]), b = cgal::to_cgal(ring[m]), c = cgal::to_cgal(ring[(m + 1) % n]);
  return CGAL::orientation(a, b, c) == CGAL::LEFT_TURN;
}

Ring reversed_keep_first(const Ring& ring) {
  Ring out;
  out.reserve(ring.size());
  if (ring.empty()) return out;
  out.push_back(ring[0]);
  for (std::size_t i = ring.size() - 1; i >= 1; --i) out.push_back(ring[i]);
  return out;
}

namespace {

// Why: far from unit scale the pieces' areas and the decomposition's products overflow or vanish
// (a square of side 1e308 has no finite area); value_ranges.h gives the accepted scale.
void check_scale(const PolygonWithHoles& polygon) {
  double largest = 0.0;
  double min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
  for (const Point2& p : polygon.outer) {
    largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x), min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
  for (const Ring& hole : polygon.holes)
    for (const Point2& p : hole) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  std::ostringstream text;
  if (largest > kMaxPolygonCoordinate) {
    text << "polygon coordinates must lie in [-" << kMaxPolygonCoordinate << ", " << kMaxPolygonCoordinate
         << "], got one of magnitude " << largest << " (rescale the polygon and tau)";
  } else if (std::max(max_x - min_x, max_y - min_y) < kMinPolygonExtent) {
    text << "the polygon must be at least " << kMinPolygonExtent << " units wide or high, got "
         << std::max(max_x - min_x, max_y - min_y) << " (rescale the polygon and tau)";
  } else {
    return;
  }
  throw Error(text.str());
}

}  // namespace

PolygonWithHoles clean_and_validate(const PolygonWithHoles& polygon) {
  PolygonWithHoles result;
  result.outer = without_repeats(polygon.outer, 0);
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) result.holes.push_back(without_repeats(polygon.holes[h], h + 1));
  check_scale(result);

  const std::vector<std::vector<CPoint>> rings = cgal_rings(result);
  // A grid of the edges finds touching or crossing edges in about linear time on map-like rings;
  // inputs whose edges are long compared with their spacing (spiky stars) fill it quadratically and
  // are checked with a constrained triangulation instead.
  EdgeGrid grid;
  const std::size_t budget = grid_budget(rings);
  const bool gridded = grid.build(rings, budget) && check_no_intersections(rings, grid, budget);
  if (!gridded) check_with_triangulation(rings);

  // Rings are now pairwise disjoint simple closed curves, so one vertex decides containment.
  const std::unordered_map<std::uint64_t, int> parity = gridded ? ray_parities(rings, grid) : ray_parities_brute(rings);
  auto inside = [&](std::size_t h, std::size_t r) {
    const auto it = parity.find((static_cast<std::uint64_t>(h) << 32) | static_cast<std::uint32_t>(r));
    return it != parity.end() && it->second == 1;
  };
  for (std::size_t h = 1; h < rings.size(); ++h) {
    if (!inside(h, 0)) throw Error(ring_name(h) + " is not inside the outer ring");
  }
  std::uint64_t nested = std::numeric_limits<std::uint64_t>::max();  // smallest (hole, enclosing hole)
  for (const auto& [key, odd] : parity) {
    if (odd && (key & 0xffffffffu) != 0) nested = std::min(nested, key);
  }
  if (nested != std::numeric_limits<std::uint64_t>::max()) {
    throw Error(ring_name(nested >> 32) + " lies inside " + ring_name(nested & 0xffffffffu));
  }

  if (!is_counter_clockwise(result.outer)) result.outer = reversed_keep_first(result.outer);
  for (Ring& hole : result.holes) {
    if (is_counter_clockwise(hole)) hole = reversed_keep_first(hole);
  }
  return result;
}

}  // namespace topocut::dude

namespace topocut {

std::vector<int> intersecting_rings(const PolygonWithHoles& polygon) {
  using namespace dude;
  const std::vector<std::vector<CPoint>> rings = cgal_rings(polygon);
  const std::size_t budget = grid_budget(rings);
  std::vector<char> bad(rings.size(), 0);
  EdgeGrid grid;
  const bool gridded = grid.build(rings, budget) && grid.for_each_overlapping_pair(budget, [&](const Edge& e, const Edge& f) {
    if (edges_meet(rings, e, f)) bad[static_cast<std::size_t>(e.ring)] = bad[static_cast<std::size_t>(f.ring)] = 1;
  });
  std::vector<int> found;
  for (std::size_t r = 0; r < rings.size(); ++r)
    if (!gridded || bad[r]) found.push_back(static_cast<int>(r));
  return found;
}

}  // namespace topocut
