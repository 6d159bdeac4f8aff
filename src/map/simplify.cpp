#include "topocut/map/simplify.h"

#include <cmath>
#include <utility>
#include <vector>

namespace topocut {

namespace {

// Squared distance from p to the segment ab.
double squared_distance(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 d = b - a;
  const double length2 = dot(d, d);
  double t = length2 > 0.0 ? dot(p - a, d) / length2 : 0.0;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  const Point2 e = a + t * d - p;
  return dot(e, e);
}

// Marks the vertices of ring[first..last] (indices modulo n) that Douglas-Peucker keeps.
void mark(const Ring& ring, std::size_t first, std::size_t last, double tolerance2, std::vector<char>& keep) {
  const std::size_t n = ring.size();
  std::vector<std::pair<std::size_t, std::size_t>> stack{{first, last}};  // explicit stack: rings can be long
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const std::size_t span = (j + n - i) % n;
    if (span < 2) continue;
    double worst = -1.0;
    std::size_t at = i;
    for (std::size_t s = 1; s < span; ++s) {
      const std::size_t k = (i + s) % n;
      const double d = squared_distance(ring[k], ring[i], ring[j]);
      if (d > worst) {
        worst = d;
        at = k;
      }
    }
    if (worst > tolerance2) {
      keep[at] = 1;
      stack.emplace_back(i, at);
      stack.emplace_back(at, j);
    }
  }
}

}  // namespace

Ring simplify_ring(const Ring& ring, double tolerance) {
  const std::size_t n = ring.size();
  if (n < 4 || !(tolerance > 0.0)) return ring;
  // Split the closed ring at two far-apart vertices: the first one and the vertex farthest from it.
  std::size_t far = 0;
  double best = -1.0;
  for (std::size_t k = 1; k < n; ++k) {
    const double d = (ring[k].x - ring[0].x) * (ring[k].x - ring[0].x) + (ring[k].y - ring[0].y) * (ring[k].y - ring[0].y);
    if (d > best) {
      best = d;
      far = k;
    }
  }
  std::vector<char> keep(n, 0);
  keep[0] = keep[far] = 1;
  const double tolerance2 = tolerance * tolerance;
  mark(ring, 0, far, tolerance2, keep);
  mark(ring, far, 0, tolerance2, keep);
  Ring out;
  for (std::size_t k = 0; k < n; ++k)
    if (keep[k]) out.push_back(ring[k]);
  return out;
}

PolygonWithHoles simplify_polygon(const PolygonWithHoles& polygon, double tolerance) {
  auto simplified = [&](const Ring& ring) {
    Ring s = simplify_ring(ring, tolerance);
    return s.size() >= 3 && signed_area(s) != 0.0 ? s : ring;
  };
  PolygonWithHoles out;
  out.outer = simplified(polygon.outer);
  out.holes.reserve(polygon.holes.size());
  for (const Ring& hole : polygon.holes) out.holes.push_back(simplified(hole));
  return out;
}

}  // namespace topocut
