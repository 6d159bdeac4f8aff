#pragma once
// Private bridge between the plain value types and CGAL (Epick kernel). Only .cpp files and tests
// include it, so CGAL's heavy headers stay out of the public API.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include "topocut/core/geometry.h"

namespace topocut::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
using Segment = Kernel::Segment_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

inline Point to_cgal(const Point2& p) { return {p.x, p.y}; }
inline Point2 from_cgal(const Point& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

inline Polygon to_cgal(const Ring& ring) {
  Polygon polygon;
  for (const Point2& p : ring) polygon.push_back(to_cgal(p));
  return polygon;
}

inline Ring from_cgal(const Polygon& polygon) {
  Ring ring;
  ring.reserve(polygon.size());
  for (const Point& p : polygon.container()) ring.push_back(from_cgal(p));
  return ring;
}

inline PolygonWithHoles to_cgal(const topocut::PolygonWithHoles& polygon) {
  PolygonWithHoles result(to_cgal(polygon.outer));
  for (const Ring& hole : polygon.holes) result.add_hole(to_cgal(hole));
  return result;
}

inline topocut::PolygonWithHoles from_cgal(const PolygonWithHoles& polygon) {
  topocut::PolygonWithHoles result;
  result.outer = from_cgal(polygon.outer_boundary());
  for (auto it = polygon.holes_begin(); it != polygon.holes_end(); ++it) result.holes.push_back(from_cgal(*it));
  return result;
}

}  // namespace topocut::cgal
