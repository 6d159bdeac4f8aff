#include "topocut/lines/ale.h"

#include <cmath>

#include "lines/common.h"
#include "topocut/core/error.h"

namespace topocut {

namespace {

// Prefix moments of a run of points, relative to its first point (so sums stay small).
class PrefixMoments {
 public:
  explicit PrefixMoments(const std::vector<Point2>& q) : origin_(q.empty() ? Point2{} : q.front()), prefix_(q.size() + 1) {
    for (std::size_t k = 0; k < q.size(); ++k) {
      prefix_[k + 1] = prefix_[k];
      prefix_[k + 1].add({q[k].x - origin_.x, q[k].y - origin_.y});
    }
  }
  // RMSE of points [first, last] about their total-least-squares line.
  double rmse(std::size_t first, std::size_t last) const { return (prefix_[last + 1] - prefix_[first]).sigma(); }

 private:
  Point2 origin_;
  std::vector<Moments> prefix_;
};

// Largest e in [lo, hi] with rmse(first, e) <= threshold, given rmse(first, lo) <= threshold.
std::size_t last_within(const PrefixMoments& pm, std::size_t first, std::size_t lo, std::size_t hi, double threshold) {
  if (pm.rmse(first, hi) <= threshold) return hi;
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (pm.rmse(first, mid) <= threshold) lo = mid;
    else hi = mid;
  }
  return lo;
}

}  // namespace

std::vector<Line> extract_lines_ale(const Scan& scan, const AleOptions& options) {
  detail::require_positive(options.rmse_min, "rmse_min");
  detail::require_positive(options.rmse_max, "rmse_max");
  detail::require_positive(options.gradient_max, "gradient_max");
  if (options.rmse_max < options.rmse_min) throw Error("the ALE thresholds must satisfy rmse_min <= rmse_max");
  if (!std::isfinite(options.reference_noise)) throw Error("the ALE reference noise must be finite");
  const std::vector<ScanPoint> points = detail::prepared_points(scan);
  double scale = 1.0;
  if (options.reference_noise > 0.0) {
    const double noise = options.breakpoints.sigma_r > 0.0 ? options.breakpoints.sigma_r : estimate_range_noise(scan);
    scale = std::max(1.0, noise / options.reference_noise);
  }
  const double t_min = options.rmse_min * scale, t_max = options.rmse_max * scale;

  std::vector<PointRun> groups;
  std::vector<bool> neighbours;
  std::vector<double> angles, ranges;
  std::vector<Point2> smoothed;
  for (const PointRun& run : split_at_breakpoints(scan, points, options.breakpoints)) {
    if (!groups.empty()) neighbours.back() = false;
    const std::size_t n = run.size();
    if (n < 3) {
      groups.push_back(run);
      neighbours.push_back(true);
      continue;
    }
    angles.resize(n);
    ranges.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      angles[k] = scan.angles[points[run.first + k].index];
      ranges[k] = scan.ranges[points[run.first + k].index];
    }
    const std::vector<double> r = lowess(angles, ranges, options.smoothing);
    smoothed.resize(n);
    for (std::size_t k = 0; k < n; ++k) smoothed[k] = {r[k] * std::cos(angles[k]), r[k] * std::sin(angles[k])};
    const PrefixMoments pm(smoothed);

    std::size_t s = 0;
    while (s < n) {
      if (n - s <= 2) {
        groups.push_back({run.first + s, run.first + n - 1});
        neighbours.push_back(true);
        break;
      }
      // Two points always fit a line exactly, so the searches start at s + 1.
      const std::size_t e_max = last_within(pm, s, s + 1, n - 1, t_max);
      const std::size_t e_min = last_within(pm, s, s + 1, e_max, t_min);
      std::size_t e = e_max;
      if (e_min < e_max || e_max < n - 1) {
        // Floating threshold: between the two bounds the line ends where the RMSE starts to climb.
        double previous = pm.rmse(s, e_min);
        for (std::size_t k = e_min; k < e_max; ++k) {
          const double next = pm.rmse(s, k + 1);
          const double count = static_cast<double>(k + 2 - s);
          if (next > 0.0 && count * (next - previous) / next > options.gradient_max) {
            e = k;
            break;
          }
          previous = next;
        }
      }
      groups.push_back({run.first + s, run.first + e});
      neighbours.push_back(true);
      s = e + 1;
    }
  }
  // Smoothing rounds corners, which can leave a short extra piece next to one; pieces that one line
  // explains as well as each explains itself are fused (tolerance: the scaled lower threshold).
  detail::merge_collinear(points, groups, neighbours, t_min);
  detail::refine_boundaries(points, groups, neighbours);
  detail::trim_run_ends(points, groups, neighbours);
  return detail::lines_from_runs(scan, points, groups, options.min_points);
}

}  // namespace topocut
