#include "topocut/walls/wall_merging.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "topocut/core/error.h"

namespace topocut {
namespace {

WallSegment seg(double ax, double ay, double bx, double by, int scan = 0) {
  return {{{ax, ay}, {bx, by}}, scan, 10};
}

double min_x(const Wall& w) { return std::min(w.segment.a.x, w.segment.b.x); }
double max_x(const Wall& w) { return std::max(w.segment.a.x, w.segment.b.x); }

TEST(WallMerging, OverlappingCollinearSegmentsBecomeOneWall) {
  // Symmetric about x = 2, so the fitted line is horizontal at the length-weighted mean height
  // (4·0 + 2·0.03) / 6 = 0.01, and spans both extents.
  const std::vector<WallSegment> s{seg(1, 0.03, 3, 0.03), seg(0, 0, 4, 0)};
  const auto walls = merge_wall_segments(s);
  ASSERT_EQ(walls.size(), 1u);
  EXPECT_EQ(walls[0].observations, 2);
  EXPECT_EQ(walls[0].members, (std::vector<int>{0, 1}));
  EXPECT_DOUBLE_EQ(walls[0].weight, 2.0 + 4.0);
  const double y = 0.01;
  EXPECT_NEAR(walls[0].segment.a.y, y, 1e-9);
  EXPECT_NEAR(walls[0].segment.b.y, y, 1e-9);
  EXPECT_NEAR(min_x(walls[0]), 0.0, 1e-9);
  EXPECT_NEAR(max_x(walls[0]), 4.0, 1e-9);
}

TEST(WallMerging, SmallGapsCloseDoorsStayOpen) {
  // Default gap tolerance 0.3 m: a 0.2 m gap closes, a 0.9 m door stays.
  EXPECT_EQ(merge_wall_segments(std::vector{seg(0, 0, 2, 0), seg(2.2, 0, 4, 0)}).size(), 1u);
  const auto door = merge_wall_segments(std::vector{seg(0, 0, 2, 0), seg(2.9, 0, 4, 0)});
  ASSERT_EQ(door.size(), 2u);
  EXPECT_NEAR(max_x(door[0]), 2.0, 1e-9);
  EXPECT_NEAR(min_x(door[1]), 2.9, 1e-9);
}

TEST(WallMerging, ParallelOffsetAndTurnedSegmentsStayApart) {
  // 0.3 m apart (both sides of a thick wall), beyond the 0.1 m distance tolerance.
  EXPECT_EQ(merge_wall_segments(std::vector{seg(0, 0, 4, 0), seg(0, 0.3, 4, 0.3)}).size(), 2u);
  // Turned by 10° about a shared point: ends 0.17 m apart after 1 m, angle beyond 5°.
  const double a = 10.0 * M_PI / 180.0;
  EXPECT_EQ(merge_wall_segments(std::vector{seg(0, 0, 4, 0), seg(2, 0, 2 + std::cos(a), std::sin(a))}).size(), 2u);
  // A corner: two walls.
  EXPECT_EQ(merge_wall_segments(std::vector{seg(0, 0, 4, 0), seg(4, 0, 4, 3)}).size(), 2u);
  // A turned segment within 4° and 0.1 m merges.
  const double b = 3.0 * M_PI / 180.0;
  EXPECT_EQ(merge_wall_segments(std::vector{seg(0, 0, 4, 0), seg(1, 0, 1 + std::cos(b), std::sin(b))}).size(), 1u);
}

TEST(WallMerging, ShortSegmentsJoinByDistanceOnly) {
  // A 0.1 m piece at 45° lying on the wall: its direction means nothing, its points are on the wall.
  const auto walls = merge_wall_segments(std::vector{seg(0, 0, 4, 0), seg(1, -0.03, 1.07, 0.04)});
  EXPECT_EQ(walls.size(), 1u);
}

TEST(WallMerging, ManyNoisyObservationsOfOneWallGiveTheWall) {
  // 300 pieces of the wall y = 0.5 x + 1 for x in [0, 10], each 1–3 m long, ends jittered by 1 cm,
  // in random order: one wall on the true line.
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> start(0.0, 9.0), length(1.0, 3.0);
  std::normal_distribution<double> jitter(0.0, 0.01);
  const double norm = std::hypot(1.0, 0.5);
  auto on_line = [](double x) { return 0.5 * x + 1.0; };
  std::vector<WallSegment> segments;
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < 300; ++i) {
    const double x0 = start(rng);
    const double x1 = std::min(10.0, x0 + length(rng) / norm);
    lo = std::min(lo, x0);
    hi = std::max(hi, x1);
    segments.push_back(seg(x0, on_line(x0) + jitter(rng), x1, on_line(x1) + jitter(rng), i));
  }
  const auto walls = merge_wall_segments(segments);
  ASSERT_EQ(walls.size(), 1u);
  EXPECT_EQ(walls[0].observations, 300);
  for (const Point2& p : {walls[0].segment.a, walls[0].segment.b}) {
    EXPECT_NEAR(std::abs(0.5 * p.x - p.y + 1.0) / norm, 0.0, 0.01);  // on the true line within 1 cm
  }
  EXPECT_NEAR(min_x(walls[0]), lo, 0.02);
  EXPECT_NEAR(max_x(walls[0]), hi, 0.02);
}

TEST(WallMerging, EverySegmentIsInExactlyOneWallAndTheResultIsDeterministic) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0.0, 20.0), angle(0.0, M_PI), length(0.05, 3.0);
  std::vector<WallSegment> segments;
  for (int i = 0; i < 3000; ++i) {
    const double x = u(rng), y = u(rng), a = angle(rng), l = length(rng);
    // Quantise directions so that many segments are parallel and some merge.
    const double q = std::round(a / (M_PI / 4)) * (M_PI / 4);
    segments.push_back(seg(x, std::round(y), x + l * std::cos(q), std::round(y) + l * std::sin(q), i));
  }
  segments.push_back(seg(1, 1, 1, 1));  // degenerate: skipped
  segments.push_back(seg(std::numeric_limits<double>::quiet_NaN(), 0, 1, 1));
  const auto walls = merge_wall_segments(segments);
  std::vector<int> seen(segments.size(), 0);
  for (std::size_t w = 0; w < walls.size(); ++w) {
    EXPECT_EQ(walls[w].observations, static_cast<int>(walls[w].members.size()));
    for (int m : walls[w].members) ++seen[static_cast<std::size_t>(m)];
    if (w > 0) {
      EXPECT_LT(walls[w - 1].members.front(), walls[w].members.front());
    }
  }
  for (std::size_t i = 0; i + 2 < segments.size(); ++i) EXPECT_EQ(seen[i], 1) << i;
  EXPECT_EQ(seen[segments.size() - 2], 0);
  EXPECT_EQ(seen[segments.size() - 1], 0);
  EXPECT_LT(walls.size(), 3000u);
  const auto again = merge_wall_segments(segments);
  ASSERT_EQ(again.size(), walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) {
    EXPECT_EQ(again[w].segment, walls[w].segment);
    EXPECT_EQ(again[w].members, walls[w].members);
  }
}

TEST(WallMerging, EmptyInputAndInvalidOptions) {
  EXPECT_TRUE(merge_wall_segments(std::vector<WallSegment>{}).empty());
  const std::vector<WallSegment> s{seg(0, 0, 1, 0)};
  WallMergeOptions bad;
  bad.angle_tolerance = 2.0;
  EXPECT_THROW(merge_wall_segments(s, bad), Error);
  bad = {};
  bad.distance_tolerance = -1.0;
  EXPECT_THROW(merge_wall_segments(s, bad), Error);
  bad = {};
  bad.index_cell = 0.0;
  EXPECT_THROW(merge_wall_segments(s, bad), Error);
}

TEST(WallMerging, DistanceToSegment) {
  const Segment2 s{{0, 0}, {4, 0}};
  EXPECT_DOUBLE_EQ(distance_to_segment({2, 3}, s), 3.0);
  EXPECT_DOUBLE_EQ(distance_to_segment({7, 4}, s), 5.0);
  EXPECT_DOUBLE_EQ(distance_to_segment({-3, -4}, s), 5.0);
  EXPECT_DOUBLE_EQ(distance_to_segment({1, 1}, Segment2{{1, 2}, {1, 2}}), 1.0);
}

}  // namespace
}  // namespace topocut
