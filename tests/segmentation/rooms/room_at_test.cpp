#include "topocut/segmentation/room_at.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "topocut/core/error.h"

namespace topocut {
namespace {

// Labels of a 3-row, 4-column grid (top-down rows) at 0.5 m a cell, origin (10, 20):
//   row 0 (y 21.0..21.5): 2 2 0 3
//   row 1 (y 20.5..21.0): 1 1 0 3
//   row 2 (y 20.0..20.5): 1 1 0 0
Segmentation small_grid() {
  Segmentation s;
  s.labels = (cv::Mat_<int>(3, 4) << 2, 2, 0, 3, 1, 1, 0, 3, 1, 1, 0, 0);
  s.resolution = 0.5;
  s.origin = {10.0, 20.0};
  return s;
}

TEST(RoomAt, TopDownLabelsAnswerByCell) {
  const Segmentation s = small_grid();
  const GridFrame frame;  // top-down, no yaw: what segment() gives
  EXPECT_EQ(room_at(s, frame, {10.2, 20.2}), 1);  // bottom-left cell
  EXPECT_EQ(room_at(s, frame, {10.7, 21.2}), 2);  // top row, second column
  EXPECT_EQ(room_at(s, frame, {11.7, 20.9}), 3);
  EXPECT_EQ(room_at(s, frame, {11.2, 20.7}), 0);  // a wall cell: none
  EXPECT_EQ(room_at(s, frame, {11.7, 20.2}), 0);
  // Off the grid on every side: none, not an error.
  for (const Point2 p : {Point2{9.99, 20.2}, Point2{12.01, 20.2}, Point2{10.2, 19.99}, Point2{10.2, 21.51}, Point2{-1e9, 1e9}})
    EXPECT_EQ(room_at(s, frame, p), 0) << p.x << ", " << p.y;
  // A cell edge belongs to the cell above and to the right.
  EXPECT_EQ(room_at(s, frame, {10.0, 20.0}), 1);
  EXPECT_EQ(room_at(s, frame, {10.5, 21.0}), 2);
  EXPECT_EQ(room_at(s, frame, {12.0, 20.7}), 0);
}

TEST(RoomAt, BottomUpLabelsAnswerTheSame) {
  Segmentation s = small_grid();
  cv::flip(s.labels.clone(), s.labels, 0);
  const GridFrame frame{RowOrder::kBottomUp, 0.0};
  EXPECT_EQ(room_at(s, frame, {10.2, 20.2}), 1);
  EXPECT_EQ(room_at(s, frame, {10.7, 21.2}), 2);
  EXPECT_EQ(room_at(s, frame, {11.7, 20.9}), 3);
  EXPECT_EQ(room_at(s, frame, {11.2, 20.7}), 0);
}

TEST(RoomAt, YawTurnsTheGridAboutTheOrigin) {
  const Segmentation s = small_grid();
  // A quarter turn: the grid's x axis points along the map's y axis, its y axis along -x.
  const GridFrame frame{RowOrder::kTopDown, M_PI / 2};
  const auto turned = [&](double gx, double gy) { return Point2{s.origin.x - gy, s.origin.y + gx}; };
  EXPECT_EQ(room_at(s, frame, turned(0.2, 0.2)), 1);
  EXPECT_EQ(room_at(s, frame, turned(0.7, 1.2)), 2);
  EXPECT_EQ(room_at(s, frame, turned(1.7, 0.9)), 3);
  EXPECT_EQ(room_at(s, frame, turned(1.2, 0.7)), 0);
  // The unturned place of room 1 lies off the turned grid.
  EXPECT_EQ(room_at(s, frame, {10.2, 20.2}), 0);
}

TEST(RoomAt, EveryRoomsInsidePointIsInThatRoom) {
  OccupancyGrid grid;
  grid.cells = cv::Mat(60, 100, CV_8UC1, cv::Scalar(kOccupied));
  grid.resolution = 0.05;
  grid.origin = {-3.0, 4.0};
  grid.cells(cv::Rect(2, 2, 47, 56)).setTo(kFree);
  grid.cells(cv::Rect(51, 2, 47, 56)).setTo(kFree);
  grid.cells(cv::Rect(49, 20, 2, 18)).setTo(kFree);  // a 0.9 m door
  for (const GridFrame frame : {GridFrame{}, GridFrame{RowOrder::kBottomUp, 0.0}, GridFrame{RowOrder::kBottomUp, 0.7}}) {
    const GridSegmentation result = segment_grid(grid, frame);
    ASSERT_EQ(result.segmentation.rooms.size(), 2u);
    for (std::size_t k = 0; k < result.placements.size(); ++k)
      EXPECT_EQ(room_at(result, result.placements[k].inside), result.segmentation.rooms[k].id);
    EXPECT_EQ(room_at(result, grid.origin), 0);  // the corner cell is wall
  }
}

TEST(RoomAt, RefusesANonFinitePoint) {
  const Segmentation s = small_grid();
  EXPECT_THROW(room_at(s, GridFrame{}, {NAN, 20.0}), Error);
  EXPECT_THROW(room_at(s, GridFrame{}, {10.0, INFINITY}), Error);
}


TEST(RoomAt, AFrameThatIsNotANumberFindsNoRoomAndReadsNothingOutside) {
  // Resolutions and yaws an unpickled or hand-made result may hold: the cell index is NaN or
  // infinite, which must read as off the grid, never as a cell (a read outside the labels).
  for (const double resolution : {0.0, -0.5, std::nan(""), 1e-300}) {
    Segmentation s = small_grid();
    s.resolution = resolution;
    EXPECT_EQ(room_at(s, GridFrame{}, {10.2, 20.2}), 0) << resolution;
  }
  for (const double yaw : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    const GridFrame frame{RowOrder::kTopDown, yaw};
    EXPECT_EQ(room_at(small_grid(), frame, {10.2, 20.2}), 0) << yaw;
  }
  Segmentation nan_origin = small_grid();
  nan_origin.origin = {std::nan(""), 20.0};
  EXPECT_EQ(room_at(nan_origin, GridFrame{}, {10.2, 20.2}), 0);
  Segmentation other_type = small_grid();
  other_type.labels.convertTo(other_type.labels, CV_8U);  // not the CV_32S labels every result holds
  EXPECT_EQ(room_at(other_type, GridFrame{}, {10.2, 20.2}), 0);
}

}  // namespace
}  // namespace topocut
