// wall_cells() is the cells within Euclidean distance reach of an occupied cell: checked against
// the exact distance transform on random maps, for radii on and between the lattice's distances.
#include "topocut/map/room_outline.h"

#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/occupancy_grid.h"

namespace topocut {
namespace {

cv::Mat by_distance(const cv::Mat& cells, double reach) {
  cv::Mat distance;
  cv::distanceTransform(cells != kOccupied, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance <= reach;
}

TEST(WallCells, AreTheCellsWithinReachOfAnOccupiedCell) {
  std::mt19937 random(7);
  int differing_radii = 0;
  for (const double density : {0.002, 0.05, 0.3}) {
    cv::Mat cells(90, 130, CV_8UC1, cv::Scalar(kUnknown));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int r = 0; r < cells.rows; ++r)
      for (int c = 0; c < cells.cols; ++c) {
        const double x = u(random);
        cells.at<unsigned char>(r, c) = x < density ? kOccupied : x < 0.6 ? kFree : kUnknown;
      }
    for (const double reach : {0.0, 1.0, 1.5, 2.0 + 1e-9, 3.0 + 1e-9, std::sqrt(13.0) + 1e-9, 4.2, 7.5, 12.0, 12.5, 40.0}) {
      SCOPED_TRACE(testing::Message() << "density " << density << ", reach " << reach);
      const cv::Mat expected = by_distance(cells, reach);
      EXPECT_EQ(cv::countNonZero(wall_cells(cells, reach) != expected), 0);
      differing_radii += cv::countNonZero(expected != by_distance(cells, reach + 1.0)) > 0;
    }
  }
  EXPECT_GT(differing_radii, 10);  // the radii cut different discs: the comparison can fail
  // No occupied cell: no wall.
  EXPECT_EQ(cv::countNonZero(wall_cells(cv::Mat(20, 20, CV_8UC1, cv::Scalar(kFree)), 3.0)), 0);
}

}  // namespace
}  // namespace topocut
