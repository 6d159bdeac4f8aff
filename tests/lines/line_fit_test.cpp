#include "topocut/lines/line_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "topocut/core/error.h"

namespace topocut {
namespace {

constexpr double kPi = std::numbers::pi;

// Noiseless points on the line x cos a + y sin a = rho (rho may be negative), spread over 4 m.
std::vector<Point2> points_on(double rho, double alpha, int count = 21) {
  std::vector<Point2> p;
  const double nx = std::cos(alpha), ny = std::sin(alpha);
  for (int i = 0; i < count; ++i) {
    const double t = -2.0 + 4.0 * i / (count - 1);
    p.push_back({rho * nx - t * ny, rho * ny + t * nx});
  }
  return p;
}

// The two polar forms describe the same line.
void expect_same_line(const LineFit& fit, double rho, double alpha, double tol) {
  EXPECT_GE(fit.rho, 0.0);
  EXPECT_GT(fit.alpha, -kPi);
  EXPECT_LE(fit.alpha, kPi);
  if (rho < 0.0) rho = -rho, alpha += kPi;
  if (rho > tol) {
    EXPECT_NEAR(fit.rho, rho, tol);
    EXPECT_NEAR(angle_difference(fit.alpha, alpha), 0.0, tol) << fit.alpha << " vs " << alpha;
  } else {
    // Through (or next to) the origin both normals are right.
    EXPECT_NEAR(fit.rho, rho, tol);
    EXPECT_NEAR(std::sin(fit.alpha - alpha), 0.0, tol);
  }
}

TEST(LineFit, ExactForEveryOrientation) {
  for (int k = -180; k <= 180; k += 5) {
    const double alpha = k * kPi / 180.0;
    for (const double rho : {3.0, 0.25}) {
      SCOPED_TRACE("alpha " + std::to_string(k) + " rho " + std::to_string(rho));
      const LineFit fit = fit_line(points_on(rho, alpha));
      expect_same_line(fit, rho, alpha, 1e-12);
      EXPECT_NEAR(fit.sigma, 0.0, 1e-12);
      EXPECT_EQ(fit.weight, 21.0);
    }
  }
}

TEST(LineFit, ExactNearPlusMinusPiAndNearTheOrigin) {
  for (const double alpha : {kPi, -kPi, kPi - 1e-9, -kPi + 1e-9, kPi - 1e-6, -kPi + 1e-6}) {
    for (const double rho : {2.0, 1e-3}) {
      const LineFit fit = fit_line(points_on(rho, alpha));
      expect_same_line(fit, rho, alpha, 1e-12);
    }
  }
  for (const double alpha : {0.0, 0.3, kPi / 2, -2.5, kPi}) {
    for (const double rho : {0.0, 1e-12, -1e-12}) expect_same_line(fit_line(points_on(rho, alpha)), rho, alpha, 1e-12);
  }
}

TEST(LineFit, AxisLinesHaveCanonicalParameters) {
  const LineFit right = fit_line(std::vector<Point2>{{2, -1}, {2, 0}, {2, 3}});
  EXPECT_NEAR(right.rho, 2.0, 1e-15);
  EXPECT_NEAR(right.alpha, 0.0, 1e-15);
  const LineFit left = fit_line(std::vector<Point2>{{-2, -1}, {-2, 0}, {-2, 3}});
  EXPECT_NEAR(left.rho, 2.0, 1e-15);
  EXPECT_NEAR(left.alpha, kPi, 1e-15);  // +pi, never -pi
  const LineFit below = fit_line(std::vector<Point2>{{-1, -3}, {4, -3}});
  EXPECT_NEAR(below.rho, 3.0, 1e-15);
  EXPECT_NEAR(below.alpha, -kPi / 2, 1e-15);
}

TEST(LineFit, HandComputedNoisyExample) {
  // Centroid (1, 1/3); Suu = 2, Svv = 2/3, Suv = 0, so tan 2a = 0 with the minimum at a = pi/2:
  // the line y = 1/3, residuals -1/3, 2/3, -1/3, sigma = sqrt((1/9 + 4/9 + 1/9) / 3).
  const LineFit fit = fit_line(std::vector<Point2>{{0, 0}, {1, 1}, {2, 0}});
  EXPECT_NEAR(fit.alpha, kPi / 2, 1e-15);
  EXPECT_NEAR(fit.rho, 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(fit.sigma, std::sqrt(2.0 / 9.0), 1e-15);
  EXPECT_NEAR(fit.centroid.x, 1.0, 1e-15);
  EXPECT_NEAR(fit.centroid.y, 1.0 / 3.0, 1e-15);
}

TEST(LineFit, CollinearPointsFarFromTheOrigin) {
  std::vector<Point2> p;
  for (int i = 0; i < 50; ++i) p.push_back({1000.0 + 0.6 * i, -2000.0 + 0.8 * i});  // direction (3,4)/5
  const LineFit fit = fit_line(p);
  // Normal (4,-3)/5 or its opposite; rho = |4*1000 - 3*(-2000)| / 5 = 2000.
  expect_same_line(fit, (4 * 1000.0 + 3 * 2000.0) / 5.0, std::atan2(-3.0, 4.0), 1e-9);
}

TEST(LineFit, DegenerateInputs) {
  const LineFit empty = fit_line(std::vector<Point2>{});
  EXPECT_EQ(empty.weight, 0.0);
  // One spot seen by the laser: the line through it facing the sensor.
  const LineFit same = fit_line(std::vector<Point2>(5, Point2{3.0, 4.0}));
  EXPECT_NEAR(same.rho, 5.0, 1e-12);
  EXPECT_NEAR(same.alpha, std::atan2(4.0, 3.0), 1e-12);
  EXPECT_EQ(same.sigma, 0.0);
  const LineFit single = fit_line(std::vector<Point2>{{-1.0, 0.0}});
  EXPECT_NEAR(single.rho, 1.0, 1e-15);
  EXPECT_NEAR(single.alpha, kPi, 1e-15);
  const LineFit origin = fit_line(std::vector<Point2>{{0.0, 0.0}, {0.0, 0.0}});
  EXPECT_EQ(origin.rho, 0.0);
  EXPECT_TRUE(std::isfinite(origin.alpha));
}

TEST(LineFit, WeightsSelectAndScale) {
  std::vector<Point2> p = points_on(1.5, 0.7, 10);
  std::vector<double> w(p.size(), 2.0);
  p.push_back({10.0, -7.0});  // an outlier with weight 0 changes nothing
  w.push_back(0.0);
  const LineFit fit = fit_line(p, w);
  expect_same_line(fit, 1.5, 0.7, 1e-12);
  EXPECT_DOUBLE_EQ(fit.weight, 20.0);
  // Uniform weights give the unweighted fit.
  const std::vector<Point2> q{{0, 0}, {1, 1}, {2, 0}};
  const LineFit a = fit_line(q), b = fit_line(q, std::vector<double>{0.5, 0.5, 0.5});
  EXPECT_NEAR(a.rho, b.rho, 1e-15);
  EXPECT_NEAR(a.alpha, b.alpha, 1e-15);
  EXPECT_NEAR(a.sigma, b.sigma, 1e-15);
  // Weighted by hand: weights 1, 2, 1 -> centroid (1, 1/2), Suu = 2, Svv = 1/4 + 2/4 + 1/4 = 1, Suv = 0.
  const LineFit c = fit_line(q, std::vector<double>{1, 2, 1});
  EXPECT_NEAR(c.rho, 0.5, 1e-15);
  EXPECT_NEAR(c.alpha, kPi / 2, 1e-15);
  EXPECT_NEAR(c.sigma, std::sqrt(1.0 / 4.0), 1e-15);
  EXPECT_EQ(fit_line(q, std::vector<double>{0, 0, 0}).weight, 0.0);
}

TEST(LineFit, BadWeightsAreErrors) {
  const std::vector<Point2> q{{0, 0}, {1, 1}};
  EXPECT_THROW(fit_line(q, std::vector<double>{1.0}), Error);
  EXPECT_THROW(fit_line(q, std::vector<double>{1.0, -1.0}), Error);
  EXPECT_THROW(fit_line(q, std::vector<double>{1.0, NAN}), Error);
}

TEST(LineGeometry, DistanceAndAngles) {
  // The line x = 2 (rho 2, alpha 0).
  EXPECT_DOUBLE_EQ(signed_distance(2.0, 0.0, {5.0, 1.0}), 3.0);
  EXPECT_DOUBLE_EQ(signed_distance(2.0, 0.0, {0.0, 1.0}), -2.0);
  EXPECT_DOUBLE_EQ(normalize_angle(kPi), kPi);
  EXPECT_DOUBLE_EQ(normalize_angle(-kPi), kPi);
  EXPECT_NEAR(normalize_angle(3 * kPi), kPi, 1e-12);
  EXPECT_NEAR(normalize_angle(-0.5 - 4 * kPi), -0.5, 1e-12);
  EXPECT_NEAR(angle_difference(kPi - 0.1, -kPi + 0.1), 0.2, 1e-12);
  const LineFit p = polar_line({0.0, -3.0}, kPi / 2);  // normal up, point below: flipped
  EXPECT_DOUBLE_EQ(p.rho, 3.0);
  EXPECT_NEAR(p.alpha, -kPi / 2, 1e-15);
}

}  // namespace
}  // namespace topocut
