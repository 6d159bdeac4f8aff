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

// Plan's corridor (room 1) and the room off its side (room 2) labelled, as the labelling leaves them:
// the room's floor its piece, and, with rays, the rays the cleaning removed beyond its ragged far side
// (one every other row, 25 cells long, free cells off the floor) given to it too. fan_first numbers the
// room before the corridor. Open to the edge, the never-seen space beyond the room reaches the grid's
// edge (the open, outside the building); else the map's 10-cell walls enclose it.
struct Labelled {
  Segmentation segmentation;
  OccupancyGrid grid;
  cv::Mat floor;
  int fan = 2, corridor = 1;
  Labelled(unsigned char beyond_room, bool rays, bool fan_first = false, bool open_to_edge = true) {
    Plan plan(true, beyond_room);
    grid = plan.grid;
    if (open_to_edge) grid.cells(cv::Rect(120, 15, 10, 100)).setTo(beyond_room);
    const cv::Mat pieces = rasterize_polygons(plan.rooms.pieces, grid.cells.size());
    floor = pieces > 0;
    if (fan_first) std::swap(fan, corridor);
    segmentation.labels = cv::Mat(grid.cells.size(), CV_32SC1, cv::Scalar(0));
    segmentation.labels.setTo(corridor, pieces == 1);
    segmentation.labels.setTo(fan, pieces == 2);
    for (int row = 129 - 84; rays && row <= 129 - 46; row += 2) {
      grid.cells(cv::Rect(87, row, 25, 1)).setTo(kFree);
      segmentation.labels(cv::Rect(87, row, 25, 1)).setTo(fan);
    }
    segmentation.resolution = kRes;
    for (int id = 1; id <= 2; ++id) {
      Room room;
      room.id = id;
      room.area = cv::countNonZero((segmentation.labels == id) & floor) * kRes * kRes;  // the piece's cells
      room.labelled_area = cv::countNonZero(segmentation.labels == id) * kRes * kRes;
      room.centroid = {static_cast<double>(id), 0.0};  // tells the rooms apart once renumbered
      segmentation.rooms.push_back(room);
    }
    segmentation.passages.push_back(Passage{1, 2, Segment2{{2.25, 0.25}, {2.25, 2.25}}, 2.0, false, CutRule::kDoor});
  }
};

// A room still open once labelled that holds a fan's rays is no room: its cells, rays and all, get 0;
// the corridor keeps its cells and becomes room 1 whatever its number was; the passage goes.
TEST(OpenRooms, AnOpenRoomHoldingTheRaysOfAFanIsLeftOut) {
  for (const bool fan_first : {false, true}) {
    SCOPED_TRACE(fan_first);
    Labelled fan(kUnknown, true, fan_first);
    const cv::Mat corridor_cells = fan.segmentation.labels == fan.corridor;
    const Point2 corridor_tag = fan.segmentation.rooms[static_cast<std::size_t>(fan.corridor - 1)].centroid;
    const Room& room = fan.segmentation.rooms[static_cast<std::size_t>(fan.fan - 1)];
    ASSERT_GT(room.labelled_area - room.area, 0.02 * room.labelled_area);
    leave_out_fans(fan.segmentation, fan.grid, fan.floor);
    ASSERT_EQ(fan.segmentation.rooms.size(), 1u);
    EXPECT_EQ(fan.segmentation.rooms[0].id, 1);
    EXPECT_EQ(fan.segmentation.rooms[0].centroid, corridor_tag);
    cv::Mat expected;
    corridor_cells.convertTo(expected, CV_32S, 1.0 / 255.0);
    EXPECT_EQ(cv::countNonZero(fan.segmentation.labels != expected), 0);  // the corridor 1, all else 0
    EXPECT_TRUE(fan.segmentation.passages.empty());
  }
}

// A drawn plan's room has no rays; a walled room with rays is no fan; the rule switched off or
// without walls changes nothing; a floor of another size is an error.
TEST(OpenRooms, RoomsWithoutRaysWalledRoomsAndTheRuleOffStay) {
  const auto kept = [](Labelled labelled, const OpenRoomOptions& options = {}) {
    const cv::Mat before = labelled.segmentation.labels.clone();
    leave_out_fans(labelled.segmentation, labelled.grid, labelled.floor, options);
    return labelled.segmentation.rooms.size() == 2u && labelled.segmentation.passages.size() == 1u &&
           cv::countNonZero(labelled.segmentation.labels != before) == 0;
  };
  EXPECT_TRUE(kept(Labelled(kUnknown, false)));
  EXPECT_TRUE(kept(Labelled(kOccupied, true)));
  OpenRoomOptions off;
  off.fan_ray_share = 0.0;
  EXPECT_TRUE(kept(Labelled(kUnknown, true), off));
  OpenRoomOptions disabled;
  disabled.enabled = false;
  EXPECT_TRUE(kept(Labelled(kUnknown, true), disabled));
  // A share of rays just above the room's own (the cells the labelling gave it beyond its piece).
  const Labelled fan(kUnknown, true);
  const cv::Mat room = fan.segmentation.labels == fan.fan;
  OpenRoomOptions more;
  more.fan_ray_share = 0.01 + static_cast<double>(cv::countNonZero(room & (fan.floor == 0))) / cv::countNonZero(room);
  ASSERT_LT(more.fan_ray_share, 0.5);
  EXPECT_TRUE(kept(fan, more));
  more.fan_ray_share -= 0.02;
  EXPECT_FALSE(kept(fan, more));
  Labelled no_walls(kUnknown, true);
  no_walls.grid.cells.setTo(kUnknown, no_walls.grid.cells == kOccupied);
  EXPECT_TRUE(kept(no_walls));
  Labelled wrong(kUnknown, true);
  EXPECT_THROW(leave_out_fans(wrong.segmentation, wrong.grid, wrong.floor(cv::Rect(0, 0, 10, 10)).clone()), Error);
  // Inside the building (walls closed across 0.5 m gaps enclose it), it is a walled room holding the
  // fan seen through its door; unless every fan is to be left out.
  const Labelled walled_in(kUnknown, true, false, false);
  const auto left_out = [&](OpenRoomOptions options, double closing) {
    Labelled labelled = walled_in;
    labelled.segmentation.labels = walled_in.segmentation.labels.clone();
    options.fan_closing = closing;
    leave_out_fans(labelled.segmentation, labelled.grid, labelled.floor, options);
    return labelled.segmentation.rooms.size() == 1u;
  };
  EXPECT_FALSE(left_out(OpenRoomOptions{}, 0.5));
  OpenRoomOptions every_fan;
  every_fan.fan_inside_share = 1.0;
  EXPECT_TRUE(left_out(every_fan, 0.5));
  EXPECT_TRUE(left_out(OpenRoomOptions{}, 0.0));  // no closing: nothing is inside, as in the cleaning
  Labelled stray(kUnknown, true);
  stray.segmentation.labels.at<int>(0, 0) = 7;  // no room of the segmentation
  EXPECT_THROW(leave_out_fans(stray.segmentation, stray.grid, stray.floor), Error);
  Labelled unnumbered(kUnknown, true);
  unnumbered.segmentation.rooms[1].id = 5;
  EXPECT_THROW(leave_out_fans(unnumbered.segmentation, unnumbered.grid, unnumbered.floor), Error);
  OpenRoomOptions bad;
  bad.fan_ray_share = 1.5;
  EXPECT_THROW(leave_out_fans(wrong.segmentation, wrong.grid, wrong.floor, bad), Error);
}

}  // namespace
}  // namespace topocut
