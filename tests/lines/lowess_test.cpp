#include "topocut/lines/lowess.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "topocut/core/error.h"

namespace topocut {
namespace {

TEST(Lowess, ReproducesStraightLines) {
  std::vector<double> x, y;
  for (int i = 0; i < 30; ++i) {
    x.push_back(0.1 * i * i);  // uneven spacing
    y.push_back(-2.0 * x.back() + 1.0);
  }
  for (const std::size_t k : {3u, 7u, 30u}) {
    const auto fitted = lowess(x, y, {.span = 0.0, .neighbours = k, .iterations = 2});
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(fitted[i], y[i], 1e-9);
  }
}

TEST(Lowess, HandComputedTricubeWeights) {
  // x = 0..4, y = 0 1 0 1 0, 4 neighbours, no robustness round. At x = 2 the window is {0,1,2,3}
  // (ties keep the left one), h = 2: weights 0, w, 1, w with w = (1 - 1/8)^3 = 343/512. The points
  // (1,1), (2,0), (3,1) are symmetric, so the slope is 0 and the value the weighted mean
  // 2w / (2w + 1) = 686 / 1198.
  const std::vector<double> x{0, 1, 2, 3, 4}, y{0, 1, 0, 1, 0};
  const auto fitted = lowess(x, y, {.span = 0.0, .neighbours = 4, .iterations = 0});
  EXPECT_NEAR(fitted[2], 686.0 / 1198.0, 1e-15);
  // At x = 0 the window is {0,1,2,3}, h = 3: weights 1, (1-1/27)^3, (1-8/27)^3, 0. Weighted
  // regression through (0,0), (1,1), (2,0) with weights 1, a, b evaluated at x = 0.
  const double a = std::pow(26.0 / 27.0, 3), b = std::pow(19.0 / 27.0, 3);
  const double sw = 1 + a + b, mx = (a + 2 * b) / sw, my = a / sw;
  const double sxx = mx * mx + a * (1 - mx) * (1 - mx) + b * (2 - mx) * (2 - mx);
  const double sxy = (0 - mx) * (0 - my) + a * (1 - mx) * (1 - my) + b * (2 - mx) * (0 - my);
  EXPECT_NEAR(fitted[0], my + sxy / sxx * (0 - mx), 1e-14);
}

TEST(Lowess, SpanFractionSetsTheNeighbourhood) {
  // 10 points, span 0.4 -> 4 neighbours: the same as asking for 4 directly.
  std::vector<double> x, y;
  for (int i = 0; i < 10; ++i) {
    x.push_back(i);
    y.push_back(std::sin(i));
  }
  EXPECT_EQ(lowess(x, y, {.span = 0.4, .neighbours = 0, .iterations = 1}),
            lowess(x, y, {.span = 0.0, .neighbours = 4, .iterations = 1}));
}

TEST(Lowess, RobustnessRoundsRejectAnOutlier) {
  // A line with +-0.05 wiggle and one spike of +20: the plain smoother is dragged by several units
  // around the spike; the bisquare rounds give the spike weight 0 and recover the line.
  std::vector<double> x, y;
  for (int i = 0; i < 41; ++i) {
    x.push_back(i);
    y.push_back(0.5 * i + (i % 2 == 0 ? 0.05 : -0.05));
  }
  y[20] += 20.0;
  const auto plain = lowess(x, y, {.span = 0.0, .neighbours = 15, .iterations = 0});
  const auto robust = lowess(x, y, {.span = 0.0, .neighbours = 15, .iterations = 2});
  EXPECT_GT(plain[20] - 10.0, 1.0);
  for (int i = 0; i < 41; ++i) EXPECT_NEAR(robust[i], 0.5 * i, 0.1) << i;
}

TEST(Lowess, TiedAbscissaeGiveTheirMean) {
  const std::vector<double> x{1, 1, 1}, y{1, 2, 3};
  for (const double v : lowess(x, y, {.span = 1.0, .neighbours = 0, .iterations = 0})) EXPECT_DOUBLE_EQ(v, 2.0);
}

TEST(Lowess, SmallAndBadInputs) {
  EXPECT_TRUE(lowess(std::vector<double>{}, std::vector<double>{}).empty());
  EXPECT_EQ(lowess(std::vector<double>{1.0}, std::vector<double>{7.0}), std::vector<double>{7.0});
  EXPECT_THROW(lowess(std::vector<double>{1, 2}, std::vector<double>{1}), Error);
  EXPECT_THROW(lowess(std::vector<double>{2, 1}, std::vector<double>{1, 1}), Error);
  EXPECT_THROW(lowess(std::vector<double>{1, 2}, std::vector<double>{1, NAN}), Error);
  EXPECT_THROW(lowess(std::vector<double>{1, 2}, std::vector<double>{1, 2}, {.span = 0.0, .neighbours = 0, .iterations = 1}), Error);
  EXPECT_THROW(lowess(std::vector<double>{1, 2}, std::vector<double>{1, 2}, {.span = 0.5, .neighbours = 0, .iterations = -1}), Error);
}

}  // namespace
}  // namespace topocut
