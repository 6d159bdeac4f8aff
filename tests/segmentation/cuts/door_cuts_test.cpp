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
  // Each rule has its own switch: the passages off leaves the wall openings, both off leave nothing.
  DoorOptions off;
  off.passages = false;
  EXPECT_TRUE(find_passage_cuts(two_rooms(), kRes, off).empty());
  EXPECT_FALSE(find_passage_cuts(two_rooms(), kRes).empty());
  off.extend_walls = false;
  EXPECT_TRUE(find_door_cuts(two_rooms(), kRes, off).empty());
  DoorOptions bad;
  bad.door_like.ratio = 0.0;
  EXPECT_THROW(find_door_cuts(two_rooms(), kRes, bad), Error);
  EXPECT_THROW(find_door_cuts(two_rooms(), -1.0), Error);
}

// validate() holds each field to its row's range (door_option_rows()), the range the front ends check:
// a value no row takes (a negative length, ratio or angle) is refused naming the row's option.
TEST(DoorOptions, ValidateHoldsEveryFieldToItsRowsRange) {
  EXPECT_NO_THROW(validate(DoorOptions{}));
  for (const OptionRow<DoorOptions>& row : door_option_rows()) {
    DoorOptions options;
    row.set(options, -1.0);
    try {
      validate(options);
      ADD_FAILURE() << row.name << " took -1";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("--" + row.name + " must"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace topocut
