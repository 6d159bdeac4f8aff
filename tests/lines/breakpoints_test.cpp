#include "topocut/lines/breakpoints.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "topocut/core/error.h"
#include "topocut/scan/laser_simulator.h"

namespace topocut {
namespace {

constexpr double kPi = std::numbers::pi;

LaserSpec front_laser(double noise, std::uint32_t seed = 0) {
  LaserSpec spec;
  spec.field_of_view = kPi / 2;
  spec.angular_resolution = kPi / 1440.0;  // 0.125 degrees: 721 beams
  spec.range_max = 20.0;
  spec.noise_stddev = noise;
  spec.seed = seed;
  return spec;
}

TEST(RangeNoise, EstimatesTheSimulatedNoise) {
  const std::vector<Segment2> wall{{{2.0, -10.0}, {2.0, 10.0}}};
  for (const double sigma : {0.01, 0.03, 0.05}) {
    const double estimate = estimate_range_noise(simulate_scan(wall, {}, front_laser(sigma, 5)).scan);
    EXPECT_NEAR(estimate, sigma, 0.15 * sigma) << sigma;
  }
  // Noiseless: only the wall's curvature in range (second differences ~1e-5 m here).
  EXPECT_LT(estimate_range_noise(simulate_scan(wall, {}, front_laser(0.0)).scan), 1e-4);
  EXPECT_EQ(estimate_range_noise(Scan{{0.0, 0.1}, {1.0, 1.0}}), 0.0);
}

// Two beams 0.01 rad apart, the first at 2 m, the second placed so the points are `gap` apart.
Scan two_beams(double gap) {
  const double dphi = 0.01;
  const double r1 = 2.0 * std::cos(dphi) + std::sqrt(gap * gap - 4.0 * std::sin(dphi) * std::sin(dphi));
  return Scan{{0.0, dphi}, {2.0, r1}};
}

TEST(Breakpoints, AdaptiveThresholdByHand) {
  // D_max = r sin(dphi) / sin(lambda - dphi) + 3 sigma_r = 2 sin(0.01) / sin(10 deg - 0.01) + 0.03.
  const double lambda = 10.0 * kPi / 180.0;
  const double d_max = 2.0 * std::sin(0.01) / std::sin(lambda - 0.01) + 0.03;
  BreakpointOptions options;
  options.sigma_r = 0.01;
  for (const double gap : {d_max - 1e-6, d_max + 1e-6}) {
    const Scan scan = two_beams(gap);
    const auto runs = split_at_breakpoints(scan, valid_points(scan), options);
    EXPECT_EQ(runs.size(), gap < d_max ? 1u : 2u) << gap;
  }
}

TEST(Breakpoints, SplitsAtAStepAndKeepsWallsWhole) {
  // A near wall (x = 2) for y < 0 and a far one (x = 3) for y > 0: one break, at the step.
  const std::vector<Segment2> walls{{{2.0, -10.0}, {2.0, 0.0}}, {{3.0, 0.0}, {3.0, 10.0}}};
  const SimulatedScan sim = simulate_scan(walls, {}, front_laser(0.01, 2));
  const auto points = valid_points(sim.scan);
  const auto runs = split_at_breakpoints(sim.scan, points);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].first, 0u);
  EXPECT_EQ(runs[1].last, points.size() - 1);
  EXPECT_EQ(runs[0].last + 1, runs[1].first);
  EXPECT_EQ(sim.hit[points[runs[0].last].index], 0);
  EXPECT_EQ(sim.hit[points[runs[1].first].index], 1);
}

TEST(Breakpoints, FixedGaps) {
  const std::vector<ScanPoint> points{{{0, 0}, 0}, {{0.1, 0}, 1}, {{0.35, 0}, 2}, {{0.4, 0}, 5}};
  const auto runs = split_at_gaps(points, 0.2);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].first, 0u);
  EXPECT_EQ(runs[0].last, 1u);
  EXPECT_EQ(runs[1].first, 2u);
  EXPECT_EQ(runs[1].last, 3u);
  EXPECT_TRUE(split_at_gaps({}, 0.2).empty());
  EXPECT_THROW(split_at_gaps(points, 0.0), Error);
  EXPECT_THROW(split_at_breakpoints(Scan{{0.0, 0.1}, {1.0, 1.0}}, valid_points(Scan{{0.0, 0.1}, {1.0, 1.0}}),
                                    BreakpointOptions{.lambda = 0.0}),
               Error);
}

}  // namespace
}  // namespace topocut
