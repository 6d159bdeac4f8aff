#include "topocut/core/polygon_difference.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "topocut/core/error.h"

namespace topocut {
namespace {

PolygonWithHoles square(double x0, double y0, double side) {
  return {{{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}}, {}};
}

// A corner, a hole, a split in two and nothing at all taken out of a 4 x 4 square, by hand.
TEST(PolygonDifference, CornersHolesAndSplitsByHand) {
  const PolygonWithHoles a = square(0, 0, 4);
  std::vector<PolygonWithHoles> parts = polygon_difference(a, {square(2, 2, 4)});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_DOUBLE_EQ(area(parts[0]), 12.0);  // an L: 16 - 2 x 2
  EXPECT_TRUE(parts[0].holes.empty());
  EXPECT_GT(signed_area(parts[0].outer), 0.0);

  parts = polygon_difference(a, {square(1, 1, 1)});
  ASSERT_EQ(parts.size(), 1u);
  ASSERT_EQ(parts[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ(area(parts[0]), 15.0);
  EXPECT_LT(signed_area(parts[0].holes[0]), 0.0);

  // A band 1 wide across at y in [1, 2] leaves a 4 x 1 and a 4 x 2 part, the larger first.
  parts = polygon_difference(a, {PolygonWithHoles{{{-1, 1}, {5, 1}, {5, 2}, {-1, 2}}, {}}});
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_DOUBLE_EQ(area(parts[0]), 8.0);
  EXPECT_DOUBLE_EQ(area(parts[1]), 4.0);

  // A slanted edge crossing the square's at (3.5, 0) and (4, 0.5): 16 - the corner (1/2 x 0.5 x 0.5);
  // a region beside the square takes nothing.
  parts = polygon_difference(a, {PolygonWithHoles{{{2.5, -1}, {5, -1}, {5, 1.5}}, {}}, square(10, 10, 1)});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_NEAR(area(parts[0]), 16.0 - 0.125, 1e-12);

  EXPECT_DOUBLE_EQ(area(polygon_difference(a, {}).at(0)), 16.0);
  EXPECT_TRUE(polygon_difference(a, {square(-1, -1, 6)}).empty());
  // A clockwise outer ring is read as the same square.
  PolygonWithHoles clockwise = a;
  std::reverse(clockwise.outer.begin(), clockwise.outer.end());
  EXPECT_DOUBLE_EQ(area(polygon_difference(clockwise, {square(2, 2, 4)}).at(0)), 12.0);
}

// A ring crossing itself (a bow tie) is no polygon CGAL's set operations take.
TEST(PolygonDifference, ARingCrossingItselfIsAnError) {
  const PolygonWithHoles bow_tie{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}};
  EXPECT_THROW(polygon_difference(bow_tie, {square(0, 0, 1)}), Error);
  EXPECT_THROW(polygon_difference(square(0, 0, 4), {bow_tie}), Error);
}

}  // namespace
}  // namespace topocut
