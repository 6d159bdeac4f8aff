#include "topocut/labeling/fuzzy_c_means.h"

#include <algorithm>
#include <cmath>
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

// Bezdek's membership update u_ij = 1 / Σ_k (d_ij / d_ik)^(2/(m-1)); a point on a centre belongs
// to it (shared equally among coinciding centres).
void update_memberships(std::span<const Point2> points, const std::vector<Point2>& centres, double exponent,
                        std::vector<double>& u) {
  const size_t c = centres.size();
  std::vector<double> d2(c);
  for (size_t i = 0; i < points.size(); ++i) {
    double* row = &u[i * c];
    int zero = 0;
    for (size_t j = 0; j < c; ++j) {
      d2[j] = squared_distance(points[i], centres[j]);
      if (d2[j] == 0.0) ++zero;
    }
    if (zero > 0) {
      for (size_t j = 0; j < c; ++j) row[j] = d2[j] == 0.0 ? 1.0 / zero : 0.0;
      continue;
    }
    // With squared distances the exponent is 1/(m-1).
    for (size_t j = 0; j < c; ++j) {
      double sum = 0.0;
      for (size_t k = 0; k < c; ++k) sum += std::pow(d2[j] / d2[k], exponent);
      row[j] = 1.0 / sum;
    }
  }
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
  const double exponent = 1.0 / (options.fuzzifier - 1.0);
  std::vector<double> u(n * c, 0.0);
  std::vector<double> previous;
  update_memberships(points, centres, exponent, u);
  result.iterations = 1;
  while (true) {
    // Centres are the u^m-weighted means of the points.
    for (size_t j = 0; j < c; ++j) {
      double wx = 0.0, wy = 0.0, w = 0.0;
      for (size_t i = 0; i < n; ++i) {
        const double weight = std::pow(u[i * c + j], options.fuzzifier);
        wx += weight * points[i].x;
        wy += weight * points[i].y;
        w += weight;
      }
      if (w > 0.0) centres[j] = {wx / w, wy / w};
    }
    if (result.iterations >= options.max_iterations) break;
    previous = u;
    update_memberships(points, centres, exponent, u);
    ++result.iterations;
    double change = 0.0;
    for (size_t k = 0; k < u.size(); ++k) change = std::max(change, std::abs(u[k] - previous[k]));
    if (change <= options.tolerance) {
      result.converged = true;
      // One last centre update so the centres match the final memberships.
      for (size_t j = 0; j < c; ++j) {
        double wx = 0.0, wy = 0.0, w = 0.0;
        for (size_t i = 0; i < n; ++i) {
          const double weight = std::pow(u[i * c + j], options.fuzzifier);
          wx += weight * points[i].x;
          wy += weight * points[i].y;
          w += weight;
        }
        if (w > 0.0) centres[j] = {wx / w, wy / w};
      }
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
