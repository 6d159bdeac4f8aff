#include "topocut/core/geometry.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/cgal_geometry.h"
#include "topocut/core/error.h"
#include "topocut/core/occupancy_grid.h"

#include <cmath>

namespace topocut {
namespace {

TEST(Geometry, SignedAreaFollowsOrientation) {
  const Ring square{{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  EXPECT_DOUBLE_EQ(signed_area(square), 12.0);
  EXPECT_DOUBLE_EQ(signed_area(oriented(square, false)), -12.0);
}

TEST(Geometry, SignedAreaStaysExactFarFromTheOrigin) {
  // A 1 x 1 square at 1e9: the plain shoelace sum loses the whole area to cancellation.
  const double f = 1e9;
  const Ring square{{f, f}, {f + 1, f}, {f + 1, f + 1}, {f, f + 1}};
  EXPECT_DOUBLE_EQ(signed_area(square), 1.0);
}

TEST(Geometry, AreaAndCentroidSubtractHoles) {
  PolygonWithHoles p{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{0, 0}, {0, 5}, {5, 5}, {5, 0}}}};
  EXPECT_DOUBLE_EQ(area(p), 75.0);
  // Hand computation: (100*(5,5) - 25*(2.5,2.5)) / 75 = (5.8333.., 5.8333..).
  const Point2 c = centroid(p);
  EXPECT_NEAR(c.x, (500.0 - 62.5) / 75.0, 1e-12);
  EXPECT_NEAR(c.y, (500.0 - 62.5) / 75.0, 1e-12);
}

TEST(Geometry, PointsAddSubtractAndScaleAsVectors) {
  const Point2 a{1.0, 2.0}, b{3.0, -1.0};
  EXPECT_EQ(a + b, (Point2{4.0, 1.0}));
  EXPECT_EQ(a - b, (Point2{-2.0, 3.0}));
  EXPECT_EQ(2.0 * a, (Point2{2.0, 4.0}));
  EXPECT_EQ(a * 2.0, 2.0 * a);
  EXPECT_EQ(b / 2.0, (Point2{1.5, -0.5}));
  EXPECT_DOUBLE_EQ(dot(a, b), 1.0);  // 1 * 3 + 2 * -1
  EXPECT_DOUBLE_EQ(dot(a, Point2{-2.0, 1.0}), 0.0);
  EXPECT_DOUBLE_EQ(cross(a, b), -7.0);  // 1 * -1 - 2 * 3: b lies clockwise of a
  EXPECT_DOUBLE_EQ(cross(Point2{1.0, 0.0}, Point2{0.0, 1.0}), 1.0);
  EXPECT_DOUBLE_EQ(cross(b, a), -cross(a, b));
}

TEST(Geometry, NormalizedOrientationMatchesCgalConvention) {
  PolygonWithHoles p{{{0, 0}, {0, 10}, {10, 10}, {10, 0}}, {{{2, 2}, {4, 2}, {4, 4}, {2, 4}}}};
  const cgal::PolygonWithHoles c = cgal::to_cgal(normalized_orientation(p));
  EXPECT_TRUE(c.outer_boundary().is_counterclockwise_oriented());
  EXPECT_TRUE(c.holes_begin()->is_clockwise_oriented());
  EXPECT_EQ(cgal::from_cgal(c), normalized_orientation(p));
}

TEST(OccupancyGrid, CellCentresFollowRosConvention) {
  OccupancyGrid grid{cv::Mat(4, 6, CV_8UC1, cv::Scalar(kFree)), 0.5, {-1.0, 2.0}};
  const Point2 bottom_left = cell_center_world(grid, 0, 3);
  EXPECT_DOUBLE_EQ(bottom_left.x, -0.75);
  EXPECT_DOUBLE_EQ(bottom_left.y, 2.25);
  EXPECT_EQ(world_to_cell(grid, bottom_left), cv::Point(0, 3));
  const Point2 w = grid_to_world(grid, {5, 3});  // grid (5,3) = column 5, row 0
  EXPECT_EQ(w, cell_center_world(grid, 5, 0));
}

TEST(OccupancyGrid, CropKeepsEveryCellInItsWorldPlace) {
  OccupancyGrid grid{cv::Mat(5, 7, CV_8UC1), 0.5, {-1.0, 2.0}};
  cv::randu(grid.cells, 0, 256);
  const cv::Rect box(2, 1, 4, 3);
  OccupancyGrid part = crop(grid, box);
  ASSERT_EQ(part.cells.size(), box.size());
  EXPECT_EQ(part.resolution, grid.resolution);
  for (int r = 0; r < box.height; ++r) {
    for (int c = 0; c < box.width; ++c) {
      EXPECT_EQ(part.cells.at<unsigned char>(r, c), grid.cells.at<unsigned char>(r + box.y, c + box.x));
      const Point2 a = cell_center_world(part, c, r), b = cell_center_world(grid, c + box.x, r + box.y);
      EXPECT_NEAR(a.x, b.x, 1e-12);
      EXPECT_NEAR(a.y, b.y, 1e-12);
    }
  }
  part.cells.setTo(0);  // a copy, not a view
  EXPECT_NE(cv::countNonZero(grid.cells(box)), 0);
  EXPECT_THROW(crop(grid, cv::Rect(5, 0, 3, 2)), Error);  // beyond the right edge
  EXPECT_THROW(crop(grid, cv::Rect(0, 0, 0, 2)), Error);
}

TEST(OccupancyGrid, KnownBoxIsTheBoxOfTheKnownCells) {
  cv::RNG rng(3);
  for (int trial = 0; trial < 60; ++trial) {
    cv::Mat cells(rng.uniform(1, 90), rng.uniform(1, 150), CV_8UC1, cv::Scalar(kUnknown));
    for (int k = rng.uniform(0, 4); k > 0; --k) {
      const cv::Point p(rng.uniform(0, cells.cols), rng.uniform(0, cells.rows));
      cells(cv::Rect(p, cv::Size(rng.uniform(1, 30), rng.uniform(1, 30))) & cv::Rect(0, 0, cells.cols, cells.rows))
          .setTo(rng.uniform(0, 2) == 0 ? kFree : kOccupied);
    }
    EXPECT_EQ(known_box(cells), cv::boundingRect(cells != kUnknown)) << "trial " << trial;
  }
  EXPECT_TRUE(known_box(cv::Mat(3, 3, CV_8UC1, cv::Scalar(kUnknown))).empty());
}

TEST(OccupancyGrid, UncropPutsThePartBackAndFillsTheRest) {
  cv::Mat part(3, 4, CV_32SC1);
  cv::randu(part, 1, 1000);
  for (const cv::Rect box : {cv::Rect(2, 1, 4, 3), cv::Rect(0, 0, 4, 3), cv::Rect(5, 6, 4, 3)}) {
    const cv::Mat whole = uncrop(part, {9, 9}, box, -7);
    cv::Mat expected(9, 9, CV_32SC1, cv::Scalar(-7));
    part.copyTo(expected(box));
    EXPECT_EQ(cv::countNonZero(whole != expected), 0);
  }
  EXPECT_ANY_THROW(uncrop(part, {5, 5}, cv::Rect(2, 1, 4, 3), 0));
}

TEST(OccupancyGrid, ValidateRejectsBadResolution) {
  OccupancyGrid grid{cv::Mat(2, 2, CV_8UC1, cv::Scalar(kFree)), 0.0, {}};
  EXPECT_THROW(validate(grid), Error);
  grid.resolution = std::nan("");
  EXPECT_THROW(validate(grid), Error);
  grid.resolution = 0.05;
  EXPECT_NO_THROW(validate(grid));
  EXPECT_THROW(validate(OccupancyGrid{}), Error);
}

}  // namespace
}  // namespace topocut
