#include "topocut/labeling/fuzzy_c_means.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "topocut/core/error.h"
#include "topocut/labeling/segment_centres.h"

namespace topocut {
namespace {

// Points spread evenly on a circle of the given radius around a centre: their mean is the centre.
void add_ring(std::vector<Point2>& points, Point2 centre, double radius, int count) {
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * M_PI * i / count;
    points.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
  }
}

TEST(FuzzyCMeans, ConvergesToTheCentresOfSeparableClusters) {
  // Three symmetric clusters 10 m apart with 0.5 m radius: memberships in the far clusters are
  // about (0.5/10)^2, so each centre sits within a few millimetres of its cluster's mean. The input
  // is in cluster order 2, 0, 1 so the centres come back in that order.
  const Point2 truth[3] = {{0, 0}, {10, 0}, {5, 8.66}};
  std::vector<Point2> points;
  add_ring(points, truth[2], 0.5, 24);
  add_ring(points, truth[0], 0.5, 24);
  add_ring(points, truth[1], 0.5, 24);
  FuzzyCMeansOptions options;
  options.clusters = 3;
  const FuzzyCMeansResult r = fuzzy_c_means(points, options);
  ASSERT_EQ(r.centres.size(), 3u);
  EXPECT_TRUE(r.converged);
  const int order[3] = {2, 0, 1};
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(r.centres[j].x, truth[order[j]].x, 0.01) << j;
    EXPECT_NEAR(r.centres[j].y, truth[order[j]].y, 0.01) << j;
  }
  for (size_t i = 0; i < points.size(); ++i) {
    double sum = 0.0;
    for (int j = 0; j < 3; ++j) sum += r.membership(static_cast<int>(i), j);
    EXPECT_NEAR(sum, 1.0, 1e-12);
    // Each point belongs mostly to its own cluster.
    EXPECT_GT(r.membership(static_cast<int>(i), static_cast<int>(i / 24)), 0.99);
  }
}

TEST(FuzzyCMeans, NoisyBlobsConvergeNearTheirMeans) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.2);
  const Point2 truth[2] = {{-4, 1}, {4, -1}};
  std::vector<Point2> points;
  Point2 mean[2];
  for (int c = 0; c < 2; ++c) {
    for (int i = 0; i < 200; ++i) {
      const Point2 p{truth[c].x + noise(rng), truth[c].y + noise(rng)};
      points.push_back(p);
      mean[c].x += p.x / 200;
      mean[c].y += p.y / 200;
    }
  }
  const FuzzyCMeansResult r = fuzzy_c_means(points);
  ASSERT_EQ(r.centres.size(), 2u);
  EXPECT_TRUE(r.converged);
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(r.centres[c].x, mean[c].x, 0.02);
    EXPECT_NEAR(r.centres[c].y, mean[c].y, 0.02);
  }
}

TEST(FuzzyCMeans, HandComputedSmallCases) {
  // One cluster: all memberships are 1 and the centre is the mean.
  const std::vector<Point2> three{{0, 0}, {3, 0}, {0, 6}};
  FuzzyCMeansOptions one;
  one.clusters = 1;
  const FuzzyCMeansResult r1 = fuzzy_c_means(three, one);
  ASSERT_EQ(r1.centres.size(), 1u);
  EXPECT_NEAR(r1.centres[0].x, 1.0, 1e-12);
  EXPECT_NEAR(r1.centres[0].y, 2.0, 1e-12);

  // Two points, two clusters: each point is its own centre with membership 1.
  const std::vector<Point2> two{{0, 0}, {2, 0}};
  const FuzzyCMeansResult r2 = fuzzy_c_means(two);
  ASSERT_EQ(r2.centres.size(), 2u);
  EXPECT_EQ(r2.centres[0], (Point2{0, 0}));
  EXPECT_EQ(r2.centres[1], (Point2{2, 0}));
  EXPECT_DOUBLE_EQ(r2.membership(0, 0), 1.0);
  EXPECT_TRUE(r2.converged);

  // Four points symmetric under p → -p: by symmetry the two centres are each other's negatives,
  // and each lies between the inner (|x| = 1) and the outer (|x| = 3) column of its side.
  const std::vector<Point2> four{{-3, 1}, {-1, -1}, {1, 1}, {3, -1}};
  const FuzzyCMeansResult r4 = fuzzy_c_means(four);
  ASSERT_EQ(r4.centres.size(), 2u);
  EXPECT_NEAR(r4.centres[0].x, -r4.centres[1].x, 1e-6);
  EXPECT_NEAR(r4.centres[0].y, -r4.centres[1].y, 1e-6);
  EXPECT_GT(std::abs(r4.centres[0].x), 1.0);
  EXPECT_LT(std::abs(r4.centres[0].x), 3.0);
}

TEST(FuzzyCMeans, FewerDistinctPointsThanClusters) {
  const std::vector<Point2> points{{1, 1}, {1, 1}, {5, 5}};
  FuzzyCMeansOptions options;
  options.clusters = 4;
  const FuzzyCMeansResult r = fuzzy_c_means(points, options);
  ASSERT_EQ(r.centres.size(), 2u);
  EXPECT_EQ(r.centres[0], (Point2{1, 1}));
  EXPECT_EQ(r.centres[1], (Point2{5, 5}));
  EXPECT_TRUE(fuzzy_c_means(std::vector<Point2>{}).centres.empty());
}

TEST(FuzzyCMeans, IsDeterministic) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 10);
  std::vector<Point2> points;
  for (int i = 0; i < 100; ++i) points.push_back({u(rng), u(rng)});
  FuzzyCMeansOptions options;
  options.clusters = 5;
  const FuzzyCMeansResult a = fuzzy_c_means(points, options);
  const FuzzyCMeansResult b = fuzzy_c_means(points, options);
  EXPECT_EQ(a.centres, b.centres);
  EXPECT_EQ(a.memberships, b.memberships);
}

// Textbook memberships (Bezdek): u_ij = 1 / sum_k (|x_i - v_j| / |x_i - v_k|)^(2/(m-1)), with pow.
std::vector<double> reference_memberships(const std::vector<Point2>& points, const std::vector<Point2>& centres, double m) {
  const std::size_t c = centres.size();
  std::vector<double> u(points.size() * c);
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = 0; j < c; ++j) {
      const double dj = std::hypot(points[i].x - centres[j].x, points[i].y - centres[j].y);
      double sum = 0.0;
      for (std::size_t k = 0; k < c; ++k)
        sum += std::pow(dj / std::hypot(points[i].x - centres[k].x, points[i].y - centres[k].y), 2.0 / (m - 1.0));
      u[i * c + j] = 1.0 / sum;
    }
  }
  return u;
}

TEST(FuzzyCMeans, MembershipsMatchThePowFormulaAtTheFixedPoint) {
  // Converged tightly, the memberships are the textbook formula applied to the returned centres,
  // for m = 2 (no pow in the update) and for another fuzzifier (pow per centre).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 10);
  std::vector<Point2> points;
  for (int i = 0; i < 150; ++i) points.push_back({u(rng), 0.3 * u(rng)});
  for (const double m : {2.0, 1.7, 3.0}) {
    FuzzyCMeansOptions options;
    options.clusters = 4;
    options.fuzzifier = m;
    options.tolerance = 1e-11;
    options.max_iterations = 5000;
    const FuzzyCMeansResult r = fuzzy_c_means(points, options);
    ASSERT_TRUE(r.converged) << m;
    ASSERT_EQ(r.centres.size(), 4u);
    const std::vector<double> expected = reference_memberships(points, r.centres, m);
    for (std::size_t i = 0; i < points.size(); ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < 4; ++j) {
        sum += r.memberships[i * 4 + j];
        EXPECT_NEAR(r.memberships[i * 4 + j], expected[i * 4 + j], 1e-7) << m << " point " << i << " centre " << j;
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << m;
    }
  }
}

TEST(FuzzyCMeans, PointsNearACentreKeepFiniteMemberships) {
  // A point 1e-160 from a centre: squared distances underflow to 0 or 1/d^2 overflows unless the
  // update works with ratios. Memberships stay finite and sum to 1.
  const std::vector<Point2> points{{0, 0}, {1e-160, 0}, {10, 0}, {10, 1e-160}};
  const FuzzyCMeansResult r = fuzzy_c_means(points);
  ASSERT_EQ(r.centres.size(), 2u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double a = r.membership(static_cast<int>(i), 0), b = r.membership(static_cast<int>(i), 1);
    EXPECT_TRUE(std::isfinite(a) && std::isfinite(b)) << i;
    EXPECT_NEAR(a + b, 1.0, 1e-12) << i;
  }
  EXPECT_NEAR(r.centres[0].x, 0.0, 1e-9);
  EXPECT_NEAR(r.centres[1].x, 10.0, 1e-9);
}

TEST(FuzzyCMeans, RejectsInvalidInput) {
  const std::vector<Point2> points{{0, 0}, {1, 1}};
  FuzzyCMeansOptions bad;
  bad.clusters = 0;
  EXPECT_THROW(fuzzy_c_means(points, bad), Error);
  bad = {};
  bad.fuzzifier = 1.0;
  EXPECT_THROW(fuzzy_c_means(points, bad), Error);
  bad = {};
  bad.tolerance = -1.0;
  EXPECT_THROW(fuzzy_c_means(points, bad), Error);
  bad = {};
  bad.max_iterations = 0;
  EXPECT_THROW(fuzzy_c_means(points, bad), Error);
  const std::vector<Point2> nan{{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0}};
  EXPECT_THROW(fuzzy_c_means(nan), Error);
}

}  // namespace
}  // namespace topocut

namespace topocut {
namespace {

// Issue 28: fuzzy c-means on a whole scan is bounded by its point-centre pairs.
TEST(SegmentCentres, PointCentrePairsBeyondTheLimitAreRefused) {
  Scan scan;
  for (int i = 0; i < 20000; ++i) {
    scan.angles.push_back(-1.0 + 2.0 * i / 20000.0);
    scan.ranges.push_back(4.0);
  }
  Labeling labeling;
  labeling.segments.emplace_back();
  for (int i = 0; i < 20000; ++i) labeling.segments[0].push_back(i);
  FuzzyCMeansOptions options;
  options.clusters = 5000;  // 10^8 pairs
  try {
    segment_centres(scan, labeling, options);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("more than the limit of 5e+07"), std::string::npos) << e.what();
  }
  options.clusters = 2;
  EXPECT_EQ(segment_centres(scan, labeling, options)[0].size(), 2u);
}

}  // namespace
}  // namespace topocut
