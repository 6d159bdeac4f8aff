#include "topocut/segmentation/room_merging.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "topocut/core/error.h"

namespace topocut {
namespace {

// Grid coordinates, one unit per cell; at 0.05 m per cell 20 units are a metre.
constexpr double kRes = 0.05;

PolygonWithHoles box(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

FreeSpaceComponent no_component() { return {}; }

// The hand rules (door ratio, width steps, furniture), which these tests work through by hand.
RoomMergeOptions hand_rules() {
  RoomMergeOptions options;
  options.learned = false;
  return options;
}

// The learned criterion with a model that answers p = 1 / (1 + exp(-bias)) to every merge.
RoomMergeOptions constant_model(double bias) {
  RoomMergeOptions options;
  options.model = parse_merge_model("topocut-merge-model 1\nthreshold 0.5\nbias " + std::to_string(bias) + "\n");
  return options;
}

bool has_edge(const Ring& ring, const Point2& a, const Point2& b) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point2& p = ring[i];
    const Point2& q = ring[(i + 1) % ring.size()];
    if ((p == a && q == b) || (p == b && q == a)) return true;
  }
  return false;
}

TEST(UnionOfPieces, TwoSquaresSharingAnEdgeGiveTheRectangle) {
  const PolygonWithHoles u = union_of_pieces({box(0, 0, 10, 10), box(10, 0, 20, 10)});
  EXPECT_TRUE(u.holes.empty());
  EXPECT_DOUBLE_EQ(signed_area(u.outer), 200.0);
  // The shared edge is gone; its end points stay (the boundary goes straight on through them).
  EXPECT_FALSE(has_edge(u.outer, {10, 0}, {10, 10}));
  EXPECT_EQ(u.outer.size(), 6u);
}

TEST(UnionOfPieces, PiecesAroundAnObstacleGiveAPolygonWithAHole) {
  // Four pieces framing the square [10, 20]²: the union is the big square minus the small one.
  const std::vector<PolygonWithHoles> pieces{
      {{{0, 0}, {30, 0}, {30, 10}, {20, 10}, {10, 10}, {0, 10}}, {}},
      {{{20, 10}, {30, 10}, {30, 20}, {20, 20}}, {}},
      {{{0, 20}, {10, 20}, {20, 20}, {30, 20}, {30, 30}, {0, 30}}, {}},
      {{{0, 10}, {10, 10}, {10, 20}, {0, 20}}, {}}};
  const PolygonWithHoles u = union_of_pieces(pieces);
  ASSERT_EQ(u.holes.size(), 1u);
  EXPECT_GT(signed_area(u.outer), 0.0);
  EXPECT_LT(signed_area(u.holes[0]), 0.0);
  EXPECT_DOUBLE_EQ(area(u), 900.0 - 100.0);
}

TEST(UnionOfPieces, DisjointPiecesAreAnError) {
  EXPECT_THROW(union_of_pieces({box(0, 0, 10, 10), box(20, 0, 30, 10)}), Error);
}

TEST(MergeRooms, AnOpeningAsWideAsTheRoomIsNoDoor) {
  // An L-shaped room cut at its inner corner: the cut is exactly as wide as the narrower side.
  PieceSet set;
  set.pieces = {box(0, 0, 60, 40), box(60, 0, 100, 40), box(60, 40, 100, 100)};
  set.cuts = {{{60, 0}, {60, 40}}, {{60, 40}, {100, 40}}};
  const PieceSet rooms = merge_rooms(no_component(), set, cv::Mat(), kRes, hand_rules());
  ASSERT_EQ(rooms.pieces.size(), 1u);
  EXPECT_TRUE(rooms.cuts.empty());
  EXPECT_DOUBLE_EQ(area(rooms.pieces[0]), 60 * 40 + 40 * 40 + 40 * 60);
  EXPECT_TRUE(rooms.pieces[0].holes.empty());
  // Merged rooms keep no internal passage: no vertex of the union lies on a removed cut's inside.
  for (const Point2& v : rooms.pieces[0].outer) EXPECT_FALSE(v.x == 60 && v.y > 0 && v.y < 40);
}

TEST(MergeRooms, ADoorBetweenTwoRoomsKeepsThemApart) {
  // Two 3 m rooms joined by a 0.9 m door through a 0.2 m wall. The door's own frame is a sliver
  // piece; it is folded into a room, and the door stays a passage.
  // Pieces meet along whole edges, so the rooms carry the door's end points as vertices.
  PieceSet set;
  set.pieces = {{{{0, 0}, {60, 0}, {60, 20}, {60, 38}, {60, 60}, {0, 60}}, {}},
                box(60, 20, 64, 38),
                {{{64, 0}, {124, 0}, {124, 60}, {64, 60}, {64, 38}, {64, 20}}, {}}};
  set.cuts = {{{60, 20}, {60, 38}}, {{64, 38}, {64, 20}}};
  const PieceSet rooms = merge_rooms(no_component(), set, cv::Mat(), kRes, hand_rules());
  ASSERT_EQ(rooms.pieces.size(), 2u);
  ASSERT_EQ(rooms.cuts.size(), 1u);
  EXPECT_NEAR(distance(rooms.cuts[0].a, rooms.cuts[0].b) * kRes, 0.9, 1e-12);
  const double a0 = area(rooms.pieces[0]), a1 = area(rooms.pieces[1]);
  EXPECT_DOUBLE_EQ(a0 + a1, 3600 + 72 + 3600);
  EXPECT_DOUBLE_EQ(std::min(a0, a1), 3600.0);
  // The remaining cut is an edge of both rooms.
  EXPECT_TRUE(has_edge(rooms.pieces[0].outer, rooms.cuts[0].a, rooms.cuts[0].b));
  EXPECT_TRUE(has_edge(rooms.pieces[1].outer, rooms.cuts[0].a, rooms.cuts[0].b));
}

TEST(MergeRooms, AKnownDoorIsNeverMergedAsAWideOpening) {
  PieceSet set;
  set.pieces = {box(0, 0, 60, 40), box(60, 0, 100, 40)};
  set.cuts = {{{60, 0}, {60, 40}}};
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, hand_rules()).pieces.size(), 1u);
  set.rules = {CutRule::kDoor};
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, hand_rules()).pieces.size(), 2u);
}

TEST(MergeRooms, ASliverIsFoldedIntoTheNeighbourWithTheLongestCut) {
  // A small strip between two large rooms; it shares 3 m with the left room, 1 m with the right.
  PieceSet set;
  set.pieces = {{{{0, 0}, {80, 0}, {80, 60}, {80, 100}, {0, 100}}, {}},
                {{{80, 60}, {80, 0}, {100, 0}, {100, 20}}, {}},
                {{{100, 0}, {200, 0}, {200, 100}, {100, 100}, {100, 20}}, {}}};
  // Left/strip cut 60 units (3 m), strip/right cut 20 units (1 m). The strip is a trapezoid of
  // (60 + 20) / 2 * 20 = 800 units² = 2 m².
  set.cuts = {{{80, 0}, {80, 60}}, {{100, 20}, {100, 0}}};
  RoomMergeOptions options = hand_rules();
  options.door_like.ratio = 10.0;  // no cut is wide enough to merge as "not a door"
  options.min_room_area = 3.0;    // m²: the strip is too small to be a room
  const PieceSet rooms = merge_rooms(no_component(), set, cv::Mat(), kRes, options);
  ASSERT_EQ(rooms.pieces.size(), 2u);
  EXPECT_DOUBLE_EQ(area(rooms.pieces[0]), 80 * 100 + area(set.pieces[1]));
  ASSERT_EQ(rooms.cuts.size(), 1u);
  EXPECT_EQ(rooms.cuts[0], set.cuts[1]);
}

TEST(MergeRooms, SmallRoomsFoldSmallestFirstAndAreAskedAgainOnceGrown) {
  // A 1 m² room beside a 2 m² one beside a large room; the 2 m² room shares 2 m with the large one
  // and 1 m with the small one. Smallest first: the 1 m² room folds into the 2 m², which at 3 m² is
  // a room. The 2 m² first would fold into the large room (its longest cut) and take the small one.
  PieceSet set;
  set.pieces = {box(0, 0, 20, 20), {{{20, 0}, {40, 0}, {40, 40}, {20, 40}, {20, 20}}, {}},
                {{{40, 0}, {200, 0}, {200, 100}, {40, 100}, {40, 40}}, {}}};
  set.cuts = {{{20, 0}, {20, 20}}, {{40, 0}, {40, 40}}};
  RoomMergeOptions options = hand_rules();
  options.door_like.ratio = 10.0;  // nothing merges as "not a door"
  options.min_room_thickness = 0.0;
  options.min_room_area = 2.5;  // m²: both small rooms alone, not the two together
  const PieceSet rooms = merge_rooms(no_component(), set, cv::Mat(), kRes, options);
  ASSERT_EQ(rooms.pieces.size(), 2u);
  std::vector<double> areas{area(rooms.pieces[0]), area(rooms.pieces[1])};
  std::sort(areas.begin(), areas.end());
  EXPECT_DOUBLE_EQ(areas[0], 20 * 20 + 20 * 40);
  EXPECT_DOUBLE_EQ(areas[1], 160 * 100);
  ASSERT_EQ(rooms.cuts.size(), 1u);
  EXPECT_EQ(rooms.cuts[0], set.cuts[1]);
}

TEST(MergeRooms, AThinStripIsFoldedWhenAMinimumWidthIsSet) {
  // A 0.3 m x 6 m strip (1.8 m², above the area limit) sticking out of a 6 m x 4 m room, cut off
  // at its root (a laser leak through a gap); door_like.ratio is set so high that nothing merges as
  // "not a door".
  PieceSet set;
  set.pieces = {{{{0, 0}, {120, 0}, {120, 80}, {56, 80}, {50, 80}, {0, 80}}, {}}, box(50, 80, 56, 200)};
  set.cuts = {{{56, 80}, {50, 80}}};
  RoomMergeOptions options = hand_rules();
  options.door_like.ratio = 10.0;
  options.min_room_thickness = 0.0;
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 2u);
  options.min_room_width = 0.5;  // the strip's widest chord parallel to its cut is 0.3 m
  const PieceSet rooms = merge_rooms(no_component(), set, cv::Mat(), kRes, options);
  ASSERT_EQ(rooms.pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(area(rooms.pieces[0]), 120 * 80 + 6 * 120);
  EXPECT_TRUE(rooms.cuts.empty());
}

TEST(MergeRooms, DisabledReturnsThePiecesAndBadOptionsAreErrors) {
  PieceSet set;
  set.pieces = {box(0, 0, 60, 40), box(60, 0, 100, 40)};
  set.cuts = {{{60, 0}, {60, 40}}};
  RoomMergeOptions off;
  off.enabled = false;
  const PieceSet same = merge_rooms(no_component(), set, cv::Mat(), kRes, off);
  EXPECT_EQ(same.pieces, set.pieces);
  EXPECT_EQ(same.cuts, set.cuts);
  RoomMergeOptions bad;
  bad.door_like.ratio = 0.0;
  EXPECT_THROW(merge_rooms(no_component(), set, cv::Mat(), kRes, bad), Error);
  bad = {};
  bad.min_room_area = -1.0;
  EXPECT_THROW(merge_rooms(no_component(), set, cv::Mat(), kRes, bad), Error);
  EXPECT_THROW(merge_rooms(no_component(), set, cv::Mat(), 0.0), Error);
}

}  // namespace
}  // namespace topocut

namespace topocut {
namespace {

TEST(MergeRooms, ASliverThinnerThanAPersonIsFolded) {
  // A 6 m x 4 m room and a 0.4 m x 4 m strip along its side (1.6 m², above the area limit):
  // thickness 2 * 1.6 / 8.8 = 0.36 m. Nothing merges as "not a door" (door_like.ratio 10).
  PieceSet set;
  set.pieces = {box(0, 0, 120, 80), box(120, 0, 128, 80)};
  set.cuts = {{{120, 0}, {120, 80}}};
  RoomMergeOptions options = hand_rules();
  options.door_like.ratio = 10.0;
  options.min_room_thickness = 0.0;
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 2u);
  options.min_room_thickness = 0.35;  // just below the strip's 0.36 m
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 2u);
  options.min_room_thickness = 0.6;  // the default
  const PieceSet rooms = merge_rooms(no_component(), set, cv::Mat(), kRes, options);
  ASSERT_EQ(rooms.pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(area(rooms.pieces[0]), 128 * 80);
}

// A 10 m x 5 m room with an obstacle of side cells in its middle, cut by DuDe into four pieces whose
// cuts all end on the obstacle's corners.
PieceSet around_obstacle(int side, FreeSpaceComponent& component) {
  const double x0 = 100 - side / 2, x1 = 100 + side / 2, y0 = 50 - side / 2, y1 = 50 + side / 2;
  component.polygon.outer = {{0, 0}, {200, 0}, {200, 100}, {0, 100}};
  component.polygon.holes = {{{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}}};  // clockwise
  PieceSet set;
  set.pieces = {{{{0, 0}, {x0, 0}, {x0, y0}, {x0, y1}, {x0, 100}, {0, 100}}, {}},
                {{{x1, 0}, {200, 0}, {200, 100}, {x1, 100}, {x1, y1}, {x1, y0}}, {}},
                {{{x0, 0}, {x1, 0}, {x1, y0}, {x0, y0}}, {}},
                {{{x0, y1}, {x1, y1}, {x1, 100}, {x0, 100}}, {}}};
  set.cuts = {{{x0, 0}, {x0, y0}}, {{x0, y1}, {x0, 100}}, {{x1, y0}, {x1, 0}}, {{x1, 100}, {x1, y1}}};
  return set;
}

TEST(MergeRooms, CutsEndingOnFurnitureSeparateNoRooms) {
  RoomMergeOptions options = hand_rules();
  options.door_like.ratio = 10.0;  // no cut merges as "not a door": only the furniture rule can merge
  FreeSpaceComponent table;
  const PieceSet set = around_obstacle(20, table);  // a 1 m table
  EXPECT_EQ(merge_rooms(table, set, cv::Mat(), kRes, options).pieces.size(), 1u);
  options.furniture_size = 0.0;
  EXPECT_EQ(merge_rooms(table, set, cv::Mat(), kRes, options).pieces.size(), 4u);
  options.furniture_size = 2.5;
  FreeSpaceComponent core;
  const PieceSet big = around_obstacle(60, core);  // a 3 m block is no furniture
  EXPECT_EQ(merge_rooms(core, big, cv::Mat(), kRes, options).pieces.size(), 4u);
}

TEST(MergeRooms, ARoomOpeningOntoAMuchWiderDeepSpaceStaysApart) {
  // A 4 m x 4 m room open across its whole width onto a 12 m wide room below: widths 4 and 12 m
  // (0.33 < 0.6), areas 16 and 96 m², the wide side 8 m deep behind the cut.
  PieceSet set;
  set.pieces = {{{{0, 0}, {240, 0}, {240, 160}, {160, 160}, {80, 160}, {0, 160}}, {}}, box(80, 160, 160, 240)};
  set.cuts = {{{80, 160}, {160, 160}}};
  RoomMergeOptions options = hand_rules();
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 2u);
  options.step_ratio = 0.0;  // the cut spans the narrow room: not door-like, merged
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 1u);
  // Onto a 3 m deep corridor instead: the corridor takes the room in.
  PieceSet corridor;
  corridor.pieces = {{{{0, 100}, {240, 100}, {240, 160}, {160, 160}, {80, 160}, {0, 160}}, {}}, box(80, 160, 160, 240)};
  corridor.cuts = set.cuts;
  EXPECT_EQ(merge_rooms(no_component(), corridor, cv::Mat(), kRes, hand_rules()).pieces.size(), 1u);
  // A 2 m x 4 m room onto a 12 m wide hall only 3 m deep: merged across a DuDe cut (3 < 5 m), kept
  // apart across a wall line (the hall reaches 3 m behind it, more than 1.25 x 2 m), and the line
  // stays listed as one.
  PieceSet hall;
  hall.pieces = {{{{0, 100}, {240, 100}, {240, 160}, {120, 160}, {80, 160}, {0, 160}}, {}}, box(80, 160, 120, 240)};
  hall.cuts = {{{80, 160}, {120, 160}}};
  EXPECT_EQ(merge_rooms(no_component(), hall, cv::Mat(), kRes, hand_rules()).pieces.size(), 1u);
  hall.rules = {CutRule::kWallLine};
  const PieceSet kept = merge_rooms(no_component(), hall, cv::Mat(), kRes, hand_rules());
  EXPECT_EQ(kept.pieces.size(), 2u);
  EXPECT_EQ(kept.cuts, hall.cuts);
  EXPECT_EQ(kept.rules, std::vector<CutRule>{CutRule::kWallLine});
  // The 4 m room onto the 3 m corridor still merges across a wall line: 3 < 1.25 x 4 m.
  corridor.rules = {CutRule::kWallLine};
  EXPECT_EQ(merge_rooms(no_component(), corridor, cv::Mat(), kRes, hand_rules()).pieces.size(), 1u);
}

TEST(MergeRooms, TheLearnedCriterionMergesWhereTheModelSaysOneRoom) {
  PieceSet set;
  set.pieces = {box(0, 0, 60, 40), box(60, 0, 100, 40)};
  set.cuts = {{{60, 0}, {60, 40}}};
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, constant_model(5.0)).pieces.size(), 1u);
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, constant_model(-5.0)).pieces.size(), 2u);
  // The model alone decides: no hand rule merges a table's cuts behind its back.
  FreeSpaceComponent table;
  EXPECT_EQ(merge_rooms(table, around_obstacle(20, table), cv::Mat(), kRes, constant_model(-10.0)).pieces.size(), 4u);
  EXPECT_EQ(merge_rooms(table, around_obstacle(20, table), cv::Mat(), kRes, constant_model(10.0)).pieces.size(), 1u);
}

TEST(MergeRooms, AThinClosetIsTheModelsToKeepAndSliversBelowTheFoldAreaFold) {
  // A 0.5 m x 2 m closet (1 m², 0.4 m thick) beside a 4 m x 2 m room: the hand rules fold it as thinner
  // than a person, the learned criterion keeps what its model keeps; a 0.4 m² sliver folds either way.
  PieceSet set;
  set.pieces = {box(0, 0, 80, 40), box(80, 0, 90, 40)};
  set.cuts = {{{80, 0}, {80, 40}}};
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, constant_model(-10.0)).pieces.size(), 2u);
  RoomMergeOptions hand = hand_rules();
  hand.door_like.ratio = 10.0;  // nothing merges as "not a door": only the fold can join them
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, hand).pieces.size(), 1u);
  set.pieces[1] = box(80, 0, 84, 40);  // 0.2 m x 2 m = 0.4 m²
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, constant_model(-10.0)).pieces.size(), 1u);
}

TEST(MergeRooms, ASliverThinnerThanHalfAPersonFoldsWhateverTheModel) {
  // A 0.25 m x 5 m sliver (1.25 m², above the fold area) beside a 4 m x 5 m room, thickness
  // 2 * 1.25 / 10.5 = 0.24 m: the learned criterion with a model sure of two rooms still folds it (the
  // closet of the test above, 0.4 m thick, stays); --sliver-thickness 0 keeps it.
  PieceSet set;
  set.pieces = {box(0, 0, 80, 100), box(80, 0, 85, 100)};
  set.cuts = {{{80, 0}, {80, 100}}};
  RoomMergeOptions options = constant_model(-10.0);
  const PieceSet rooms = merge_rooms(no_component(), set, cv::Mat(), kRes, options);
  ASSERT_EQ(rooms.pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(area(rooms.pieces[0]), 85 * 100);
  options.sliver_thickness = 0.0;
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 2u);
  options.sliver_thickness = 0.2;  // below the sliver's 0.24 m
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 2u);
}

TEST(MergeRooms, ACorridorContinuedIsOneRoomWhateverTheModel) {
  // A corridor 2 m wide bent at a right angle, legs 10 m and 8 m beyond the corner, cut at the corner
  // across its width (as a wall line does): one room even where the model says two.
  PieceSet bent;
  bent.pieces = {{{{0, 0}, {200, 0}, {200, 40}, {40, 40}, {0, 40}}, {}}, box(0, 40, 40, 200)};
  bent.cuts = {{{0, 40}, {40, 40}}};
  bent.rules = {CutRule::kWallLine};
  EXPECT_EQ(merge_rooms(no_component(), bent, cv::Mat(), kRes, constant_model(-10.0)).pieces.size(), 1u);
  // Through a door it stays two (a door is a boundary people draw), and a 4 m x 4 m room at the
  // corridor's end is no strip: the model decides.
  bent.rules = {CutRule::kDoor};
  EXPECT_EQ(merge_rooms(no_component(), bent, cv::Mat(), kRes, constant_model(-10.0)).pieces.size(), 2u);
  PieceSet room;
  room.pieces = {box(0, 0, 200, 40), {{{200, -20}, {280, -20}, {280, 60}, {200, 60}, {200, 40}, {200, 0}}, {}}};
  room.cuts = {{{200, 0}, {200, 40}}};
  EXPECT_EQ(merge_rooms(no_component(), room, cv::Mat(), kRes, constant_model(-10.0)).pieces.size(), 2u);
  EXPECT_EQ(merge_rooms(no_component(), room, cv::Mat(), kRes, constant_model(10.0)).pieces.size(), 1u);
}

}  // namespace
}  // namespace topocut

namespace topocut {
namespace {

// The learned criterion with a model that answers p to every merge (below 0.5: it keeps every cut).
RoomMergeOptions model_answering(double p) {
  RoomMergeOptions options;
  options.model = parse_merge_model("topocut-merge-model 1\nthreshold 0.5\nbias " + std::to_string(std::log(p / (1.0 - p))) + "\n");
  return options;
}

// A 10 m x 8 m room and a 4 m x 1.5 m strip along its top edge, cut off across the strip's whole
// length (a strip cut off along a wall line): 6 m² beside 80 m², the cut 4 of its 11 m of outline.
PieceSet strip_beside_room(CutRule rule) {
  PieceSet set;
  set.pieces = {{{{0, 0}, {200, 0}, {200, 160}, {140, 160}, {60, 160}, {0, 160}}, {}}, box(60, 160, 140, 190)};
  set.add_cut({{60, 160}, {140, 160}}, rule);
  return set;
}

TEST(MergeRooms, ABayCutOffALargerRoomAlongMuchOfItsOutlineJoinsItWhereTheModelLeansThatWay) {
  const PieceSet set = strip_beside_room(CutRule::kWallLine);
  RoomMergeOptions options = model_answering(0.45);  // below the threshold: the merge keeps the cut
  const PieceSet rooms = merge_rooms(no_component(), set, cv::Mat(), kRes, options);
  ASSERT_EQ(rooms.pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(area(rooms.pieces[0]), 200 * 160 + 80 * 30);
  EXPECT_TRUE(rooms.cuts.empty());
  options.bay_share = 0.0;  // --no-bays
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 2u);
  // The model sure of two rooms (a room beside a hall in a drawn plan): the bay stays.
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, model_answering(0.2)).pieces.size(), 2u);
  // A door, or a room's open front, stays a boundary.
  EXPECT_EQ(merge_rooms(no_component(), strip_beside_room(CutRule::kDoor), cv::Mat(), kRes, model_answering(0.45)).pieces.size(), 2u);
  EXPECT_EQ(merge_rooms(no_component(), strip_beside_room(CutRule::kWallOpening), cv::Mat(), kRes, model_answering(0.45)).pieces.size(), 2u);
  // A cut at most a fifth of the room's outline (4 of 11 m: 0.36), or a room not much smaller (6 of
  // 80 m²: 0.075), is no bay.
  options = model_answering(0.45);
  options.bay_share = 0.4;
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 2u);
  options = model_answering(0.45);
  options.bay_area_ratio = 0.07;
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, options).pieces.size(), 2u);
  // Hand rules: no model to lean on; the bay rule stays out of them.
  RoomMergeOptions hand = hand_rules();
  hand.door_like.ratio = 10.0;  // no cut merges as "not a door"
  hand.step_ratio = 0.0;
  EXPECT_EQ(merge_rooms(no_component(), set, cv::Mat(), kRes, hand).pieces.size(), 2u);
}

// A 10 m x 8 m room and, behind a gap of gap cells in its 0.2 m top wall, a 1.2 m x 1 m scrap of
// floor; the scrap's sides and top run into never-seen cells, or into walls when walled. Drawn with
// y up from the grid's bottom edge and cell (x, y) the square [x, x + 1] x [y, y + 1], then put in the
// segmenter's grid coordinates (cell centres at whole numbers, row 0 the top row).
struct ScrapBehindGap {
  PieceSet set;
  cv::Mat cells;
  ScrapBehindGap(int gap, bool walled) {
    const int a = 100 - gap / 2, b = a + gap;
    const double da = a - 0.5, db = b - 0.5;
    set.pieces = {{{{-0.5, -0.5}, {199.5, -0.5}, {199.5, 159.5}, {db, 159.5}, {da, 159.5}, {-0.5, 159.5}}, {}},
                  {{{da, 159.5}, {db, 159.5}, {db, 163.5}, {111.5, 163.5}, {111.5, 183.5}, {87.5, 183.5}, {87.5, 163.5}, {da, 163.5}},
                   {}}};
    set.add_cut({{da, 159.5}, {db, 159.5}}, CutRule::kDoor);
    cells = cv::Mat(200, 220, CV_8UC1, cv::Scalar(kOccupied));
    if (!walled) cells(cv::Rect(82, 164, 36, 26)).setTo(kUnknown);
    cells(cv::Rect(0, 0, 200, 160)).setTo(kFree);
    cells(cv::Rect(a, 160, gap, 4)).setTo(kFree);
    cells(cv::Rect(88, 164, 24, 20)).setTo(kFree);
    cv::flip(cells, cells, 0);
  }
};

TEST(MergeRooms, AScrapBoundedByNeverSeenCellsBehindAGapNarrowerThanAPersonJoinsTheRoom) {
  const RoomMergeOptions options = model_answering(0.45);
  const ScrapBehindGap scrap(8, false);  // a 0.4 m gap
  const PieceSet rooms = merge_rooms(no_component(), scrap.set, scrap.cells, kRes, options);
  ASSERT_EQ(rooms.pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(area(rooms.pieces[0]), 200 * 160 + 8 * 4 + 24 * 20);
  // A walled closet behind the same gap, the scrap behind a door a person walks through (0.8 m), the
  // model sure of two rooms, or --no-fragments: two rooms.
  const ScrapBehindGap closet(8, true);
  EXPECT_EQ(merge_rooms(no_component(), closet.set, closet.cells, kRes, options).pieces.size(), 2u);
  const ScrapBehindGap door(16, false);
  EXPECT_EQ(merge_rooms(no_component(), door.set, door.cells, kRes, options).pieces.size(), 2u);
  EXPECT_EQ(merge_rooms(no_component(), scrap.set, scrap.cells, kRes, model_answering(0.2)).pieces.size(), 2u);
  RoomMergeOptions off = options;
  off.fragment_area = 0.0;
  EXPECT_EQ(merge_rooms(no_component(), scrap.set, scrap.cells, kRes, off).pieces.size(), 2u);
  // Walls drawn in the never-seen grey (no occupied cell): walls and the dark cannot be told apart.
  cv::Mat grey = scrap.cells.clone();
  grey.setTo(kUnknown, grey == kOccupied);
  EXPECT_EQ(merge_rooms(no_component(), scrap.set, grey, kRes, options).pieces.size(), 2u);
}

}  // namespace
}  // namespace topocut
