#include "topocut/segmentation/wall_lines.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/segmentation/polygon_split.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;  // 20 units per metre


// An 8 m x 6 m room with a 3.5 m x 4 m room on top, flush with its right wall: one reflex corner, at
// (90, 120), where the wide room's top wall stops.
PolygonWithHoles room_on_a_wider_room() { return {{{0, 0}, {160, 0}, {160, 200}, {90, 200}, {90, 120}, {0, 120}}, {}}; }

DoorOptions with_wall_lines() { return DoorOptions{}; }  // on by default

TEST(WallLines, TheWideRoomsTopWallIsDrawnOnAcrossTheOpening) {
  const std::vector<Segment2> lines = find_wall_line_cuts(room_on_a_wider_room(), kRes, with_wall_lines(), {});
  // The top wall (4.5 m, straight) continued to the right wall; the narrow room's left wall would
  // have to cross 6 m of floor, more than max_wall_line.
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].a, (Point2{90, 120}));
  EXPECT_EQ(lines[0].b, (Point2{160, 120}));
  const std::vector<PolygonWithHoles> parts = split_polygon(room_on_a_wider_room(), lines);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_DOUBLE_EQ(std::min(area(parts[0]), area(parts[1])), 70.0 * 80.0);
  // Off when switched off, and a door already there is not repeated.
  DoorOptions off;
  off.wall_lines = false;
  EXPECT_TRUE(find_wall_line_cuts(room_on_a_wider_room(), kRes, off, {}).empty());
  EXPECT_TRUE(find_wall_line_cuts(room_on_a_wider_room(), kRes, with_wall_lines(), lines).empty());
}

TEST(WallLines, LengthLimitsDecideWhichWallsAreDrawnOn) {
  // The narrow room's left wall continued down crosses 6 m of floor: a line once max_wall_line
  // allows it. A side limit longer than the 3.5 m top-wall line leaves that one out.
  DoorOptions far = with_wall_lines();
  far.max_wall_line = 8.0;
  const std::vector<Segment2> lines = find_wall_line_cuts(room_on_a_wider_room(), kRes, far, {});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_DOUBLE_EQ(std::max(distance(lines[0].a, lines[0].b), distance(lines[1].a, lines[1].b)), 120.0);
  DoorOptions wide_sides = with_wall_lines();
  wide_sides.wall_line_side = 4.0;
  EXPECT_TRUE(find_wall_line_cuts(room_on_a_wider_room(), kRes, wide_sides, {}).empty());
  DoorOptions long_wall = with_wall_lines();
  long_wall.wall_line_wall = 5.0;  // the top wall is 4.5 m
  EXPECT_TRUE(find_wall_line_cuts(room_on_a_wider_room(), kRes, long_wall, {}).empty());
  DoorOptions bad = with_wall_lines();
  bad.wall_line_side = -1.0;
  EXPECT_THROW(find_wall_line_cuts(room_on_a_wider_room(), kRes, bad, {}), Error);
}

TEST(WallLines, ThePartitionsTwoFacesGiveOneLineAcrossTheCorridor) {
  // Two 7 m deep rooms open onto a 3 m corridor, split by a 0.8 m partition (x in [192, 208]): each
  // face continued across the corridor is a wall line, but the strip between them is no room.
  const PolygonWithHoles plan{{{0, 0}, {400, 0}, {400, 200}, {208, 200}, {208, 60}, {192, 60}, {192, 200}, {0, 200}}, {}};
  const std::vector<Segment2> lines = find_wall_line_cuts(plan, kRes, with_wall_lines(), {});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].a.x, lines[0].b.x);
  EXPECT_DOUBLE_EQ(distance(lines[0].a, lines[0].b), 60.0);
  DoorOptions both = with_wall_lines();
  both.wall_line_spacing = 0.0;
  EXPECT_EQ(find_wall_line_cuts(plan, kRes, both, {}).size(), 2u);
}

TEST(WallLines, ShortOrCrookedWallsAndRoomsOfEvenWidthGiveNone) {
  // A rectangle has no reflex corner; a 1.5 m wide desk-sized notch has no wall 2.5 m long.
  const PolygonWithHoles rectangle{{{0, 0}, {400, 0}, {400, 80}, {0, 80}}, {}};
  EXPECT_TRUE(find_wall_line_cuts(rectangle, kRes, with_wall_lines(), {}).empty());
  const PolygonWithHoles notch{{{0, 0}, {160, 0}, {160, 120}, {30, 120}, {30, 100}, {0, 100}}, {}};
  EXPECT_TRUE(find_wall_line_cuts(notch, kRes, with_wall_lines(), {}).empty());
  // The same room, its top wall wavy by 0.5 m: no straight wall to continue.
  const PolygonWithHoles wavy{{{0, 0}, {160, 0}, {160, 200}, {90, 200}, {90, 120}, {60, 130}, {30, 120}, {0, 130}}, {}};
  EXPECT_TRUE(find_wall_line_cuts(wavy, kRes, with_wall_lines(), {}).empty());
  DoorOptions bad = with_wall_lines();
  bad.max_wall_line = -1.0;
  EXPECT_THROW(find_wall_line_cuts(rectangle, kRes, bad, {}), Error);
}
}  // namespace
}  // namespace topocut
