#pragma once
// Vector arithmetic on Point2 for the door search and the polygon split (internal to the module).
#include <cmath>
#include <cstddef>

#include "topocut/core/geometry.h"

namespace topocut::plane {

using topocut::cross;  // core/geometry.h's, under the names this module's code calls
using topocut::dot;
inline Point2 minus(const Point2& a, const Point2& b) { return {a.x - b.x, a.y - b.y}; }
inline double length(const Point2& a) { return std::hypot(a.x, a.y); }

// The turn at b from a -> b to b -> c, in radians: positive to the left.
inline double turn_angle(const Point2& a, const Point2& b, const Point2& c) {
  const Point2 d = minus(b, a), e = minus(c, b);
  return std::atan2(cross(d, e), dot(d, e));
}

// Even-odd point-in-ring test (half-open in y).
inline bool in_ring(const Ring& ring, const Point2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point2& a = ring[i];
    const Point2& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
  }
  return inside;
}

}  // namespace topocut::plane
