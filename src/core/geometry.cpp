#include "topocut/core/geometry.h"

#include <algorithm>
#include <cmath>

namespace topocut {

double signed_area(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return 0.0;
  // Relative to the first vertex: the shoelace terms of far-off coordinates would otherwise cancel.
  const Point2 o = ring[0];
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double px = ring[i].x - o.x, py = ring[i].y - o.y;
    const double qx = ring[i + 1].x - o.x, qy = ring[i + 1].y - o.y;
    twice += px * qy - qx * py;
  }
  return 0.5 * twice;
}

Box bounding_box(const Ring& ring) {
  Box box;
  for (const Point2& p : ring) {
    box.x0 = std::min(box.x0, p.x);
    box.y0 = std::min(box.y0, p.y);
    box.x1 = std::max(box.x1, p.x);
    box.y1 = std::max(box.y1, p.y);
  }
  return box;
}

double perimeter(const Ring& ring) {
  double length = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) length += distance(ring[i], ring[(i + 1) % ring.size()]);
  return length;
}

double area(const PolygonWithHoles& polygon) {
  double a = std::abs(signed_area(polygon.outer));
  for (const Ring& hole : polygon.holes) a -= std::abs(signed_area(hole));
  return a;
}

namespace {
// Accumulates the first moments of a ring, signed so that holes subtract when oriented opposite.
void add_moments(const Ring& ring, double sign, double& a2, double& mx, double& my) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& p = ring[i];
    const Point2& q = ring[(i + 1) % n];
    const double c = cross(p, q);
    a2 += sign * c;
    mx += sign * (p.x + q.x) * c;
    my += sign * (p.y + q.y) * c;
  }
}
}  // namespace

Point2 centroid(const PolygonWithHoles& polygon) {
  const PolygonWithHoles p = normalized_orientation(polygon);
  double a2 = 0.0, mx = 0.0, my = 0.0;
  add_moments(p.outer, 1.0, a2, mx, my);
  for (const Ring& hole : p.holes) add_moments(hole, 1.0, a2, mx, my);
  if (std::abs(a2) < 1e-12) {
    Point2 sum;
    if (p.outer.empty()) return sum;
    for (const Point2& v : p.outer) sum = sum + v;
    return sum / static_cast<double>(p.outer.size());
  }
  return {mx / (3.0 * a2), my / (3.0 * a2)};
}

Ring oriented(const Ring& ring, bool counter_clockwise) {
  if ((signed_area(ring) > 0.0) == counter_clockwise || ring.size() < 3) return ring;
  return Ring(ring.rbegin(), ring.rend());
}

PolygonWithHoles normalized_orientation(const PolygonWithHoles& polygon) {
  PolygonWithHoles result;
  result.outer = oriented(polygon.outer, true);
  result.holes.reserve(polygon.holes.size());
  for (const Ring& hole : polygon.holes) result.holes.push_back(oriented(hole, false));
  return result;
}

double distance(const Point2& a, const Point2& b) { return std::hypot(a.x - b.x, a.y - b.y); }

double distance_to_segment(const Point2& p, const Segment2& s) {
  const Point2 d = s.b - s.a;
  const double length2 = dot(d, d);
  const double t = length2 > 0.0 ? std::clamp(dot(p - s.a, d) / length2, 0.0, 1.0) : 0.0;
  return distance(p, s.a + t * d);
}

}  // namespace topocut
