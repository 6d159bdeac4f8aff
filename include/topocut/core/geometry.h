#pragma once
// Plain geometry value types shared by every module. They carry no CGAL types so that public
// headers stay light; src/core/cgal_geometry.h converts to and from CGAL where the geometry is done.
#include <limits>
#include <vector>

namespace topocut {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point2&, const Point2&) = default;
};

// A point also serves as a vector (from the origin): component-wise sum, difference, scaling.
inline Point2 operator+(const Point2& a, const Point2& b) { return {a.x + b.x, a.y + b.y}; }
inline Point2 operator-(const Point2& a, const Point2& b) { return {a.x - b.x, a.y - b.y}; }
inline Point2 operator*(double s, const Point2& v) { return {s * v.x, s * v.y}; }
inline Point2 operator*(const Point2& v, double s) { return {v.x * s, v.y * s}; }
inline Point2 operator/(const Point2& v, double s) { return {v.x / s, v.y / s}; }

// The dot product of two vectors.
inline double dot(const Point2& a, const Point2& b) { return a.x * b.x + a.y * b.y; }

// The z component of the cross product: positive when b turns counter-clockwise from a.
inline double cross(const Point2& a, const Point2& b) { return a.x * b.y - a.y * b.x; }

// A closed ring of vertices; the last vertex is implicitly joined to the first (never repeated).
using Ring = std::vector<Point2>;

// One outer ring (counter-clockwise) and any number of holes (clockwise), as in CGAL.
struct PolygonWithHoles {
  Ring outer;
  std::vector<Ring> holes;
  friend bool operator==(const PolygonWithHoles&, const PolygonWithHoles&) = default;
};

struct Segment2 {
  Point2 a;
  Point2 b;
  friend bool operator==(const Segment2&, const Segment2&) = default;
};

// An axis-aligned box; the default one is empty (it grows to the first point added).
struct Box {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -std::numeric_limits<double>::infinity(), y1 = x1;
};

// The smallest box holding every vertex of the ring (empty for an empty ring).
Box bounding_box(const Ring& ring);

// The signed area of a ring (positive when counter-clockwise).
double signed_area(const Ring& ring);

// The length of a ring's boundary, closing edge included.
double perimeter(const Ring& ring);

// Area of the outer ring minus the areas of the holes (orientation-independent).
double area(const PolygonWithHoles& polygon);

// Area centroid of a polygon with holes; the vertex mean if the area is zero.
Point2 centroid(const PolygonWithHoles& polygon);

// Returns the ring with the requested orientation (reversed if needed).
Ring oriented(const Ring& ring, bool counter_clockwise);

// Returns the polygon with the outer ring counter-clockwise and the holes clockwise.
PolygonWithHoles normalized_orientation(const PolygonWithHoles& polygon);

// Euclidean distance between two points.
double distance(const Point2& a, const Point2& b);

// Distance of a point from a segment (to its nearest point; a degenerate segment is its end a).
double distance_to_segment(const Point2& p, const Segment2& s);

}  // namespace topocut
