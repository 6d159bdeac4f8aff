#include "topocut/segmentation/open_rooms.h"

#include <gtest/gtest.h>

#include "topocut/core/error.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;

// A 2 m x 6 m corridor (x in [5, 45], y in [5, 125]) walled all round but where a 2 m x 2 m room opens
// off its right side (x in [45, 85], y in [45, 85]) through a cut at x = 45; the room is surrounded by
// beyond_room cells 1.5 m deep (grid rows are y = 129 - row). Its far side ends in teeth a cell long
// (laser rays of different lengths) when ragged.
struct Plan {
  PieceSet rooms;
  OccupancyGrid grid;
  Plan(bool ragged, unsigned char beyond_room) {
    Ring room{{45, 45}, {85, 45}};
    for (int y = 45; y < 85 && ragged; y += 2)  // the far side, upwards: out a cell and back every other cell
      room.insert(room.end(), {{85, y + 1.0}, {86, y + 1.0}, {86, y + 2.0}, {85, y + 2.0}});
    room.insert(room.end(), {{85, 85}, {45, 85}});
    rooms.pieces = {{{{5, 5}, {45, 5}, {45, 45}, {45, 85}, {45, 125}, {5, 125}}, {}}, {room, {}}};
    rooms.add_cut({{45, 45}, {45, 85}}, CutRule::kDoor);
    grid.cells = cv::Mat(130, 130, CV_8UC1, cv::Scalar(kOccupied));
    grid.resolution = kRes;
    grid.cells(cv::Rect(5, 5, 40, 120)).setTo(kFree);
    grid.cells(cv::Rect(45, 15, 75, 100)).setTo(beyond_room);
    grid.cells(cv::Rect(45, 45, 40, 40)).setTo(kFree);
    for (int y = 45; y < 85 && ragged; y += 2) grid.cells.at<unsigned char>(129 - y - 1, 85) = kFree;
  }
};

TEST(OpenRooms, ARayFanJoinsTheCorridorItOpensFrom) {
  Plan plan(true, kUnknown);
  const PieceSet rooms = join_open_rooms(plan.rooms, plan.grid);
  ASSERT_EQ(rooms.pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(area(rooms.pieces[0]), area(plan.rooms.pieces[0]) + area(plan.rooms.pieces[1]));
  EXPECT_EQ(rooms.cuts, plan.rooms.cuts);  // the cut stays listed; it separates nothing now
}

// Free space seen only through a gap, with no room beside it (its own component once the cleaning
// cut it off): outside the building, so left unlabelled; walled all round, it stays a room.
TEST(OpenRooms, AnOpenRoomWithNothingBesideItIsDropped) {
  for (const unsigned char beyond : {kUnknown, kOccupied}) {
    Plan alone(true, beyond);
    alone.grid.cells(cv::Rect(5, 5, 40, 120)).setTo(kOccupied);  // no corridor
    alone.rooms.pieces.erase(alone.rooms.pieces.begin());
    alone.rooms.cuts.clear();
    alone.rooms.rules.clear();
    // Alone on the map it is the building explored so far, and stays.
    EXPECT_EQ(join_open_rooms(alone.rooms, alone.grid).pieces.size(), 1u);
    // Beside a walled room more than twice its size, it is a scrap outside the building.
    alone.rooms.pieces.push_back({{{5, 5}, {44, 5}, {44, 125}, {5, 125}}, {}});
    alone.grid.cells(cv::Rect(5, 5, 39, 120)).setTo(kFree);
    EXPECT_EQ(join_open_rooms(alone.rooms, alone.grid).pieces.size(), beyond == kUnknown ? 1u : 2u);
  }
}

TEST(OpenRooms, AWalledRoomOrOneBehindAStraightGreyWallStays) {
  EXPECT_EQ(join_open_rooms(Plan(true, kOccupied).rooms, Plan(true, kOccupied).grid).pieces.size(), 2u);
  Plan straight(false, kUnknown);  // a wall drawn in the unknown grey runs straight
  EXPECT_EQ(join_open_rooms(straight.rooms, straight.grid).pieces.size(), 2u);
  OpenRoomOptions any_outline;
  any_outline.ragged_share = 0.0;
  EXPECT_EQ(join_open_rooms(straight.rooms, straight.grid, any_outline).pieces.size(), 1u);
}

TEST(OpenRooms, OffWithoutWallsOrWhenSwitchedOffAndBadOptions) {
  Plan plan(true, kUnknown);
  OpenRoomOptions off;
  off.enabled = false;
  EXPECT_EQ(join_open_rooms(plan.rooms, plan.grid, off).pieces.size(), 2u);
  Plan no_walls(true, kUnknown);
  no_walls.grid.cells.setTo(kUnknown, no_walls.grid.cells == kOccupied);  // walls in the unknown grey
  EXPECT_EQ(join_open_rooms(no_walls.rooms, no_walls.grid).pieces.size(), 2u);
  OpenRoomOptions bad;
  bad.share = 1.5;
  EXPECT_THROW(join_open_rooms(plan.rooms, plan.grid, bad), Error);
}

}  // namespace
}  // namespace topocut
