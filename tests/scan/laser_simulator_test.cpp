#include "topocut/scan/laser_simulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "topocut/core/error.h"

namespace topocut {
namespace {

constexpr double kPi = std::numbers::pi;

// A 4 m x 4 m square room centred on the origin; walls 0..3 = south, east, north, west.
std::vector<Segment2> square_room() {
  return {{{-2, -2}, {2, -2}}, {{2, -2}, {2, 2}}, {{2, 2}, {-2, 2}}, {{-2, 2}, {-2, -2}}};
}

TEST(BeamAngles, CountsFollowFieldOfViewAndResolution) {
  LaserSpec spec;
  spec.field_of_view = 270.0 * kPi / 180.0;
  spec.angular_resolution = 0.6 * kPi / 180.0;
  const auto a = beam_angles(spec);
  ASSERT_EQ(a.size(), 451u);
  EXPECT_NEAR(a.front(), -135.0 * kPi / 180.0, 1e-12);
  EXPECT_NEAR(a.back(), 135.0 * kPi / 180.0, 1e-12);
  spec.field_of_view = 2 * kPi;
  spec.angular_resolution = kPi / 360.0;
  const auto full = beam_angles(spec);
  ASSERT_EQ(full.size(), 720u);  // no duplicate beam at +pi
  EXPECT_NEAR(full.front(), -kPi, 1e-12);
  EXPECT_NEAR(full.back(), kPi - kPi / 360.0, 1e-12);
}

TEST(BeamAngles, RejectsBadSpecs) {
  LaserSpec spec;
  spec.angular_resolution = 0.0;
  EXPECT_THROW(beam_angles(spec), Error);
  spec = LaserSpec{};
  spec.field_of_view = 7.0;
  EXPECT_THROW(beam_angles(spec), Error);
  spec = LaserSpec{};
  spec.range_max = -1.0;
  EXPECT_THROW(beam_angles(spec), Error);
}

TEST(SegmentSimulator, RangesMatchHandGeometry) {
  LaserSpec spec;
  spec.field_of_view = 2 * kPi;
  spec.angular_resolution = kPi / 180.0;  // 1 degree, beam i at -180 + i degrees
  spec.range_max = 10.0;
  const Pose2 pose{0.5, 0.0, 0.0};
  const SimulatedScan s = simulate_scan(square_room(), pose, spec);
  ASSERT_EQ(s.scan.size(), 360u);
  // Beam 180 looks along +x: east wall at distance 1.5.
  EXPECT_NEAR(s.scan.ranges[180], 1.5, 1e-12);
  EXPECT_EQ(s.hit[180], 1);
  // Beam 0 looks along -x: west wall at 2.5.
  EXPECT_NEAR(s.scan.ranges[0], 2.5, 1e-12);
  EXPECT_EQ(s.hit[0], 3);
  // Beam 210 (30 degrees): east wall at 1.5 / cos 30.
  EXPECT_NEAR(s.scan.ranges[210], 1.5 / std::cos(kPi / 6), 1e-12);
  // Beam 270 (90 degrees): north wall at 2.
  EXPECT_NEAR(s.scan.ranges[270], 2.0, 1e-12);
  EXPECT_EQ(s.hit[270], 2);
  for (std::size_t i = 0; i < s.scan.size(); ++i) EXPECT_TRUE(s.scan.is_valid(i));
}

TEST(SegmentSimulator, PoseRotatesTheBeamsAndRangeMaxCuts) {
  LaserSpec spec;
  spec.field_of_view = kPi;
  spec.angular_resolution = kPi / 2;  // beams at -90, 0, +90 degrees
  spec.range_max = 1.9;
  const SimulatedScan s = simulate_scan(square_room(), {0.0, 0.5, kPi / 2}, spec);
  ASSERT_EQ(s.scan.size(), 3u);
  // Heading north: beam 0 looks east (2.0 > range_max: no return), beam 1 north (1.5), beam 2 west.
  EXPECT_TRUE(std::isinf(s.scan.ranges[0]));
  EXPECT_EQ(s.hit[0], -1);
  EXPECT_NEAR(s.scan.ranges[1], 1.5, 1e-12);
  EXPECT_EQ(s.hit[1], 2);
  EXPECT_TRUE(std::isinf(s.scan.ranges[2]));
  EXPECT_FALSE(s.scan.is_valid(0));
}

TEST(SegmentSimulator, NoiseIsSeededAndHasTheRequestedSpread) {
  LaserSpec spec;
  spec.field_of_view = 2 * kPi;
  spec.angular_resolution = kPi / 1800.0;  // 3600 beams
  spec.range_max = 10.0;
  spec.noise_stddev = 0.05;
  spec.seed = 7;
  const SimulatedScan clean = [&] {
    LaserSpec c = spec;
    c.noise_stddev = 0.0;
    return simulate_scan(square_room(), {}, c);
  }();
  const SimulatedScan a = simulate_scan(square_room(), {}, spec);
  const SimulatedScan b = simulate_scan(square_room(), {}, spec);
  EXPECT_EQ(a.scan.ranges, b.scan.ranges);
  spec.seed = 8;
  EXPECT_NE(simulate_scan(square_room(), {}, spec).scan.ranges, a.scan.ranges);
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < a.scan.size(); ++i) {
    const double e = a.scan.ranges[i] - clean.scan.ranges[i];
    sum += e;
    sum2 += e * e;
  }
  const double n = static_cast<double>(a.scan.size());
  // 3600 samples: the mean is within 4 standard errors (0.05/60) of 0, the std within 10 % of 0.05.
  EXPECT_NEAR(sum / n, 0.0, 4 * 0.05 / 60.0);
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.05, 0.005);
}

OccupancyGrid empty_grid(int width, int height, double resolution) {
  return {cv::Mat(height, width, CV_8UC1, cv::Scalar(kFree)), resolution, {0.0, 0.0}};
}

TEST(GridSimulator, RangeIsDistanceToTheFirstOccupiedCellBoundary) {
  OccupancyGrid grid = empty_grid(10, 10, 0.1);
  grid.cells.col(8).setTo(kOccupied);  // world x in [0.8, 0.9]
  LaserSpec spec;
  spec.field_of_view = kPi / 2;
  spec.angular_resolution = kPi / 12;  // -45, -30, ..., +45 degrees
  spec.range_max = 5.0;
  const Pose2 pose{0.25, 0.55, 0.0};
  const SimulatedScan s = simulate_scan(grid, pose, spec);
  ASSERT_EQ(s.scan.size(), 7u);
  for (std::size_t i = 0; i < s.scan.size(); ++i) {
    const double a = s.scan.angles[i];
    const double y_hit = 0.55 + std::tan(a) * 0.55;
    if (y_hit >= 0.0 && y_hit <= 1.0) {
      EXPECT_NEAR(s.scan.ranges[i], 0.55 / std::cos(a), 1e-9) << "beam " << i;
      const int row = 9 - static_cast<int>(std::floor(y_hit / 0.1));
      EXPECT_EQ(s.hit[i], row * 10 + 8) << "beam " << i;
    } else {
      EXPECT_TRUE(std::isinf(s.scan.ranges[i])) << "beam " << i;  // leaves the grid
      EXPECT_EQ(s.hit[i], -1);
    }
  }
}

TEST(GridSimulator, UnknownCellsBlockOnlyOnRequest) {
  OccupancyGrid grid = empty_grid(10, 3, 0.5);
  grid.cells.at<unsigned char>(1, 4) = kUnknown;
  grid.cells.at<unsigned char>(1, 7) = kOccupied;
  LaserSpec spec;
  spec.field_of_view = 2 * kPi;
  spec.angular_resolution = kPi;  // beams at -180 and 0 degrees
  spec.range_max = 10.0;
  const Pose2 pose{0.25, 0.75, 0.0};
  EXPECT_NEAR(simulate_scan(grid, pose, spec).scan.ranges[1], 3.25, 1e-12);
  spec.unknown_blocks = true;
  EXPECT_NEAR(simulate_scan(grid, pose, spec).scan.ranges[1], 1.75, 1e-12);
}

TEST(GridSimulator, PoseInsideAWallOrOutsideTheGrid) {
  OccupancyGrid grid = empty_grid(10, 10, 0.1);
  grid.cells.col(5).setTo(kOccupied);
  LaserSpec spec;
  spec.field_of_view = 2 * kPi;
  spec.angular_resolution = kPi;  // beams at -180 and 0 degrees
  spec.range_max = 5.0;
  const SimulatedScan inside = simulate_scan(grid, {0.55, 0.5, 0.0}, spec);
  EXPECT_EQ(inside.scan.ranges[0], 0.0);
  EXPECT_EQ(inside.scan.ranges[1], 0.0);
  EXPECT_FALSE(inside.scan.is_valid(1));
  // From 1 m left of the grid, looking in: the wall's left face is at x = 0.5.
  const SimulatedScan outside = simulate_scan(grid, {-1.0, 0.52, 0.0}, spec);
  EXPECT_NEAR(outside.scan.ranges[1], 1.5, 1e-12);
  // Looking away from the grid: nothing.
  EXPECT_TRUE(std::isinf(outside.scan.ranges[0]));
  EXPECT_EQ(outside.hit[0], -1);
}

TEST(GridSimulator, AgreesWithSegmentSimulatorOnARasterisedRoom) {
  // Room interior x,y in [0.5, 4.5] m; walls are the one-cell ring around it (res 0.05).
  const double res = 0.05;
  OccupancyGrid grid = empty_grid(100, 100, res);
  for (int r = 0; r < 100; ++r)
    for (int c = 0; c < 100; ++c) {
      const bool ring = (c == 9 || c == 90) && r >= 9 && r <= 90;
      const bool ring2 = (r == 9 || r == 90) && c >= 9 && c <= 90;
      if (ring || ring2) grid.cells.at<unsigned char>(r, c) = kOccupied;
    }
  const std::vector<Segment2> walls{{{0.5, 0.5}, {4.5, 0.5}}, {{4.5, 0.5}, {4.5, 4.5}},
                                    {{4.5, 4.5}, {0.5, 4.5}}, {{0.5, 4.5}, {0.5, 0.5}}};
  LaserSpec spec;
  spec.range_max = 10.0;
  const Pose2 pose{1.7, 2.9, 0.4};
  const SimulatedScan g = simulate_scan(grid, pose, spec);
  const SimulatedScan s = simulate_scan(walls, pose, spec);
  ASSERT_EQ(g.scan.size(), s.scan.size());
  for (std::size_t i = 0; i < g.scan.size(); ++i) EXPECT_NEAR(g.scan.ranges[i], s.scan.ranges[i], 1e-9) << i;
}

}  // namespace
}  // namespace topocut
