#include "topocut/core/polygon_difference.h"

#include <algorithm>

#include <CGAL/Boolean_set_operations_2/Gps_polygon_validation.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include "topocut/core/error.h"

namespace topocut {

namespace {

// Exact constructions: the edges of a cut-out region cross the polygon's edges at points no double
// holds, and the set operations must see those points where they are. The inputs are checked with
// exact predicates alone, which is all a check needs and costs a fraction.
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<Kernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using ExactSet = CGAL::Polygon_set_2<Kernel>;
using CheckKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CheckTraits = CGAL::Gps_segment_traits_2<CheckKernel>;

template <class K>
CGAL::Polygon_2<K> ring_in(const Ring& ring, bool counter_clockwise) {
  CGAL::Polygon_2<K> result;
  for (const Point2& p : oriented(ring, counter_clockwise)) result.push_back(typename K::Point_2(p.x, p.y));
  return result;
}

template <class K>
CGAL::Polygon_with_holes_2<K> polygon_in(const PolygonWithHoles& polygon) {
  CGAL::Polygon_with_holes_2<K> result(ring_in<K>(polygon.outer, true));
  for (const Ring& hole : polygon.holes) result.add_hole(ring_in<K>(hole, false));
  return result;
}

// The polygon in exact arithmetic, checked against CGAL's conditions: its operations assume them.
ExactPolygonWithHoles exact_polygon(const PolygonWithHoles& polygon) {
  CheckTraits traits;
  if (!CGAL::is_valid_polygon_with_holes(polygon_in<CheckKernel>(polygon), traits))
    throw Error("polygon_difference: a ring is not simple or a hole lies not inside its outer ring");
  return polygon_in<Kernel>(polygon);
}

Ring double_ring(const ExactPolygon& ring) {
  Ring result;
  result.reserve(ring.size());
  for (const auto& p : ring.container()) result.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
  return result;
}

}  // namespace

std::vector<PolygonWithHoles> polygon_difference(const PolygonWithHoles& polygon, const std::vector<PolygonWithHoles>& minus) {
  ExactSet set(exact_polygon(polygon));
  std::vector<ExactPolygonWithHoles> cuts;
  cuts.reserve(minus.size());
  for (const PolygonWithHoles& cut : minus) cuts.push_back(exact_polygon(cut));
  if (!cuts.empty()) {
    ExactSet cut_set;
    cut_set.join(cuts.begin(), cuts.end());  // one sweep for all, whether they overlap or not
    set.difference(cut_set);
  }
  std::vector<ExactPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  std::vector<PolygonWithHoles> result;
  result.reserve(parts.size());
  for (const ExactPolygonWithHoles& part : parts) {
    PolygonWithHoles plain;
    plain.outer = double_ring(part.outer_boundary());
    for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole) plain.holes.push_back(double_ring(*hole));
    result.push_back(normalized_orientation(plain));
  }
  std::stable_sort(result.begin(), result.end(), [](const PolygonWithHoles& a, const PolygonWithHoles& b) { return area(a) > area(b); });
  return result;
}

}  // namespace topocut
