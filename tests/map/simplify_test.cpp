#include "topocut/map/simplify.h"

#include <cmath>

#include <gtest/gtest.h>

namespace topocut {
namespace {

// Distance from p to the closed ring's boundary.
double distance_to_ring(const Point2& p, const Ring& ring) {
  double best = INFINITY;
  for (std::size_t i = 0; i < ring.size(); ++i) best = std::fmin(best, distance_to_segment(p, {ring[i], ring[(i + 1) % ring.size()]}));
  return best;
}

// A right triangle whose hypotenuse is a pixel staircase (steps of one cell), counter-clockwise.
Ring staircase_triangle(int steps) {
  Ring ring{{0, 0}, {static_cast<double>(steps), 0}};
  for (int k = steps; k > 0; --k) {
    ring.push_back({static_cast<double>(k), static_cast<double>(steps - k + 1)});
    ring.push_back({static_cast<double>(k - 1), static_cast<double>(steps - k + 1)});
  }
  ring.pop_back();  // the last step ends on the y axis at (0, steps)
  ring.push_back({0, static_cast<double>(steps)});
  return ring;
}

TEST(Simplify, StairStepsBecomeOneEdgeAndEveryVertexStaysWithinTolerance) {
  const Ring stairs = staircase_triangle(20);
  ASSERT_GT(signed_area(stairs), 0.0);
  const Ring simple = simplify_ring(stairs, 0.75);
  EXPECT_LE(simple.size(), 4u);
  EXPECT_GT(signed_area(simple), 0.0);
  for (const Point2& p : stairs) EXPECT_LE(distance_to_ring(p, simple), 0.75 + 1e-12);
  // Kept vertices are original vertices.
  for (const Point2& p : simple) EXPECT_NE(std::find(stairs.begin(), stairs.end(), p), stairs.end());
  // Below the steps' depth (0.707 from the diagonal) every corner stays.
  EXPECT_GT(simplify_ring(stairs, 0.3).size(), 20u);
}

TEST(Simplify, SquaresAndZeroToleranceAreUnchanged) {
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_EQ(simplify_ring(square, 0.45), square);
  const Ring stairs = staircase_triangle(5);
  EXPECT_EQ(simplify_ring(stairs, 0.0), stairs);
  const PolygonWithHoles polygon{square, {{{2, 2}, {2, 3}, {3, 3}, {3, 2}}}};
  EXPECT_EQ(simplify_polygon(polygon, 0.45), polygon);
}

}  // namespace
}  // namespace topocut
