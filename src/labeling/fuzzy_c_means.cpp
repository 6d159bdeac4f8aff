#include "topocut/labeling/fuzzy_c_means.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "topocut/core/error.h"

namespace topocut {

namespace {

double squared_distance(const Point2& a, const Point2& b) {
  const double dx = a.x - b.x;
  const double dy = a.y - b.y;
  return dx * dx + dy * dy;
}

void validate(std::span<const Point2> points, const FuzzyCMeansOptions& options) {
  if (options.clusters < 1) throw Error("fuzzy c-means needs at least one cluster, got " + std::to_string(options.clusters));
  if (!std::isfinite(options.fuzzifier) || options.fuzzifier <= 1.0)
    throw Error("the fuzzy c-means fuzzifier m must be greater than 1, got " + std::to_string(options.fuzzifier));
  if (!std::isfinite(options.tolerance) || options.tolerance < 0.0)
    throw Error("the fuzzy c-means tolerance must be a non-negative number, got " + std::to_string(options.tolerance));
  if (options.max_iterations < 1)
    throw Error("fuzzy c-means needs at least one iteration, got " + std::to_string(options.max_iterations));
  for (size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      throw Error("fuzzy c-means got a non-finite point (index " + std::to_string(i) + ")");
}

// Maximin initialisation: deterministic, and it picks distinct points while any remain.
std::vector<Point2> initial_centres(std::span<const Point2> points, int wanted) {
  Point2 mean;
  for (const Point2& p : points) {
    mean.x += p.x;
    mean.y += p.y;
  }
  mean.x /= static_cast<double>(points.size());
  mean.y /= static_cast<double>(points.size());
  std::vector<double> nearest(points.size());
  for (size_t i = 0; i < points.size(); ++i) nearest[i] = squared_distance(points[i], mean);
  std::vector<Point2> centres;
  while (static_cast<int>(centres.size()) < wanted) {
    size_t best = 0;
    for (size_t i = 1; i < points.size(); ++i)
      if (nearest[i] > nearest[best]) best = i;
    if (!centres.empty() && nearest[best] == 0.0) break;  // every point coincides with a centre
    centres.push_back(points[best]);
    for (size_t i = 0; i < points.size(); ++i) nearest[i] = std::min(nearest[i], squared_distance(points[i], points[best]));
  }
  return centres;
}

// The u^m-weighted sums of the points per centre, from which the next centres follow.
struct WeightedSums {
  std::vector<double> x, y, w;
  explicit WeightedSums(size_t c) : x(c), y(c), w(c) {}
  // Centres are the u^m-weighted means of the points.
  void update_centres(std::vector<Point2>& centres) const {
    for (size_t j = 0; j < centres.size(); ++j)
      if (w[j] > 0.0) centres[j] = {x[j] / w[j], y[j] / w[j]};
  }
};

// Bezdek's membership update u_ij = 1 / Σ_k (d_ij / d_ik)^(2/(m-1)), computed as w_j / Σ_k w_k with
// w_k = (d_min / d_ik)^(2/(m-1)): c powers per point instead of c², none at all for m = 2 (w_k is a
// ratio of squared distances), and no overflow for points very near a centre (every w_k <= 1). A
// point on a centre belongs to it (shared equally among coinciding centres). The same pass sums
// the points weighted by u^m (u² without pow for m = 2) for the next centres. Returns the largest
// change of any membership, for the convergence test.
double update_memberships(std::span<const Point2> points, const std::vector<Point2>& centres, double fuzzifier,
                          std::vector<double>& u, WeightedSums& sums) {
  const size_t c = centres.size();
  const double exponent = 1.0 / (fuzzifier - 1.0);  // with squared distances
  const bool squared = fuzzifier == 2.0;
  std::fill(sums.x.begin(), sums.x.end(), 0.0);
  std::fill(sums.y.begin(), sums.y.end(), 0.0);
  std::fill(sums.w.begin(), sums.w.end(), 0.0);
  std::vector<double> w(c);
  double change = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    double* row = &u[i * c];
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < c; ++j) {
      w[j] = squared_distance(points[i], centres[j]);
      nearest = std::min(nearest, w[j]);
    }
    double sum = 0.0;
    if (nearest == 0.0) {
      for (size_t j = 0; j < c; ++j) sum += w[j] = w[j] == 0.0 ? 1.0 : 0.0;
    } else {
      for (size_t j = 0; j < c; ++j) sum += w[j] = squared ? nearest / w[j] : std::pow(nearest / w[j], exponent);
    }
    for (size_t j = 0; j < c; ++j) {
      const double value = w[j] / sum;
      change = std::max(change, std::abs(value - row[j]));
      row[j] = value;
      const double weight = squared ? value * value : std::pow(value, fuzzifier);
      sums.x[j] += weight * points[i].x;
      sums.y[j] += weight * points[i].y;
      sums.w[j] += weight;
    }
  }
  return change;
}

}  // namespace

FuzzyCMeansResult fuzzy_c_means(std::span<const Point2> points, const FuzzyCMeansOptions& options) {
  validate(points, options);
  FuzzyCMeansResult result;
  if (points.empty()) {
    result.converged = true;
    return result;
  }
  std::vector<Point2> centres = initial_centres(points, options.clusters);
  const size_t c = centres.size();
  const size_t n = points.size();
  std::vector<double> u(n * c, 0.0);
  WeightedSums sums(c);
  update_memberships(points, centres, options.fuzzifier, u, sums);
  result.iterations = 1;
  while (true) {
    sums.update_centres(centres);
    if (result.iterations >= options.max_iterations) break;
    const double change = update_memberships(points, centres, options.fuzzifier, u, sums);
    ++result.iterations;
    if (change <= options.tolerance) {
      result.converged = true;
      sums.update_centres(centres);  // so the centres match the final memberships
      break;
    }
  }

  // Order the centres along the input: by the mean index of the points each holds most (by the
  // membership-weighted mean index if it holds none), ties by the centre's initial rank.
  std::vector<double> index_sum(c, 0.0), count(c, 0.0), weighted_sum(c, 0.0), weight(c, 0.0);
  for (size_t i = 0; i < n; ++i) {
    size_t best = 0;
    for (size_t j = 0; j < c; ++j) {
      if (u[i * c + j] > u[i * c + best]) best = j;
      weighted_sum[j] += u[i * c + j] * static_cast<double>(i);
      weight[j] += u[i * c + j];
    }
    index_sum[best] += static_cast<double>(i);
    count[best] += 1.0;
  }
  std::vector<double> key(c);
  for (size_t j = 0; j < c; ++j)
    key[j] = count[j] > 0.0 ? index_sum[j] / count[j] : (weight[j] > 0.0 ? weighted_sum[j] / weight[j] : 0.0);
  std::vector<size_t> order(c);
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return key[a] < key[b]; });
  result.centres.resize(c);
  result.memberships.resize(n * c);
  for (size_t j = 0; j < c; ++j) {
    result.centres[j] = centres[order[j]];
    for (size_t i = 0; i < n; ++i) result.memberships[i * c + j] = u[i * c + order[j]];
  }
  return result;
}

}  // namespace topocut
