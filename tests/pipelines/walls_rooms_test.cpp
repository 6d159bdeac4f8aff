// Pipeline C's grid segmented into rooms (pipeline A): the join `topocut walls --segment` makes.
#include <algorithm>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "topocut/segmentation/segmenter.h"
#include "topocut/walls/walls_pipeline.h"
#include "walls/simulated_run.h"

namespace topocut {
namespace {

using test::simulated_run;

TEST(WallsPipeline, SimulatedRunSegmentsIntoItsRooms) {
  // Two rooms (6 m and 8 m wide, 8 m deep) joined by a 1 m door near the top, so that the wall stub
  // from the bottom (6 m) is deeper than the concavity limit (2.5 m); scans from both rooms.
  const std::vector<Segment2> plan{{{0, 0}, {14, 0}}, {{14, 0}, {14, 8}}, {{14, 8}, {0, 8}}, {{0, 8}, {0, 0}},
                                   {{6, 0}, {6, 6}},  {{6, 7}, {6, 8}}};
  const auto scans = simulated_run(plan, {{3, 4, 0.0}, {1, 1, 1.0}, {2, 7, -1.0}, {10, 4, 3.0}, {8, 7, -1.0},
                                          {12, 1, 2.0}});
  const WallsResult result = walls_from_scans(scans);
  SegmentOptions options;
  options.binarize.opening_size = 0.15;
  const Segmentation rooms = segment(result.grid, options);
  ASSERT_EQ(rooms.rooms.size(), 2u);
  // Left to right: centroids near the rooms' centres, areas within 10 % of the plan (48 and 64 m²).
  std::vector<std::pair<double, double>> by_x;
  for (const Room& r : rooms.rooms) by_x.emplace_back(r.centroid.x, r.area);
  std::sort(by_x.begin(), by_x.end());
  EXPECT_NEAR(by_x[0].first, 3.0, 0.3);
  EXPECT_NEAR(by_x[1].first, 10.0, 0.3);
  EXPECT_NEAR(by_x[0].second, 48.0, 4.8);
  EXPECT_NEAR(by_x[1].second, 64.0, 6.4);
  EXPECT_EQ(rooms.passages.size(), 1u);
}

TEST(WallsPipeline, SimulatedRunOfThreeRoomsInARow) {
  // Three rooms (4 m, 6 m and 4 m wide, 8 m deep) joined by 1 m doors near the top.
  const std::vector<Segment2> plan{{{0, 0}, {14, 0}}, {{14, 0}, {14, 8}}, {{14, 8}, {0, 8}}, {{0, 8}, {0, 0}},
                                   {{4, 0}, {4, 6}},  {{4, 7}, {4, 8}},   {{10, 0}, {10, 6}}, {{10, 7}, {10, 8}}};
  const auto scans = simulated_run(plan, {{2, 4, 0.0}, {1, 1, 1.0}, {2, 7, -1.0}, {7, 4, 0.0}, {6, 7, -1.0},
                                          {8, 1, 2.0}, {12, 4, 3.0}, {13, 7, -2.0}, {12, 1, 2.0}});
  SegmentOptions options;
  options.binarize.opening_size = 0.15;
  const Segmentation rooms = segment(walls_from_scans(scans).grid, options);
  ASSERT_EQ(rooms.rooms.size(), 3u);
  std::vector<std::pair<double, double>> by_x;
  for (const Room& r : rooms.rooms) by_x.emplace_back(r.centroid.x, r.area);
  std::sort(by_x.begin(), by_x.end());
  const double centre[3] = {2.0, 7.0, 12.0}, area[3] = {32.0, 48.0, 32.0};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(by_x[i].first, centre[i], 0.3);
    EXPECT_NEAR(by_x[i].second, area[i], 0.1 * area[i]);
  }
  EXPECT_EQ(rooms.passages.size(), 2u);
}

}  // namespace
}  // namespace topocut
