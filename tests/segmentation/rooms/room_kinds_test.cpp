#include "topocut/segmentation/room_kinds.h"

#include <algorithm>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "topocut/core/error.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {
namespace {

constexpr double kResolution = 0.05;

// Metres as cells at kResolution.
int cells(double metres) { return static_cast<int>(metres / kResolution + 0.5); }

// A strip (label 1) along the bottom, length x width metres, with `rooms` square rooms (labels 2...)
// of side metres above it, each touching it along its whole side, one metre apart.
cv::Mat strip_with_rooms(double length, double width, int rooms, double side) {
  cv::Mat labels(cells(width + side) + 2, cells(length) + 2, CV_32SC1, cv::Scalar(0));
  labels(cv::Rect(1, cells(side) + 1, cells(length), cells(width))).setTo(1);
  for (int k = 0; k < rooms; ++k)
    labels(cv::Rect(1 + k * cells(side + 1.0), 1, cells(side), cells(side))).setTo(2 + k);
  return labels;
}

// Shapes measured on every cell (RoomKindOptions::sample no larger than a cell).
RoomKindOptions every_cell() {
  RoomKindOptions o;
  o.sample = 0.0;
  return o;
}

TEST(RoomShapes, AStripsWidthAndElongationAreItsOwn) {
  const std::vector<RoomShape> shapes = room_shapes(strip_with_rooms(10.0, 1.0, 0, 1.0), kResolution, every_cell());
  ASSERT_EQ(shapes.size(), 1u);
  EXPECT_NEAR(shapes[0].area, 10.0, 1e-9);
  EXPECT_NEAR(shapes[0].mean_width, 1.0, 0.1);
  EXPECT_NEAR(shapes[0].elongation, 10.0, 2.0);  // its ends bring cells nearer the edge: a little more
  EXPECT_EQ(shapes[0].openings, 0);
}

TEST(RoomShapes, ASquareIsNotElongated) {
  cv::Mat labels(cells(4.0) + 2, cells(4.0) + 2, CV_32SC1, cv::Scalar(0));
  labels(cv::Rect(1, 1, cells(4.0), cells(4.0))).setTo(1);
  const RoomShape square = room_shapes(labels, kResolution, every_cell())[0];
  // A square of side s: cells lie s / 6 from its edge on average, so the mean width is 2 s / 3.
  EXPECT_NEAR(square.mean_width, 4.0 * 2.0 / 3.0, 0.15);
  EXPECT_GT(square.elongation, 1.8);
  EXPECT_LT(square.elongation, 2.6);
}

// The default samples every 0.15 m (3 cells here): a quarter of the cost, the same shapes to within a sample.
TEST(RoomShapes, SamplingKeepsTheShapes) {
  const cv::Mat labels = strip_with_rooms(12.0, 1.0, 4, 2.0);
  const std::vector<RoomShape> all = room_shapes(labels, kResolution, every_cell()), sampled = room_shapes(labels, kResolution);
  ASSERT_EQ(all.size(), sampled.size());
  for (std::size_t k = 0; k < all.size(); ++k) {
    EXPECT_NEAR(sampled[k].area, all[k].area, 0.1 * all[k].area) << "room " << k + 1;
    EXPECT_NEAR(sampled[k].mean_width, all[k].mean_width, 0.15) << "room " << k + 1;
    EXPECT_EQ(sampled[k].openings, all[k].openings) << "room " << k + 1;
  }
}

TEST(RoomShapes, OpeningsCountTheRoomsTouchedAlongMoreThanTheMinimumContact) {
  cv::Mat labels = strip_with_rooms(12.0, 1.0, 4, 2.0);
  // A fifth room beyond the fourth, one row short of the strip but for one cell: no passage.
  labels(cv::Rect(cells(11.3), 1, cells(0.5), cells(2.0) - 1)).setTo(6);
  labels(cv::Rect(cells(11.3), cells(2.0), 1, 1)).setTo(6);
  const std::vector<RoomShape> shapes = room_shapes(labels, kResolution, every_cell());
  ASSERT_EQ(shapes.size(), 6u);
  EXPECT_EQ(shapes[0].openings, 4);
  for (std::size_t k = 1; k < 5; ++k) EXPECT_EQ(shapes[k].openings, 1) << "room " << k + 1;
  EXPECT_EQ(shapes[5].openings, 0);
}

TEST(RoomKinds, ANarrowStripBetweenRoomsIsACorridorAndTheRoomsAreRooms) {
  Segmentation s;
  s.labels = strip_with_rooms(12.0, 1.0, 4, 2.0);
  s.resolution = kResolution;
  for (int id = 1; id <= 5; ++id) {
    Room room;
    room.id = id;
    s.rooms.push_back(room);
  }
  assign_room_kinds(s);
  EXPECT_EQ(s.rooms[0].kind, RoomKind::kCorridor);
  for (std::size_t k = 1; k < 5; ++k) EXPECT_EQ(s.rooms[k].kind, RoomKind::kRoom) << "room " << k + 1;
}

TEST(RoomKinds, EachConditionCanMakeARoom) {
  const RoomKindOptions o;
  RoomShape corridor;
  corridor.area = 10.0;
  corridor.mean_width = 1.0;
  corridor.elongation = 10.0;
  corridor.openings = 4;
  EXPECT_EQ(room_kind(corridor, o), RoomKind::kCorridor);
  RoomShape s = corridor;
  s.openings = o.openings - 1;  // a dead end with fewer doors: a closet, a balcony
  EXPECT_EQ(room_kind(s, o), RoomKind::kRoom);
  s = corridor;
  s.elongation = o.elongation - 0.1;  // not long for its width
  EXPECT_EQ(room_kind(s, o), RoomKind::kRoom);
  s = corridor;
  s.mean_width = o.width + 0.5;  // wide and not long enough for an office hallway
  s.elongation = o.hallway_elongation - 0.5;
  EXPECT_EQ(room_kind(s, o), RoomKind::kRoom);
  s.elongation = o.hallway_elongation + 0.5;  // wide but long: a hallway
  EXPECT_EQ(room_kind(s, o), RoomKind::kCorridor);
}

TEST(RoomKinds, RejectsBadThresholdsAndLabels) {
  RoomKindOptions o;
  o.width = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(validate(o), Error);
  o = {};
  o.openings = -1;
  EXPECT_THROW(validate(o), Error);
  SegmentOptions segment;
  segment.kinds.elongation = -1.0;
  EXPECT_THROW(validate(segment), Error);
  EXPECT_THROW(room_shapes(cv::Mat::zeros(4, 4, CV_8UC1), kResolution), Error);
  EXPECT_TRUE(room_shapes(cv::Mat::zeros(4, 4, CV_32SC1), kResolution).empty());
}

// The bundled floor plan (maps/README.md): a corridor 2 m wide across the building at y 6..8 m,
// rooms north and south of it. Read with OpenCV (the segmentation module does not use io).
OccupancyGrid floorplan() {
  const cv::Mat grey = cv::imread(std::string(TOPOCUT_SOURCE_DIR "/maps/floorplan.png"), cv::IMREAD_GRAYSCALE);
  if (grey.empty()) throw Error("test map missing: floorplan.png");
  OccupancyGrid grid{cv::Mat(grey.size(), CV_8UC1, cv::Scalar(kUnknown)), 0.05, {0.0, 0.0}};
  grid.cells.setTo(kFree, grey > 250);
  grid.cells.setTo(kOccupied, grey < 50);
  return grid;
}

// The label at world point (x, y) of s.
int label_at(const Segmentation& s, double x, double y) {
  return s.labels.at<int>(s.labels.rows - 1 - static_cast<int>(y / s.resolution), static_cast<int>(x / s.resolution));
}

void expect_only_the_corridor(const Segmentation& s) {
  const int corridor = label_at(s, 10.0, 7.0);
  ASSERT_GT(corridor, 0);
  ASSERT_GE(s.rooms.size(), 5u);
  for (const Room& room : s.rooms)
    EXPECT_EQ(room.kind, room.id == corridor ? RoomKind::kCorridor : RoomKind::kRoom) << "room " << room.id;
}

TEST(RoomKinds, SegmentFindsTheFloorplansCorridor) { expect_only_the_corridor(segment(floorplan())); }

// Kinds follow the rooms' growth in an update in place: the corridor, blocked in its middle at first
// (two halves, each too short for a hallway 2 m wide), becomes one corridor when the block goes.
TEST(RoomKinds, TheLiveSegmenterUpdatesKindsInPlace) {
  const OccupancyGrid grid = floorplan();
  OccupancyGrid blocked = grid;
  blocked.cells = grid.cells.clone();
  const int corridor_row = grid.cells.rows - 1 - cells(7.0);
  blocked.cells(cv::Rect(cells(9.5), corridor_row - cells(1.2), cells(1.0), cells(2.4))).setTo(kOccupied);
  IncrementalOptions options;
  options.split_after = options.merge_after = 1;  // the halves join in this update, as batch joins them
  IncrementalSegmenter live(options);
  live.update(blocked);
  for (const Room& room : live.result().rooms) EXPECT_EQ(room.kind, RoomKind::kRoom) << "room " << room.id;
  live.update(grid);
  EXPECT_EQ(live.last_update().kind, IncrementalUpdateReport::Kind::kIncremental);
  expect_only_the_corridor(live.result());
}

// Kinds measured on the changed rooms' box only are those of a pass over all the labels, update by
// update, while the floor plan is revealed from west to east.
TEST(RoomKinds, TheLiveSegmentersKindsAreThoseOfTheWholeLabels) {
  const OccupancyGrid plan = floorplan();
  IncrementalSegmenter live;
  int in_place = 0;
  for (double seen = 4.0; seen <= 20.0; seen += 0.5) {
    OccupancyGrid grid = plan;
    grid.cells = plan.cells.clone();
    const int known = std::min(grid.cells.cols, cells(seen));
    if (known < grid.cells.cols) grid.cells.colRange(known, grid.cells.cols).setTo(kUnknown);
    live.update(grid);
    in_place += live.last_update().kind == IncrementalUpdateReport::Kind::kIncremental;
    Segmentation whole = live.result();
    assign_room_kinds(whole);
    for (std::size_t k = 0; k < whole.rooms.size(); ++k)
      EXPECT_EQ(live.result().rooms[k].kind, whole.rooms[k].kind) << "room " << whole.rooms[k].id << " seen to x " << seen;
  }
  EXPECT_GT(in_place, 5) << "the reveal should be mostly updates in place";
  expect_only_the_corridor(live.result());
}

}  // namespace
}  // namespace topocut
