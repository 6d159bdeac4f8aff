#include "topocut/segmentation/door_cuts.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/segmentation/polygon_split.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;  // 20 units per metre

// Two 3 m x 3 m rooms, x in [0, 60] and [64, 124], joined by a 0.9 m door (y in [20, 38])
// through a 0.2 m wall: one outer ring, counter-clockwise.
PolygonWithHoles two_rooms() {
  return {{{0, 0}, {60, 0}, {60, 20}, {64, 20}, {64, 0}, {124, 0}, {124, 60}, {64, 60}, {64, 38}, {60, 38}, {60, 60},
           {0, 60}},
          {}};
}

double total_area(const std::vector<PolygonWithHoles>& parts) {
  double sum = 0.0;
  for (const PolygonWithHoles& p : parts) sum += area(p);
  return sum;
}

TEST(DoorCuts, ADoorBetweenTwoRoomsIsFoundOnce) {
  const std::vector<Segment2> doors = find_door_cuts(two_rooms(), kRes);
  ASSERT_EQ(doors.size(), 1u);
  // Jamb to jamb across the opening, on one face of the wall: 18 units = 0.9 m, vertical.
  EXPECT_DOUBLE_EQ(distance(doors[0].a, doors[0].b), 18.0);
  EXPECT_EQ(doors[0].a.x, doors[0].b.x);
  EXPECT_TRUE(doors[0].a.x == 60 || doors[0].a.x == 64);
}

TEST(DoorCuts, CorridorsAndRoomsWithoutDoorsHaveNone) {
  // A straight corridor, and an L-shaped corridor: its inner corner is reflex, but every cut that
  // resolves it is as wide as the corridor on both sides.
  const PolygonWithHoles straight{{{0, 0}, {200, 0}, {200, 36}, {0, 36}}, {}};
  const PolygonWithHoles l_shape{{{0, 0}, {200, 0}, {200, 36}, {36, 36}, {36, 200}, {0, 200}}, {}};
  EXPECT_TRUE(find_door_cuts(straight, kRes).empty());
  EXPECT_TRUE(find_door_cuts(l_shape, kRes).empty());
}

TEST(DoorCuts, ARoomOpeningOntoACorridorIsADoorAndTooWideAnOpeningIsNot) {
  // A 4 m x 4 m room above a 2 m wide, 10 m long corridor, joined by an opening of width w in the
  // 0.2 m wall between them (x from 80 - w/2 to 80 + w/2 in units).
  auto plan = [](double w) {
    const double a = 80 - w / 2, b = 80 + w / 2;
    return PolygonWithHoles{{{0, 0}, {200, 0}, {200, 40}, {b, 40}, {b, 44}, {120, 44}, {120, 124}, {40, 124},
                             {40, 44}, {a, 44}, {a, 40}, {0, 40}},
                            {}};
  };
  DoorOptions passages_only;
  passages_only.extend_walls = false;
  EXPECT_EQ(find_door_cuts(plan(18), kRes, passages_only).size(), 1u);
  // A 1.9 m opening: the corridor side is 10 m long and the room 4 m wide, both wider than
  // 1.9 / 0.6 m: still a door, unless doors may be at most 1.5 m wide.
  EXPECT_EQ(find_door_cuts(plan(38), kRes, passages_only).size(), 1u);
  DoorOptions narrow = passages_only;
  narrow.max_width = 1.5;
  EXPECT_TRUE(find_door_cuts(plan(38), kRes, narrow).empty());
  // Open across almost the whole room (3.8 m of 4 m): not a door; the 0.1 m wall stubs left are
  // too short to give a wall direction.
  EXPECT_TRUE(find_door_cuts(plan(76), kRes).empty());
}

TEST(DoorCuts, AThinWallIsExtendedAcrossAnOpeningAndFurnitureIsNot) {
  // A 5 m x 5 m room (100 units) with something standing on its bottom wall at x in [40, 44]
  // (a 0.2 m partition) or [30, 50] (a 1 m cupboard), 2.5 m tall into the room.
  auto room = [](double x0, double x1) {
    return PolygonWithHoles{{{0, 0}, {x0, 0}, {x0, 50}, {x1, 50}, {x1, 0}, {100, 0}, {100, 100}, {0, 100}}, {}};
  };
  const std::vector<Segment2> partition = find_door_cuts(room(40, 44), kRes);
  ASSERT_EQ(partition.size(), 1u);
  // From the partition's end straight up to the top wall: 2.5 m.
  EXPECT_DOUBLE_EQ(distance(partition[0].a, partition[0].b), 50.0);
  EXPECT_EQ(partition[0].a.x, partition[0].b.x);
  EXPECT_EQ(split_polygon(room(40, 44), partition).size(), 2u);
  EXPECT_TRUE(find_door_cuts(room(30, 50), kRes).empty());
  DoorOptions off;
  off.extend_walls = false;
  EXPECT_TRUE(find_door_cuts(room(40, 44), kRes, off).empty());
  off = {};
  off.max_gap = 2.0;  // the opening to the top wall is wider
  EXPECT_TRUE(find_door_cuts(room(40, 44), kRes, off).empty());
}

// The room of the test above with a partition standing on its bottom wall whose left face is one
// straight 2.5 m wall and whose right face is jagged (0.25 m steps, each shorter than
// min_wall_length, 0.1-0.15 m thick): only the straight face gives the wall's end a direction.
// mirrored: the same room reflected in x = 50, its ring reversed to stay counter-clockwise.
PolygonWithHoles jagged_partition(bool mirrored) {
  Ring ring{{0, 0}, {40, 0}, {40, 50}, {43, 50}};
  for (int y = 45; y > 0; y -= 5) ring.push_back({y % 10 == 0 ? 42.0 : 43.0, static_cast<double>(y)});
  for (const Point2 p : {Point2{43, 0}, Point2{100, 0}, Point2{100, 100}, Point2{0, 100}}) ring.push_back(p);
  if (mirrored) {
    for (Point2& p : ring) p.x = 100 - p.x;
    std::reverse(ring.begin(), ring.end());
  }
  return {ring, {}};
}

TEST(DoorCuts, AWallEndIsFoundFromEitherFaceAlike) {
  // In the plain room the straight face arrives at the end corner (the corner's p side); mirrored,
  // it leaves it (its q side). Both must give the opening up to the top wall: the end's thickness
  // is probed behind the end whichever side of the corner the wall lies on.
  for (const bool mirrored : {false, true}) {
    SCOPED_TRACE(mirrored ? "mirrored" : "plain");
    const PolygonWithHoles room = jagged_partition(mirrored);
    const std::vector<Segment2> cuts = find_door_cuts(room, kRes);
    ASSERT_EQ(cuts.size(), 1u);
    EXPECT_DOUBLE_EQ(distance(cuts[0].a, cuts[0].b), 50.0);
    EXPECT_EQ(cuts[0].a.x, cuts[0].b.x);
    EXPECT_DOUBLE_EQ(cuts[0].a.x, mirrored ? 60.0 : 40.0);
    EXPECT_EQ(split_polygon(room, cuts).size(), 2u);
  }
}

TEST(DoorCuts, AWallThickerThanAPartitionIsNotExtended) {
  // The same room with a 0.35 m thick wall stub (a pillar or a cupboard side, thicker than an
  // interior partition of 0.1-0.2 m): no opening, unless walls that thick may be extended.
  const PolygonWithHoles room{{{0, 0}, {40, 0}, {40, 50}, {47, 50}, {47, 0}, {100, 0}, {100, 100}, {0, 100}}, {}};
  EXPECT_TRUE(find_door_cuts(room, kRes).empty());
  DoorOptions thick;
  thick.max_wall_thickness = 0.4;
  // (one from each face: 0.35 m apart, further than two cuts count as one, which is why the
  // default limit stays below that)
  EXPECT_EQ(find_door_cuts(room, kRes, thick).size(), 2u);
  DoorOptions bad;
  bad.wall_end_probe = 0.0;
  EXPECT_THROW(find_door_cuts(room, kRes, bad), Error);
}

TEST(DoorCuts, DisabledAndBadOptions) {
  DoorOptions off;
  off.enabled = false;
  EXPECT_TRUE(find_door_cuts(two_rooms(), kRes, off).empty());
  DoorOptions bad;
  bad.door_ratio = 0.0;
  EXPECT_THROW(find_door_cuts(two_rooms(), kRes, bad), Error);
  EXPECT_THROW(find_door_cuts(two_rooms(), -1.0), Error);
}

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
