#include "topocut/map/binarize.h"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {
namespace {

OccupancyGrid free_grid(int size, double resolution = 0.05) {
  return {cv::Mat(size, size, CV_8UC1, cv::Scalar(kFree)), resolution, {0.0, 0.0}};
}

TEST(Binarize, UnknownAndOccupiedAreNeverFree) {
  OccupancyGrid grid;
  grid.cells = (cv::Mat_<unsigned char>(1, 4) << kFree, kUnknown, kOccupied, kFree);
  const cv::Mat free = free_space_mask(grid);
  EXPECT_EQ(free.type(), CV_8UC1);
  const cv::Mat expected = (cv::Mat_<unsigned char>(1, 4) << 255, 0, 0, 255);
  EXPECT_EQ(cv::countNonZero(free != expected), 0);
}

TEST(Binarize, InflationRadiusInMetresGivesTheExpectedDisc) {
  OccupancyGrid grid = free_grid(21);
  grid.cells.at<unsigned char>(10, 10) = kOccupied;
  BinarizeOptions options;
  options.robot_radius = 0.25;  // 5 cells: lattice points with x² + y² <= 25 number 81 (Gauss circle)
  cv::Mat free = free_space_mask(grid, options);
  EXPECT_EQ(21 * 21 - cv::countNonZero(free), 81);
  EXPECT_EQ(free.at<unsigned char>(10, 15), 0);    // distance 5: blocked
  EXPECT_EQ(free.at<unsigned char>(11, 15), 255);  // distance sqrt(26): free
  EXPECT_EQ(free.at<unsigned char>(14, 13), 0);    // (3, 4): distance 5, blocked
  options.robot_radius = 0.26;  // 5.2 cells: adds the 8 points at distance sqrt(26)
  free = free_space_mask(grid, options);
  EXPECT_EQ(21 * 21 - cv::countNonZero(free), 89);
  // The same radius at 0.1 m per cell is 2.6 cells: x² + y² <= 6.76 -> 21 points.
  OccupancyGrid coarse = free_grid(21, 0.1);
  coarse.cells.at<unsigned char>(10, 10) = kOccupied;
  EXPECT_EQ(21 * 21 - cv::countNonZero(free_space_mask(coarse, options)), 21);
}

TEST(Binarize, UnknownIsInflatedOnlyWhenAsked) {
  OccupancyGrid grid = free_grid(11);
  grid.cells.at<unsigned char>(5, 5) = kUnknown;
  BinarizeOptions options;
  options.robot_radius = 0.05;  // one cell: the 4-neighbourhood
  EXPECT_EQ(11 * 11 - cv::countNonZero(free_space_mask(grid, options)), 1);
  options.inflate_unknown = true;
  EXPECT_EQ(11 * 11 - cv::countNonZero(free_space_mask(grid, options)), 5);
}

TEST(Binarize, OpeningRemovesSpecksAndSpursButKeepsRooms) {
  OccupancyGrid grid{cv::Mat(30, 30, CV_8UC1, cv::Scalar(kOccupied)), 0.05, {}};
  grid.cells(cv::Rect(2, 2, 12, 12)).setTo(kFree);   // a room
  grid.cells(cv::Rect(14, 7, 6, 1)).setTo(kFree);    // a one-cell spur off it
  grid.cells(cv::Rect(22, 22, 2, 2)).setTo(kFree);   // a 2x2 speck
  BinarizeOptions options;
  options.opening_size = 0.15;  // 3 cells
  const cv::Mat free = free_space_mask(grid, options);
  EXPECT_EQ(cv::countNonZero(free), 144);
  EXPECT_EQ(cv::countNonZero(free(cv::Rect(2, 2, 12, 12))), 144);
}

TEST(Binarize, MedianRemovesSaltButNeverCreatesFreeSpace) {
  OccupancyGrid grid{cv::Mat(20, 20, CV_8UC1, cv::Scalar(kUnknown)), 0.05, {}};
  grid.cells(cv::Rect(5, 5, 10, 10)).setTo(kFree);
  grid.cells.at<unsigned char>(2, 2) = kFree;      // salt in unknown space
  grid.cells.at<unsigned char>(9, 9) = kOccupied;  // pepper in the room: the median fills it, but it stays occupied
  BinarizeOptions options;
  options.median_size = 0.15;
  const cv::Mat free = free_space_mask(grid, options);
  EXPECT_EQ(free.at<unsigned char>(2, 2), 0);
  EXPECT_EQ(free.at<unsigned char>(9, 9), 0);
  EXPECT_EQ(cv::countNonZero(free & (grid.cells != kFree)), 0);
  EXPECT_EQ(free.at<unsigned char>(10, 10), 255);
}

TEST(Binarize, RejectsBadOptionsAndGrids) {
  BinarizeOptions options;
  options.robot_radius = -0.1;
  EXPECT_THROW(free_space_mask(free_grid(5), options), Error);
  options.robot_radius = std::nan("");
  EXPECT_THROW(free_space_mask(free_grid(5), options), Error);
  OccupancyGrid empty;
  EXPECT_THROW(free_space_mask(empty), Error);
  OccupancyGrid bad_resolution = free_grid(5, 0.0);
  EXPECT_THROW(free_space_mask(bad_resolution), Error);
}


TEST(Binarize, AnOpeningLargerThanTheMapLeavesNothingWithoutBuildingItsSquare) {
  // 1000 m at 0.05 m a cell is a 20000-cell square (400 MB as OpenCV's element): refused by size,
  // at once. Up to the map's size, OpenCV's opening as before; one cell more leaves nothing.
  OccupancyGrid grid = free_grid(40);
  grid.cells = cv::Mat(30, 40, CV_8UC1, cv::Scalar(kFree));
  BinarizeOptions options;
  for (const double metres : {1000.0, 5000.0, 1e5}) {
    options.opening_size = metres;
    EXPECT_EQ(cv::countNonZero(free_space_mask(grid, options)), 0) << metres;
  }
  // As OpenCV opens (border not free), on both sides of the map's height and width.
  for (const int side : {29, 30, 31, 40, 45}) {
    options.opening_size = side * 0.05;
    cv::Mat opened;
    cv::morphologyEx(grid.cells == kFree, opened, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_RECT, {side, side}),
                     cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    EXPECT_EQ(cv::countNonZero(free_space_mask(grid, options) != opened), 0) << side;
    EXPECT_EQ(cv::countNonZero(opened) > 0, side <= 30) << side;
  }
  // The median window is clamped to twice the map: a huge one costs what the map costs.
  options = {};
  options.median_size = 1e5;
  EXPECT_EQ(cv::countNonZero(free_space_mask(grid, options)), 30 * 40);
}

}  // namespace
}  // namespace topocut
