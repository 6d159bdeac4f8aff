#include "topocut/io/grid_from_array.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "topocut/core/error.h"

namespace topocut {
namespace {

// A 3 x 2 occupancy array in ROS row order: row 0 (the bottom) is free, free, unknown.
GridArray ros_array(const std::vector<std::int8_t>& values) {
  GridArray a;
  a.data = values.data();
  a.width = 3;
  a.height = 2;
  a.resolution = 0.1;
  a.origin = {1.0, 2.0, 0.0};
  return a;
}

TEST(GridFromArray, OccupancyUsesMapServerThresholdsAndFlipsRosRows) {
  // 19 % < 19.6 % is free, 20 % is between the thresholds, 66 % > 65 % occupied, -1 unknown.
  const std::vector<std::int8_t> values = {0, 19, -1, 20, 66, 100};
  const OccupancyGrid grid = grid_from_array(ros_array(values));
  ASSERT_EQ(grid.width(), 3);
  ASSERT_EQ(grid.height(), 2);
  // Bottom-up row 0 is the grid's last (bottom) row.
  EXPECT_EQ(grid.cells.at<unsigned char>(1, 0), kFree);
  EXPECT_EQ(grid.cells.at<unsigned char>(1, 1), kFree);
  EXPECT_EQ(grid.cells.at<unsigned char>(1, 2), kUnknown);
  EXPECT_EQ(grid.cells.at<unsigned char>(0, 0), kUnknown);
  EXPECT_EQ(grid.cells.at<unsigned char>(0, 1), kOccupied);
  EXPECT_EQ(grid.cells.at<unsigned char>(0, 2), kOccupied);
  EXPECT_DOUBLE_EQ(grid.resolution, 0.1);
  EXPECT_DOUBLE_EQ(grid.origin.x, 1.0);
  EXPECT_DOUBLE_EQ(grid.origin.y, 2.0);
}

TEST(GridFromArray, TopDownKeepsRowsAndThresholdsAreTheCallers) {
  const std::vector<std::int8_t> values = {0, 30, 70, 0, 0, 0};
  GridArray a = ros_array(values);
  a.row_order = RowOrder::kTopDown;
  a.free_thresh = 0.35;
  a.occupied_thresh = 0.8;
  const OccupancyGrid grid = grid_from_array(a);
  EXPECT_EQ(grid.cells.at<unsigned char>(0, 1), kFree);     // 30 % < 35 %
  EXPECT_EQ(grid.cells.at<unsigned char>(0, 2), kUnknown);  // 70 % between
}

TEST(GridFromArray, EveryOccupancyValueFollowsTheMapServerRule) {
  // All 102 values in one row, under several threshold pairs: p = value / 100 above occupied_thresh
  // is occupied, below free_thresh free, between (or -1) unknown, as map_server reads raw maps.
  std::vector<std::int8_t> values;
  for (int v = -1; v <= 100; ++v) values.push_back(static_cast<std::int8_t>(v));
  for (const auto& [free_thresh, occupied_thresh] : {std::pair{0.196, 0.65}, std::pair{0.0, 1.0}, std::pair{0.5, 0.5},
                                                     std::pair{0.25, 0.251}, std::pair{0.999, 0.999}}) {
    GridArray a;
    a.data = values.data();
    a.width = static_cast<int>(values.size());
    a.height = 1;
    a.resolution = 0.05;
    a.free_thresh = free_thresh;
    a.occupied_thresh = occupied_thresh;
    const OccupancyGrid grid = grid_from_array(a);
    for (int c = 0; c < a.width; ++c) {
      const int v = values[static_cast<std::size_t>(c)];
      const double p = v / 100.0;
      const unsigned char expected = v < 0 ? kUnknown : p > occupied_thresh ? kOccupied : p < free_thresh ? kFree : kUnknown;
      EXPECT_EQ(grid.cells.at<unsigned char>(0, c), expected) << "value " << v << ", thresholds " << free_thresh << " / "
                                                               << occupied_thresh;
    }
  }
}

TEST(GridFromArray, GreyUsesThePlainImageRuleAndStrides) {
  // Two rows of 2 cells stored 4 bytes apart (a view of a wider buffer).
  const std::vector<unsigned char> values = {255, 0, 9, 9, 128, 251, 9, 9};
  GridArray a;
  a.data = values.data();
  a.width = 2;
  a.height = 2;
  a.row_stride = 4;
  a.encoding = CellEncoding::kGrey;
  a.row_order = RowOrder::kTopDown;
  const OccupancyGrid grid = grid_from_array(a);
  EXPECT_EQ(grid.cells.at<unsigned char>(0, 0), kFree);
  EXPECT_EQ(grid.cells.at<unsigned char>(0, 1), kOccupied);
  EXPECT_EQ(grid.cells.at<unsigned char>(1, 0), kUnknown);
  EXPECT_EQ(grid.cells.at<unsigned char>(1, 1), kFree);
  // A negative stride walks the same buffer upwards from the last row.
  a.data = values.data() + 4;
  a.row_stride = -4;
  const OccupancyGrid reversed = grid_from_array(a);
  EXPECT_EQ(reversed.cells.at<unsigned char>(0, 0), kUnknown);
  EXPECT_EQ(reversed.cells.at<unsigned char>(1, 1), kOccupied);
}

TEST(GridFromArray, BadInputIsOneError) {
  const std::vector<std::int8_t> values = {0, 0, 0, 0, 0, 0};
  const auto throws = [](GridArray a) { EXPECT_THROW(grid_from_array(a), Error); };
  GridArray a = ros_array(values);
  a.width = 0;
  throws(a);
  a = ros_array(values);
  a.data = nullptr;
  throws(a);
  a = ros_array(values);
  a.resolution = std::numeric_limits<double>::quiet_NaN();
  throws(a);
  a.resolution = -0.05;
  throws(a);
  a = ros_array(values);
  a.row_stride = 2;  // rows would overlap
  throws(a);
  a = ros_array(values);
  a.origin.yaw = std::numeric_limits<double>::infinity();
  throws(a);
  a = ros_array(values);
  a.free_thresh = 0.9;  // above occupied_thresh
  throws(a);
  const std::vector<std::int8_t> out_of_range = {0, 0, 0, 0, 101, 0};
  try {
    grid_from_array(ros_array(out_of_range));
    FAIL() << "101 % was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("101"), std::string::npos) << e.what();
  }
  const std::vector<std::int8_t> negative = {0, -2, 0, 0, 0, 0};
  EXPECT_THROW(grid_from_array(ros_array(negative)), Error);
}

}  // namespace
}  // namespace topocut
