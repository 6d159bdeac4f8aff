#include "topocut/segmentation/island_cuts.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/segmentation/polygon_split.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;  // 20 units per metre

double total_area(const std::vector<PolygonWithHoles>& parts) {
  double sum = 0.0;
  for (const PolygonWithHoles& p : parts) sum += area(p);
  return sum;
}

// A 10 m x 6 m floor: a corridor below (y < 40) and two rooms above, split by a partition (x in
// [98, 102]) that stops 0.2 m short of the top wall; the wall between rooms and corridor (y in
// [40, 44]) stops 1 m short of both side walls. Partition and wall are one T-shaped hole, 0.2 m
// thick and 8 m long: a wall island. Its three gaps are the doors of the rooms.
PolygonWithHoles rooms_behind_a_wall_island() {
  return {{{0, 0}, {200, 0}, {200, 120}, {0, 120}},
          {{{20, 40}, {20, 44}, {98, 44}, {98, 116}, {102, 116}, {102, 44}, {180, 44}, {180, 40}}}};
}

bool joins_outline_and_hole(const PolygonWithHoles& polygon, const Segment2& s) {
  auto on = [](const Ring& ring, const Point2& p) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      if (distance_to_segment(p, {ring[i], ring[(i + 1) % ring.size()]}) < 1e-9) return true;
    return false;
  };
  return (on(polygon.outer, s.a) && on(polygon.holes[0], s.b)) || (on(polygon.outer, s.b) && on(polygon.holes[0], s.a));
}

TEST(IslandCuts, TheGapsAroundAWallIslandCloseOffEachRoom) {
  const PolygonWithHoles polygon = rooms_behind_a_wall_island();
  EXPECT_TRUE(find_door_cuts(polygon, kRes).empty());  // every gap leads to another ring
  const std::vector<Segment2> cuts = find_island_cuts(polygon, kRes, DoorOptions{}, {});
  ASSERT_EQ(cuts.size(), 3u);
  std::vector<double> widths;
  for (const Segment2& c : cuts) {
    EXPECT_TRUE(joins_outline_and_hole(polygon, c));
    widths.push_back(distance(c.a, c.b));
  }
  std::sort(widths.begin(), widths.end());
  EXPECT_EQ(widths, (std::vector<double>{4.0, 20.0, 20.0}));  // the partition's gap, both doors
  // Corridor and the two rooms, tiling the floor.
  const std::vector<PolygonWithHoles> parts = split_polygon(polygon, cuts);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_DOUBLE_EQ(total_area(parts), area(polygon));
  std::vector<double> areas;
  for (const PolygonWithHoles& part : parts) {
    EXPECT_TRUE(part.holes.empty());
    areas.push_back(area(part));
  }
  std::sort(areas.begin(), areas.end());
  // Corridor y < 40; each room 98 x 76 above the wall plus its 20 x 4 doorway; the 4 x 4 gap above
  // the partition goes to one of them.
  EXPECT_DOUBLE_EQ(areas[0], 98.0 * 76.0 + 20.0 * 4.0);
  EXPECT_DOUBLE_EQ(areas[1], 98.0 * 76.0 + 20.0 * 4.0 + 4.0 * 4.0);
  EXPECT_DOUBLE_EQ(areas[2], 200.0 * 40.0);
}

TEST(IslandCuts, ACutToAnIslandAloneSeparatesNothing) {
  const PolygonWithHoles polygon = rooms_behind_a_wall_island();
  const Segment2 left_door{{0, 40}, {20, 40}};
  EXPECT_TRUE(separating_chords(polygon, {left_door}).empty());
  const std::vector<PolygonWithHoles> parts = split_polygon(polygon, {left_door});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_DOUBLE_EQ(area(parts[0]), area(polygon));
  EXPECT_EQ(parts[0].holes.size(), 1u);
  // With the other door the corridor is closed off; the top gap stays open between the rooms.
  const Segment2 right_door{{180, 40}, {200, 40}};
  EXPECT_EQ(separating_chords(polygon, {left_door, right_door}).size(), 2u);
  EXPECT_EQ(split_polygon(polygon, {left_door, right_door}).size(), 2u);
}

TEST(IslandCuts, FurnitureShortPartitionsAndTheSwitchGiveNone) {
  DoorOptions off;
  off.island_cuts = false;
  EXPECT_TRUE(find_island_cuts(rooms_behind_a_wall_island(), kRes, off, {}).empty());
  // A solid 2 m x 1 m table 1 m from each of a room's walls: thick, so furniture.
  const PolygonWithHoles table{{{0, 0}, {80, 0}, {80, 60}, {0, 60}}, {{{20, 20}, {20, 40}, {60, 40}, {60, 20}}}};
  EXPECT_TRUE(find_island_cuts(table, kRes, DoorOptions{}, {}).empty());
  // A 0.2 m thin partition 2 m long standing free: no longer than furniture.
  const PolygonWithHoles partition{{{0, 0}, {80, 0}, {80, 60}, {0, 60}}, {{{20, 28}, {20, 32}, {60, 32}, {60, 28}}}};
  EXPECT_TRUE(find_island_cuts(partition, kRes, DoorOptions{}, {}).empty());
  DoorOptions bad;
  bad.max_island_thickness = 0.0;
  EXPECT_THROW(find_island_cuts(rooms_behind_a_wall_island(), kRes, bad, {}), Error);
}

}  // namespace
}  // namespace topocut
