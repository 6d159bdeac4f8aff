#include "topocut/segmentation/open_rooms.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/map/rasterize.h"

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

// Beyond the corridor's wall, a 1 m x 1.05 m block of floor (x in [60, 80]) walled on three sides, seen
// only through a gap in that wall: the cleaning kept the block, where the rays crossed densely, as
// floor, and removed the rays (free cells of no piece) through the gap and the fan beyond the block's
// open side, one ray every other row to the map's edge. The labelling gives the block the rays, so the
// room a person would see is a fan, though the block's own outline runs mostly along walls.
struct SeenThroughGap {
  PieceSet rooms;
  OccupancyGrid grid;
  SeenThroughGap(bool rays, bool neighbour) {
    rooms.pieces = {{{{5, 5}, {45, 5}, {45, 125}, {5, 125}}, {}}, {{{60, 55}, {80, 55}, {80, 76}, {60, 76}}, {}}};
    if (neighbour) rooms.pieces.push_back({{{60, 35}, {80, 35}, {80, 55}, {60, 55}}, {}});  // a room below the block
    grid.cells = cv::Mat(130, 130, CV_8UC1, cv::Scalar(kUnknown));
    grid.resolution = kRes;
    grid.cells(cv::Rect(4, 4, 42, 122)).setTo(kOccupied);
    grid.cells(cv::Rect(59, 52, 21, 25)).setTo(kOccupied);  // the block's walls (its right side is never-seen)
    grid.cells.setTo(kFree, rasterize_polygons(rooms.pieces, grid.cells.size()) > 0);
    const int block_top = cv::boundingRect(rasterize_polygons(rooms.pieces, grid.cells.size()) == 2).y;
    if (!rays) return;
    grid.cells(cv::Rect(45, block_top + 5, 16, 3)).setTo(kFree);  // through the corridor's wall and the block's
    // The fan beyond the block's open side, wider than the block: its rays' common front, and the rays.
    grid.cells(cv::Rect(80, block_top - 21, 1, 63)).setTo(kFree);
    for (int row = block_top - 21; row < block_top + 42; row += 2) grid.cells(cv::Rect(80, row, 50, 1)).setTo(kFree);
  }
};

TEST(OpenRooms, FloorSeenOnlyThroughRaysIsNoRoomOfItsOwn) {
  const SeenThroughGap fan(true, false);
  // Not open by its outline: more wall than never-seen space.
  OpenRoomOptions outline_only;
  outline_only.floor_share = 0.0;
  EXPECT_EQ(join_open_rooms(fan.rooms, fan.grid, outline_only).pieces.size(), 2u);
  // Mostly rays once labelled: left out, so that the labelling gives its cells and the fan to the
  // corridor they are seen from.
  const PieceSet rooms = join_open_rooms(fan.rooms, fan.grid);
  ASSERT_EQ(rooms.pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(area(rooms.pieces[0]), area(fan.rooms.pieces[0]));
  // The same block without the rays (a walled niche reached some other way) stays a room.
  const SeenThroughGap walled(false, false);
  EXPECT_EQ(join_open_rooms(walled.rooms, walled.grid).pieces.size(), 2u);
  // A room beside another is not judged by the rays it is given (a room with a fan through its door).
  const SeenThroughGap beside(true, true);
  EXPECT_EQ(join_open_rooms(beside.rooms, beside.grid).pieces.size(), 3u);
  OpenRoomOptions bad;
  bad.floor_share = 1.5;
  EXPECT_THROW(join_open_rooms(fan.rooms, fan.grid, bad), Error);
}

TEST(OpenRooms, AWalledRoomOrOneBehindAStraightGreyWallStays) {
  EXPECT_EQ(join_open_rooms(Plan(true, kOccupied).rooms, Plan(true, kOccupied).grid).pieces.size(), 2u);
  Plan straight(false, kUnknown);  // a wall drawn in the unknown grey runs straight
  EXPECT_EQ(join_open_rooms(straight.rooms, straight.grid).pieces.size(), 2u);
  OpenRoomOptions any_outline;
  any_outline.ragged_share = 0.0;
  EXPECT_EQ(join_open_rooms(straight.rooms, straight.grid, any_outline).pieces.size(), 1u);
}

// Given the rooms' spans (as segment_input() shares them with the labelling), the same rooms as when
// it rasterizes them itself, whether it joins, drops or keeps them.
TEST(OpenRooms, TheRoomsSpansGivenChangeNothing) {
  const auto same = [](const PieceSet& rooms, const OccupancyGrid& grid, std::size_t expected) {
    const PieceSet own = join_open_rooms(rooms, grid);
    const PieceSet given = join_open_rooms(rooms, grid, OpenRoomOptions{}, polygon_spans(rooms.pieces, grid.cells.size()));
    EXPECT_EQ(own.pieces.size(), expected);
    EXPECT_EQ(given.pieces, own.pieces);
    EXPECT_EQ(given.cuts, own.cuts);
  };
  const Plan ragged(true, kUnknown), walled(true, kOccupied);
  same(ragged.rooms, ragged.grid, 1u);
  same(walled.rooms, walled.grid, 2u);
  const SeenThroughGap fan(true, false), beside(true, true);
  same(fan.rooms, fan.grid, 1u);
  same(beside.rooms, beside.grid, 3u);
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
