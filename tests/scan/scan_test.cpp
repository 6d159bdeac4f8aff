#include "topocut/scan/scan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "topocut/core/error.h"

namespace topocut {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Scan, InvalidReadingsAreSkippedButIndicesKept) {
  Scan scan;
  scan.angles = {-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3};
  scan.ranges = {1.0, kNaN, 0.0, kInf, -1.0, 2.0, 50.0};
  scan.range_max = 10.0;
  EXPECT_TRUE(scan.is_valid(0));
  EXPECT_FALSE(scan.is_valid(1));
  EXPECT_FALSE(scan.is_valid(2));
  EXPECT_FALSE(scan.is_valid(3));
  EXPECT_FALSE(scan.is_valid(4));
  EXPECT_TRUE(scan.is_valid(5));
  EXPECT_FALSE(scan.is_valid(6));  // beyond range_max
  EXPECT_FALSE(scan.is_valid(7));  // no such beam
  EXPECT_EQ(count_valid(scan), 2u);
  const auto points = valid_points(scan);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].index, 0u);
  EXPECT_EQ(points[1].index, 5u);
  EXPECT_NEAR(points[1].point.x, 2.0 * std::cos(0.2), 1e-15);
  EXPECT_NEAR(points[1].point.y, 2.0 * std::sin(0.2), 1e-15);
}

TEST(Scan, RangeMinExcludesShortReadings) {
  Scan scan{{0.0, 0.1}, {0.05, 0.5}, 0.1, 4.0};
  EXPECT_FALSE(scan.is_valid(0));
  EXPECT_TRUE(scan.is_valid(1));
}

TEST(Scan, ValidateRejectsMismatchedLengths) {
  Scan scan{{0.0, 0.1}, {1.0}};
  EXPECT_THROW(validate(scan), Error);
  Scan limits{{0.0}, {1.0}, 3.0, 2.0};
  EXPECT_THROW(validate(limits), Error);
}

TEST(Pose2, WorldAndLocalAreInverse) {
  const Pose2 pose{1.0, -2.0, std::numbers::pi / 2};
  // Heading +90 deg: the sensor's x axis points along world +y.
  const Point2 w = to_world(pose, {3.0, 0.0});
  EXPECT_NEAR(w.x, 1.0, 1e-12);
  EXPECT_NEAR(w.y, 1.0, 1e-12);
  const Point2 l = to_local(pose, to_world(pose, {0.3, -0.7}));
  EXPECT_NEAR(l.x, 0.3, 1e-12);
  EXPECT_NEAR(l.y, -0.7, 1e-12);
}

}  // namespace
}  // namespace topocut
