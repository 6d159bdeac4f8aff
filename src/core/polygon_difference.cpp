#include "topocut/core/polygon_difference.h"

#include <algorithm>

#include <CGAL/Boolean_set_operations_2/Gps_polygon_validation.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include "topocut/core/error.h"

namespace topocut {

namespace {

// Exact constructions: the edges of a cut-out region cross the polygon's edges at points no double
// holds, and the set operations must see those points where they are.
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<Kernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using ExactSet = CGAL::Polygon_set_2<Kernel>;

ExactPolygon exact_ring(const Ring& ring, bool counter_clockwise) {
  ExactPolygon result;
  for (const Point2& p : oriented(ring, counter_clockwise)) result.push_back(Kernel::Point_2(p.x, p.y));
  return result;
}

// The polygon in exact arithmetic, checked against CGAL's conditions: its operations assume them.
ExactPolygonWithHoles exact_polygon(const PolygonWithHoles& polygon) {
  ExactPolygonWithHoles result(exact_ring(polygon.outer, true));
  for (const Ring& hole : polygon.holes) result.add_hole(exact_ring(hole, false));
  typename ExactSet::Traits_2 traits;
  if (!CGAL::is_valid_polygon_with_holes(result, traits))
    throw Error("polygon_difference: a ring is not simple or a hole lies not inside its outer ring");
  return result;
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
  for (const PolygonWithHoles& cut : minus) set.difference(exact_polygon(cut));
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
