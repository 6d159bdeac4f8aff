#include "decomposition/validate.h"

#include <CGAL/box_intersection_d.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "core/cgal_geometry.h"
#include "topocut/core/error.h"

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

// Checks that no two edges of any rings share a point other than the common vertex of two
// consecutive edges of the same ring (and that such neighbours do not fold back onto each other).
void check_no_intersections(const std::vector<std::vector<CPoint>>& rings) {
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, Edge>;
  std::vector<Box> boxes;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const CPoint& a = ring[i];
      const CPoint& b = ring[(i + 1) % ring.size()];
      boxes.emplace_back(a.bbox() + b.bbox(), Edge{static_cast<int>(r), static_cast<int>(i)});
    }
  }
  bool failed = false;
  std::string message;
  auto report = [&](const Edge& e, const Edge& f) {
    if (failed) return;
    const auto& re = rings[e.ring];
    const auto& rf = rings[f.ring];
    const int ne = static_cast<int>(re.size());
    const int nf = static_cast<int>(rf.size());
    const CPoint& a = re[e.index];
    const CPoint& b = re[(e.index + 1) % ne];
    const CPoint& c = rf[f.index];
    const CPoint& d = rf[(f.index + 1) % nf];
    bool bad = false;
    if (e.ring == f.ring && (f.index == (e.index + 1) % ne || e.index == (f.index + 1) % nf)) {
      // Consecutive edges share one vertex; they are fine unless they fold back onto each other.
      const bool e_first = f.index == (e.index + 1) % ne;
      const CPoint& p = e_first ? a : c;  // start of the first edge
      const CPoint& q = e_first ? b : d;  // shared vertex
      const CPoint& s = e_first ? d : b;  // end of the second edge
      if (CGAL::orientation(p, q, s) == CGAL::COLLINEAR && !CGAL::collinear_are_strictly_ordered_along_line(p, q, s)) {
        bad = true;
      }
    } else {
      bad = CGAL::do_intersect(cgal::Segment(a, b), cgal::Segment(c, d));
    }
    if (bad) {
      failed = true;
      if (e.ring == f.ring) {
        message = ring_name(e.ring) + " intersects itself near " + point_text(cgal::from_cgal(a));
      } else {
        message = ring_name(e.ring) + " and " + ring_name(f.ring) + " intersect or touch near " +
                  point_text(cgal::from_cgal(a));
      }
    }
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(),
                               [&](const Box& x, const Box& y) { report(x.info(), y.info()); });
  if (failed) throw Error(message);
}

}  // namespace

Ring reversed_keep_first(const Ring& ring) {
  Ring out;
  out.reserve(ring.size());
  if (ring.empty()) return out;
  out.push_back(ring[0]);
  for (std::size_t i = ring.size() - 1; i >= 1; --i) out.push_back(ring[i]);
  return out;
}

PolygonWithHoles clean_and_validate(const PolygonWithHoles& polygon) {
  PolygonWithHoles result;
  result.outer = without_repeats(polygon.outer, 0);
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) result.holes.push_back(without_repeats(polygon.holes[h], h + 1));

  std::vector<std::vector<CPoint>> rings;
  rings.reserve(1 + result.holes.size());
  auto to_points = [](const Ring& ring) {
    std::vector<CPoint> points;
    points.reserve(ring.size());
    for (const Point2& p : ring) points.push_back(cgal::to_cgal(p));
    return points;
  };
  rings.push_back(to_points(result.outer));
  for (const Ring& hole : result.holes) rings.push_back(to_points(hole));
  check_no_intersections(rings);

  // Rings are now pairwise disjoint simple closed curves, so one vertex decides containment.
  std::vector<CGAL::Bbox_2> boxes;
  for (const auto& ring : rings) boxes.push_back(CGAL::bbox_2(ring.begin(), ring.end()));
  for (std::size_t h = 1; h < rings.size(); ++h) {
    const CPoint& p = rings[h][0];
    if (CGAL::bounded_side_2(rings[0].begin(), rings[0].end(), p, Kernel()) != CGAL::ON_BOUNDED_SIDE) {
      throw Error(ring_name(h) + " is not inside the outer ring");
    }
    for (std::size_t g = 1; g < rings.size(); ++g) {
      if (g == h || !CGAL::do_overlap(boxes[g], p.bbox())) continue;
      if (CGAL::bounded_side_2(rings[g].begin(), rings[g].end(), p, Kernel()) == CGAL::ON_BOUNDED_SIDE) {
        throw Error(ring_name(h) + " lies inside " + ring_name(g));
      }
    }
  }

  if (signed_area(result.outer) < 0.0) result.outer = reversed_keep_first(result.outer);
  for (Ring& hole : result.holes) {
    if (signed_area(hole) > 0.0) hole = reversed_keep_first(hole);
  }
  return result;
}

}  // namespace topocut::dude
