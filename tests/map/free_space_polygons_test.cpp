#include "topocut/map/free_space_polygons.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/cgal_geometry.h"
#include "topocut/core/error.h"
#include "topocut/map/rasterize.h"

namespace topocut {
namespace {

cv::Mat blank(int rows, int cols) { return cv::Mat::zeros(rows, cols, CV_8UC1); }

ContourOptions keep_everything() {
  ContourOptions options;
  options.min_component_area = 0.0;
  options.min_hole_area = 0.0;
  return options;
}

// Every ring simple in CGAL, outer CCW, holes CW, no collinear vertices, vertices on half-integers.
void expect_valid(const PolygonWithHoles& polygon) {
  const cgal::PolygonWithHoles p = cgal::to_cgal(polygon);
  ASSERT_TRUE(p.outer_boundary().is_simple());
  EXPECT_TRUE(p.outer_boundary().is_counterclockwise_oriented());
  for (auto hole = p.holes_begin(); hole != p.holes_end(); ++hole) {
    ASSERT_TRUE(hole->is_simple());
    EXPECT_TRUE(hole->is_clockwise_oriented());
  }
  for (const Ring* ring : [&] {
         std::vector<const Ring*> rings{&polygon.outer};
         for (const Ring& h : polygon.holes) rings.push_back(&h);
         return rings;
       }()) {
    EXPECT_EQ(remove_collinear_vertices(*ring).size(), ring->size());
    for (const Point2& v : *ring) {
      EXPECT_EQ(v.x - std::floor(v.x), 0.5);
      EXPECT_EQ(v.y - std::floor(v.y), 0.5);
    }
  }
}

TEST(FreeSpacePolygons, RectangleFollowsThePixelEdges) {
  cv::Mat mask = blank(4, 5);
  mask(cv::Rect(1, 1, 3, 2)).setTo(255);  // columns 1..3, rows 1..2
  const FreeSpacePolygons result = free_space_polygons(mask, 0.05, keep_everything());
  ASSERT_EQ(result.components.size(), 1u);
  const PolygonWithHoles& p = result.components[0].polygon;
  expect_valid(p);
  // Grid y = 3 - row: rows 1..2 are y 2..1, so edges at y 0.5 and 2.5; columns 1..3 give x 0.5..3.5.
  const std::set<std::pair<double, double>> corners(
      {{0.5, 0.5}, {3.5, 0.5}, {3.5, 2.5}, {0.5, 2.5}});
  ASSERT_EQ(p.outer.size(), 4u);
  for (const Point2& v : p.outer) EXPECT_TRUE(corners.count({v.x, v.y})) << v.x << "," << v.y;
  EXPECT_DOUBLE_EQ(area(p), 6.0);
  EXPECT_EQ(result.components[0].pixel_count, 6);
  EXPECT_EQ(result.components[0].first_pixel, cv::Point(1, 1));
}

TEST(FreeSpacePolygons, HolesAreCountedAndAreaIsThePixelCount) {
  cv::Mat mask = blank(20, 30);
  mask(cv::Rect(1, 1, 28, 18)).setTo(255);
  mask(cv::Rect(5, 5, 4, 3)).setTo(0);     // a table
  mask(cv::Rect(15, 8, 2, 6)).setTo(0);    // a shelf
  mask(cv::Rect(20, 3, 3, 3)).setTo(0);    // a box, with a free cell inside (an island)
  mask.at<unsigned char>(4, 21) = 255;
  const FreeSpacePolygons result = free_space_polygons(mask, 0.05, keep_everything());
  ASSERT_EQ(result.components.size(), 2u);  // the room and the island
  const PolygonWithHoles& room = result.components[0].polygon;
  expect_valid(room);
  EXPECT_EQ(room.holes.size(), 3u);
  EXPECT_DOUBLE_EQ(area(room), 28.0 * 18 - 12 - 12 - 9);
  EXPECT_DOUBLE_EQ(area(result.components[1].polygon), 1.0);
  EXPECT_EQ(result.components[1].first_pixel, cv::Point(21, 4));
}

TEST(FreeSpacePolygons, SmallHolesAreFilledUnlessTheyHoldIslands) {
  cv::Mat mask = blank(30, 30);
  mask(cv::Rect(1, 1, 28, 28)).setTo(255);
  mask(cv::Rect(5, 5, 2, 2)).setTo(0);  // 4 cells = 0.01 m² at 0.05 m: below 0.0125 m²
  mask(cv::Rect(12, 5, 3, 2)).setTo(0); // 6 cells = 0.015 m²: kept
  mask(cv::Rect(20, 20, 3, 3)).setTo(0);
  mask.at<unsigned char>(21, 21) = 255;  // 8-cell hole around a one-cell island
  ContourOptions options;
  options.min_component_area = 0.0;
  options.min_hole_area = 0.0125;
  FreeSpacePolygons result = free_space_polygons(mask, 0.05, options);
  ASSERT_EQ(result.components.size(), 2u);
  EXPECT_EQ(result.components[0].polygon.holes.size(), 2u);
  EXPECT_EQ(result.dropped_holes, 1);
  options.min_hole_area = 1.0;  // drops every hole except the one holding the island
  result = free_space_polygons(mask, 0.05, options);
  ASSERT_EQ(result.components[0].polygon.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(std::abs(signed_area(result.components[0].polygon.holes[0])), 9.0);
}

TEST(FreeSpacePolygons, DiagonalPinchesGiveSimpleRings) {
  // Two 3x3 rooms touching at one corner, and a loop closed only by a diagonal contact.
  cv::Mat mask = blank(12, 16);
  mask(cv::Rect(1, 1, 3, 3)).setTo(255);
  mask(cv::Rect(4, 4, 3, 3)).setTo(255);
  mask(cv::Rect(9, 1, 5, 1)).setTo(255);   // loop: top
  mask(cv::Rect(9, 1, 1, 6)).setTo(255);   //       left
  mask(cv::Rect(13, 1, 1, 5)).setTo(255);  //       right, ending one row short
  mask(cv::Rect(10, 6, 3, 1)).setTo(255);  //       bottom, touching the right side only diagonally
  int removed = 0;
  const cv::Mat pinch_free = remove_diagonal_pinches(mask, &removed);
  EXPECT_EQ(removed, 2);
  // No checkerboard 2x2 block is left.
  for (int r = 0; r + 1 < pinch_free.rows; ++r)
    for (int c = 0; c + 1 < pinch_free.cols; ++c) {
      const bool a = pinch_free.at<unsigned char>(r, c), b = pinch_free.at<unsigned char>(r, c + 1);
      const bool d = pinch_free.at<unsigned char>(r + 1, c), e = pinch_free.at<unsigned char>(r + 1, c + 1);
      EXPECT_FALSE(a == e && b == d && a != b) << r << "," << c;
    }
  const FreeSpacePolygons result = free_space_polygons(mask, 0.05, keep_everything());
  EXPECT_EQ(result.pinch_cells, 2);
  double total = 0.0;
  for (const FreeSpaceComponent& c : result.components) {
    expect_valid(c.polygon);
    total += area(c.polygon);
  }
  EXPECT_DOUBLE_EQ(total, cv::countNonZero(mask) - 2.0);
}

TEST(FreeSpacePolygons, OnePixelComponentsAndBorderTouchingFreeSpace) {
  cv::Mat mask(6, 7, CV_8UC1, cv::Scalar(255));  // all free, touching every border
  mask.at<unsigned char>(2, 3) = 0;
  FreeSpacePolygons result = free_space_polygons(mask, 0.05, keep_everything());
  ASSERT_EQ(result.components.size(), 1u);
  expect_valid(result.components[0].polygon);
  EXPECT_EQ(result.components[0].polygon.outer.size(), 4u);
  EXPECT_EQ(result.components[0].polygon.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(area(result.components[0].polygon), 41.0);
  // The outer ring is the image's own border: x from -0.5 to 6.5, y from -0.5 to 5.5.
  for (const Point2& v : result.components[0].polygon.outer) {
    EXPECT_TRUE(v.x == -0.5 || v.x == 6.5) << v.x;
    EXPECT_TRUE(v.y == -0.5 || v.y == 5.5) << v.y;
  }

  cv::Mat dot = blank(3, 3);
  dot.at<unsigned char>(0, 0) = 255;  // one free cell in a corner
  result = free_space_polygons(dot, 0.05, keep_everything());
  ASSERT_EQ(result.components.size(), 1u);
  expect_valid(result.components[0].polygon);
  EXPECT_DOUBLE_EQ(area(result.components[0].polygon), 1.0);
  EXPECT_EQ(result.components[0].polygon.outer.size(), 4u);
}

TEST(FreeSpacePolygons, SmallComponentsAreDroppedButNeverAll) {
  cv::Mat mask = blank(40, 40);
  mask(cv::Rect(1, 1, 20, 20)).setTo(255);  // 400 cells = 1 m²
  mask(cv::Rect(30, 30, 5, 5)).setTo(255);  // 25 cells = 0.0625 m²
  FreeSpacePolygons result = free_space_polygons(mask, 0.05);  // default 0.25 m²
  ASSERT_EQ(result.components.size(), 1u);
  EXPECT_EQ(result.dropped_components, 1);
  EXPECT_EQ(result.kept_cells, 400);
  cv::Mat tiny = blank(10, 10);
  tiny(cv::Rect(1, 1, 2, 2)).setTo(255);
  tiny(cv::Rect(5, 5, 3, 3)).setTo(255);
  result = free_space_polygons(tiny, 0.05);
  ASSERT_EQ(result.components.size(), 1u);  // the largest survives
  EXPECT_EQ(result.components[0].pixel_count, 9);
}

TEST(FreeSpacePolygons, AgreesWithFindContoursAndRasterizesBackOnRandomMasks) {
  cv::RNG rng(12345);
  for (int trial = 0; trial < 40; ++trial) {
    cv::Mat noise(40 + trial, 50, CV_8UC1);
    rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
    cv::Mat mask = noise > (trial % 2 ? 100 : 150);
    if (trial % 3 == 0) cv::medianBlur(mask, mask, 3);  // blobs with holes as well as salt
    const cv::Mat pinch_free = remove_diagonal_pinches(mask);
    const FreeSpacePolygons result = free_space_polygons(mask, 0.05, keep_everything());
    std::vector<PolygonWithHoles> polygons;
    std::size_t holes = 0;
    double total = 0.0;
    for (const FreeSpaceComponent& c : result.components) {
      expect_valid(c.polygon);
      EXPECT_DOUBLE_EQ(area(c.polygon), c.pixel_count);
      polygons.push_back(c.polygon);
      holes += c.polygon.holes.size();
      total += area(c.polygon);
    }
    EXPECT_DOUBLE_EQ(total, cv::countNonZero(pinch_free));
    // OpenCV's two-level hierarchy sees the same components and holes on the pinch-free mask.
    std::vector<std::vector<cv::Point>> contours;
    std::vector<cv::Vec4i> hierarchy;
    cv::findContours(pinch_free.clone(), contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
    std::size_t outer = 0, inner = 0;
    for (const cv::Vec4i& h : hierarchy) (h[3] < 0 ? outer : inner)++;
    EXPECT_EQ(outer, result.components.size());
    EXPECT_EQ(inner, holes);
    // The polygons cover exactly the pinch-free cells, each by its own component.
    const cv::Mat labels = rasterize_polygons(polygons, mask.size());
    EXPECT_EQ(cv::countNonZero((labels > 0) != (pinch_free > 0)), 0) << "trial " << trial;
  }
}

TEST(FreeSpacePolygons, RemoveCollinearVertices) {
  const Ring ring{{0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 1}, {2, 2}, {0, 2}, {0, 1}};
  const Ring expected{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_EQ(remove_collinear_vertices(ring), expected);
}

TEST(FreeSpacePolygons, BadInput) {
  EXPECT_THROW(free_space_polygons(cv::Mat(), 0.05), Error);
  EXPECT_THROW(free_space_polygons(cv::Mat(3, 3, CV_32F, cv::Scalar(1)), 0.05), Error);
  EXPECT_THROW(free_space_polygons(blank(3, 3), 0.0), Error);
  EXPECT_TRUE(free_space_polygons(blank(3, 3), 0.05).components.empty());
}

}  // namespace
}  // namespace topocut
