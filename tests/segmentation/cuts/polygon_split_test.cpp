#include "topocut/segmentation/polygon_split.h"

#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "topocut/core/error.h"

namespace topocut {
namespace {

// Two 6 x 6 rooms side by side, joined through a 1-thick wall by a door 2 wide (y in [2, 4]).
PolygonWithHoles rooms_with_a_door() {
  return {{{0, 0}, {6, 0}, {6, 2}, {7, 2}, {7, 0}, {13, 0}, {13, 6}, {7, 6}, {7, 4}, {6, 4}, {6, 6}, {0, 6}}, {}};
}

double area_of(const std::vector<PolygonWithHoles>& parts) {
  return std::accumulate(parts.begin(), parts.end(), 0.0, [](double sum, const PolygonWithHoles& p) { return sum + area(p); });
}

TEST(SplitPolygon, ADoorSplitsTwoRoomsIntoPartsThatTileThePolygon) {
  const PolygonWithHoles polygon = rooms_with_a_door();
  const Segment2 door{{6, 2}, {6, 4}};
  const std::vector<PolygonWithHoles> parts = split_polygon(polygon, {door});
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_DOUBLE_EQ(area_of(parts), area(polygon));
  for (const PolygonWithHoles& part : parts) {
    EXPECT_GT(signed_area(part.outer), 0.0);
    bool has_door = false;
    for (std::size_t i = 0; i < part.outer.size(); ++i) {
      const Point2& a = part.outer[i];
      const Point2& b = part.outer[(i + 1) % part.outer.size()];
      has_door = has_door || (a == door.a && b == door.b) || (a == door.b && b == door.a);
    }
    EXPECT_TRUE(has_door);
  }
  EXPECT_TRUE(split_polygon(polygon, {}) == std::vector<PolygonWithHoles>{polygon});
}

TEST(SplitPolygon, EndPointsOnEdgesBecomeVerticesAndHolesGoToTheirPart) {
  // A 10 x 4 rectangle with a 1 x 1 hole at x in [7, 8], cut across at x = 5 (end points in the
  // middle of the long edges).
  const PolygonWithHoles polygon{{{0, 0}, {10, 0}, {10, 4}, {0, 4}}, {{{7, 1}, {7, 2}, {8, 2}, {8, 1}}}};
  const std::vector<PolygonWithHoles> parts = split_polygon(polygon, {{{5, 0}, {5, 4}}});
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_DOUBLE_EQ(area_of(parts), 39.0);
  int with_hole = 0;
  for (const PolygonWithHoles& part : parts) {
    if (part.holes.empty()) {
      EXPECT_DOUBLE_EQ(area(part), 20.0);
    } else {
      ++with_hole;
      EXPECT_DOUBLE_EQ(area(part), 19.0);
      EXPECT_LT(signed_area(part.holes[0]), 0.0);
    }
  }
  EXPECT_EQ(with_hole, 1);
  EXPECT_THROW(split_polygon(polygon, {{{5, 0.5}, {5, 4}}}), Error);
}

TEST(SplitPolygon, ManyPartsEachGetTheHolesInsideThem) {
  // A 400 x 30 floor cut into 40 strips 10 wide; a 2 x 2 hole in most strips, at a random height.
  PolygonWithHoles floor{{{0, 0}, {400, 0}, {400, 30}, {0, 30}}, {}};
  std::vector<Segment2> cuts;
  for (int x = 10; x < 400; x += 10) cuts.push_back({{static_cast<double>(x), 0.0}, {static_cast<double>(x), 30.0}});
  std::vector<double> hole_x;
  for (int strip = 0; strip < 40; ++strip) {
    if (strip % 7 == 3) continue;
    const double x = strip * 10 + 1 + strip % 6, y = 2 + (strip * 5) % 25;
    floor.holes.push_back({{x, y}, {x, y + 2}, {x + 2, y + 2}, {x + 2, y}});  // clockwise
    hole_x.push_back(x);
  }
  const std::vector<PolygonWithHoles> parts = split_polygon(floor, cuts);
  ASSERT_EQ(parts.size(), 40u);
  EXPECT_DOUBLE_EQ(area_of(parts), 400.0 * 30.0 - 4.0 * static_cast<double>(hole_x.size()));
  std::size_t holes = 0;
  for (const PolygonWithHoles& part : parts) {
    const Box box = bounding_box(part.outer);
    EXPECT_DOUBLE_EQ(box.x1 - box.x0, 10.0);
    const int expected = std::count_if(hole_x.begin(), hole_x.end(), [&](double x) { return x > box.x0 && x < box.x1; });
    ASSERT_EQ(static_cast<int>(part.holes.size()), expected);
    for (const Ring& hole : part.holes) EXPECT_TRUE(hole[0].x > box.x0 && hole[0].x < box.x1);
    holes += part.holes.size();
  }
  EXPECT_EQ(holes, hole_x.size());
}

TEST(SplitPolygon, AChordBetweenTwoRingsSeparatesOnlyWithAnother) {
  // A 10 x 6 rectangle with a 6 x 2 hole in its middle: a chord from the outline to the hole
  // separates nothing; with a second one on the hole's other side the two halves come apart.
  const PolygonWithHoles polygon{{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {{{2, 2}, {2, 4}, {8, 4}, {8, 2}}}};
  const Segment2 left{{0, 3}, {2, 3}}, right{{8, 3}, {10, 3}};
  EXPECT_TRUE(separating_chords(polygon, {left}).empty());
  const std::vector<PolygonWithHoles> one = split_polygon(polygon, {left});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_DOUBLE_EQ(area(one[0]), 48.0);
  EXPECT_EQ(separating_chords(polygon, {left, right}), (std::vector<Segment2>{left, right}));
  const std::vector<PolygonWithHoles> two = split_polygon(polygon, {left, right});
  ASSERT_EQ(two.size(), 2u);
  for (const PolygonWithHoles& part : two) {
    EXPECT_TRUE(part.holes.empty());
    EXPECT_DOUBLE_EQ(area(part), 24.0);
  }
}

}  // namespace
}  // namespace topocut
