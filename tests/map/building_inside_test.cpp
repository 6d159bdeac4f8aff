// The building's inside: a hand-made house (a door closed, a wide gap not), and random
// grids against the definition written with OpenCV's whole-image operations.
#include "topocut/map/building_inside.h"

#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/core/occupancy_grid.h"

namespace topocut {
namespace {

// The definition: walls closed by the square (OpenCV's default border: nothing dilates from beyond
// the edge, nothing erodes there), then a flood from a frame of open cells around the grid.
cv::Mat reference_inside(const cv::Mat& cells, int n) {
  cv::Mat walls;
  cv::morphologyEx(cells == kOccupied, walls, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_RECT, {2 * n + 1, 2 * n + 1}));
  cv::Mat framed(cells.rows + 2, cells.cols + 2, CV_8UC1, cv::Scalar(0));
  walls.copyTo(framed(cv::Rect(1, 1, cells.cols, cells.rows)));
  cv::floodFill(framed, cv::Point(0, 0), cv::Scalar(128), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
  return framed(cv::Rect(1, 1, cells.cols, cells.rows)) != 128;
}

// A 60 x 40 cell house with 2-cell walls in a 100 x 80 grid of never-seen cells; gap: an opening of
// that many cells in its right wall.
cv::Mat house(int gap) {
  cv::Mat cells(80, 100, CV_8UC1, cv::Scalar(kUnknown));
  cells(cv::Rect(20, 20, 60, 40)).setTo(kOccupied);
  cells(cv::Rect(22, 22, 56, 36)).setTo(kFree);
  cells(cv::Rect(78, 30, 2, gap)).setTo(kFree);  // the opening, and a fan of free cells beyond it
  cells(cv::Rect(80, 25, 15, 30)).setTo(kFree);
  return cells;
}

TEST(BuildingInside, ADoorIsClosedAWideGapIsNot) {
  const cv::Mat door = building_inside(house(8), 20);  // a 0.4 m door at 0.05 m, closing 1 m
  EXPECT_EQ(door.at<unsigned char>(40, 50), 255);        // the room
  EXPECT_EQ(door.at<unsigned char>(40, 90), 0);          // the fan outside
  const cv::Mat gap = building_inside(house(30), 20);    // a 1.5 m gap
  EXPECT_EQ(gap.at<unsigned char>(40, 50), 0);
  EXPECT_EQ(cv::countNonZero(building_inside(house(8), 0.0)), 0);  // no closing: nothing inside
  EXPECT_THROW(building_inside(cv::Mat(), 20), Error);
}

TEST(BuildingInside, EqualsTheDefinitionOnRandomGrids) {
  std::mt19937 random(7);
  for (int round = 0; round < 40; ++round) {
    SCOPED_TRACE(round);
    const int rows = 20 + static_cast<int>(random() % 60), cols = 20 + static_cast<int>(random() % 60);
    cv::Mat cells(rows, cols, CV_8UC1, cv::Scalar(kFree));
    const unsigned char kinds[] = {kFree, kOccupied, kUnknown};
    for (int k = 0; k < 30; ++k) {  // rectangles and lines of each kind
      const int x = static_cast<int>(random() % cols), y = static_cast<int>(random() % rows);
      const int w = 1 + static_cast<int>(random() % 20), h = 1 + static_cast<int>(random() % 3);
      const cv::Rect r = (k % 2 ? cv::Rect(x, y, w, h) : cv::Rect(x, y, h, w)) & cv::Rect(0, 0, cols, rows);
      cells(r).setTo(kinds[random() % 3]);
    }
    const int n = 1 + static_cast<int>(random() % 6);
    EXPECT_EQ(cv::countNonZero(building_inside(cells, 2.0 * n) != reference_inside(cells, n)), 0) << "n " << n;
  }
}

// The kept inside is building_inside()'s, computed once per closing: asked again with the same closing,
// the same matrix comes back (no second computation); another closing gives that closing's inside.
TEST(BuildingInside, KeptForTheSameClosingAndComputedAgainForAnother) {
  const cv::Mat cells = house(30);
  BuildingInside kept(cells);
  const cv::Mat& first = kept.at(40);  // closes the 1.5 m gap
  EXPECT_EQ(cv::countNonZero(first != building_inside(cells, 40)), 0);
  EXPECT_EQ(first.at<unsigned char>(40, 50), 255);
  const unsigned char* data = first.data;
  EXPECT_EQ(kept.at(40).data, data);
  const cv::Mat& narrow = kept.at(20);  // does not
  EXPECT_EQ(cv::countNonZero(narrow != building_inside(cells, 20)), 0);
  EXPECT_EQ(narrow.at<unsigned char>(40, 50), 0);
}

}  // namespace
}  // namespace topocut
