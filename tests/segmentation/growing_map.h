#pragma once
// A live map for tests of what an update changes: a floor of rooms along a corridor, revealed in a
// growing disc around a point and framed as a ROS map grows (the revealed box plus a margin, in
// steps of 20 cells: new size and origin), then left as it is, then with an obstacle seen in one room
// and a door closed.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/segmentation/incremental_segmenter.h"

namespace topocut::testing {

// 8 rooms of 44 x 100 cells above a corridor of 30 rows, 4-cell walls, doors of 16 cells.
inline OccupancyGrid rooms_along_a_corridor() {
  OccupancyGrid world;
  world.resolution = 0.05;
  world.origin = {-7.5, 2.0};
  world.cells = cv::Mat(150, 400, CV_8UC1, cv::Scalar(kOccupied));
  world.cells(cv::Rect(4, 112, 392, 30)).setTo(kFree);
  for (int i = 0; i < 8; ++i) {
    world.cells(cv::Rect(4 + 49 * i, 4, 45, 104)).setTo(kFree);
    world.cells(cv::Rect(4 + 49 * i + 14, 108, 16, 4)).setTo(kFree);
  }
  return world;
}

// world cropped to the disc of radius around centre (the rest unknown) and framed by the disc's box
// grown by 10 cells, in steps of chunk cells, within the world.
inline OccupancyGrid revealed(const OccupancyGrid& world, cv::Point centre, int radius, int chunk = 20) {
  const cv::Rect all(0, 0, world.width(), world.height());
  const int x0 = std::max(0, (centre.x - radius - 10) / chunk * chunk), y0 = std::max(0, (centre.y - radius - 10) / chunk * chunk);
  const int x1 = std::min(all.width, ((centre.x + radius + 10) / chunk + 1) * chunk);
  const int y1 = std::min(all.height, ((centre.y + radius + 10) / chunk + 1) * chunk);
  const cv::Rect box(x0, y0, x1 - x0, y1 - y0);
  cv::Mat disc(world.cells.size(), CV_8UC1, cv::Scalar(0));
  cv::circle(disc, centre, radius, cv::Scalar(255), cv::FILLED);
  OccupancyGrid out;
  out.resolution = world.resolution;
  out.cells = cv::Mat(box.size(), CV_8UC1, cv::Scalar(kUnknown));
  world.cells(box).copyTo(out.cells, disc(box));
  // Row 0 is the top: the origin (the lower-left corner) moves with the box's left and bottom.
  out.origin = {world.origin.x + box.x * world.resolution, world.origin.y + (world.height() - box.br().y) * world.resolution};
  return out;
}

// The sequence: the disc growing in steps of 15 cells until it holds the world, the whole world
// twice more (unchanged), an obstacle inside the third room, the first room's door closed.
inline std::vector<OccupancyGrid> growing_map_sequence() {
  const OccupancyGrid world = rooms_along_a_corridor();
  const cv::Point centre(180, 125);
  std::vector<OccupancyGrid> grids;
  for (int radius = 60; radius < 300; radius += 15) grids.push_back(revealed(world, centre, radius));
  grids.push_back(grids.back());
  grids.push_back(grids.back());
  OccupancyGrid last = grids.back();
  last.cells = last.cells.clone();
  last.cells(cv::Rect(4 + 49 * 2 + 20, 50, 3, 3)).setTo(kOccupied);
  grids.push_back(last);
  last.cells = last.cells.clone();
  last.cells(cv::Rect(4 + 14, 108, 16, 4)).setTo(kOccupied);
  grids.push_back(last);
  return grids;
}

// The ROS node's benchmark sequence (ros/test/node_test.py): world revealed around its free cell
// nearest the free cells' mean, the radius growing to the world's longer side in steps, the frame
// in chunks of 40 cells.
inline std::vector<OccupancyGrid> node_sequence(const OccupancyGrid& world, int steps) {
  cv::Mat free = world.cells == kFree;
  const cv::Moments m = cv::moments(free, true);
  const cv::Point mean(static_cast<int>(m.m10 / m.m00), static_cast<int>(m.m01 / m.m00));
  cv::Point centre = mean;
  long long best = -1;
  for (int r = 0; r < free.rows; ++r)
    for (int c = 0; c < free.cols; ++c) {
      if (!free.at<unsigned char>(r, c)) continue;
      const long long d = static_cast<long long>(c - mean.x) * (c - mean.x) + static_cast<long long>(r - mean.y) * (r - mean.y);
      if (best < 0 || d < best) best = d, centre = {c, r};
    }
  std::vector<OccupancyGrid> grids;
  const int longest = std::max(world.width(), world.height());
  for (int k = 1; k <= steps; ++k) grids.push_back(revealed(world, centre, longest * k / steps, 40));
  return grids;
}

// The report's promise, checked cell by cell against the previous labels moved by its shift: a room
// it does not list has the same cells, and the listed ones lie in its box.
inline void expect_relabelled_rooms_listed(const cv::Mat& before, const Segmentation& after, const IncrementalUpdateReport& report,
                                    std::size_t step) {
  const std::vector<int>& listed = report.relabelled_rooms;
  const auto is_listed = [&](int id) { return std::binary_search(listed.begin(), listed.end(), id); };
  ASSERT_TRUE(std::is_sorted(listed.begin(), listed.end()));
  int missed = 0, outside_box = 0;
  for (int r = 0; r < after.labels.rows; ++r)
    for (int c = 0; c < after.labels.cols; ++c) {
      const cv::Point old = cv::Point(c, r) - report.shift;
      const int was = cv::Rect(0, 0, before.cols, before.rows).contains(old) ? before.at<int>(old) : 0;
      const int is = after.labels.at<int>(r, c);
      if (is > 0 && is_listed(is) && !report.relabelled_box.contains({c, r})) ++outside_box;
      if (was == is) continue;
      missed += (was > 0 && !is_listed(was)) + (is > 0 && !is_listed(is));
    }
  EXPECT_EQ(missed, 0) << "step " << step;
  EXPECT_EQ(outside_box, 0) << "step " << step;
}

}  // namespace topocut::testing
