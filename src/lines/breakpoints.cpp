#include "topocut/lines/breakpoints.h"

#include <algorithm>
#include <cmath>

#include "topocut/core/error.h"

namespace topocut {

double estimate_range_noise(const Scan& scan) {
  std::vector<double> second;
  second.reserve(scan.size());
  bool valid_before = scan.size() > 0 && scan.is_valid(0);
  bool valid_here = scan.size() > 1 && scan.is_valid(1);
  for (std::size_t i = 1; i + 1 < scan.size(); ++i) {
    const bool valid_after = scan.is_valid(i + 1);
    if (valid_before && valid_here && valid_after)
      second.push_back(std::abs(scan.ranges[i - 1] - 2.0 * scan.ranges[i] + scan.ranges[i + 1]));
    valid_before = valid_here;
    valid_here = valid_after;
  }
  if (second.empty()) return 0.0;
  const std::size_t mid = second.size() / 2;
  std::nth_element(second.begin(), second.begin() + mid, second.end());
  // For Gaussian noise the second difference has standard deviation sqrt(6) sigma and its absolute
  // value a median of 0.6745 sqrt(6) sigma.
  return second[mid] * 1.4826 / std::sqrt(6.0);
}

std::vector<PointRun> split_at_breakpoints(const Scan& scan, const std::vector<ScanPoint>& points,
                                           const BreakpointOptions& options) {
  std::vector<PointRun> runs;
  if (points.empty()) return runs;
  if (!(options.lambda > 0.0) || options.lambda >= std::numbers::pi)
    throw Error("the breakpoint angle lambda must be in (0, pi)");
  double sigma = options.sigma_r;
  if (!(sigma > 0.0)) sigma = std::max(estimate_range_noise(scan), options.sigma_r_floor);
  PointRun run{0, 0};
  double cached_dphi = -1.0, cached_factor = 0.0;  // the angular step is nearly always the same
  for (std::size_t k = 1; k < points.size(); ++k) {
    const std::size_t a = points[k - 1].index, b = points[k].index;
    const double dphi = std::abs(scan.angles[b] - scan.angles[a]);
    const double dx = points[k].point.x - points[k - 1].point.x, dy = points[k].point.y - points[k - 1].point.y;
    const double gap = std::sqrt(dx * dx + dy * dy);
    // Beyond lambda the formula has no meaning (the step itself is too wide): always split.
    bool split = dphi >= options.lambda;
    if (!split) {
      if (std::abs(dphi - cached_dphi) > 1e-12) {
        cached_dphi = dphi;
        cached_factor = std::sin(dphi) / std::sin(options.lambda - dphi);
      }
      split = gap > scan.ranges[a] * cached_factor + 3.0 * sigma;
    }
    if (split) {
      runs.push_back(run);
      run = {k, k};
    } else {
      run.last = k;
    }
  }
  runs.push_back(run);
  return runs;
}

std::vector<PointRun> split_at_gaps(const std::vector<ScanPoint>& points, double max_gap) {
  std::vector<PointRun> runs;
  if (points.empty()) return runs;
  if (!(max_gap > 0.0)) throw Error("the maximum gap D_max must be positive");
  PointRun run{0, 0};
  const double max_gap2 = max_gap * max_gap;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const double dx = points[k].point.x - points[k - 1].point.x, dy = points[k].point.y - points[k - 1].point.y;
    if (dx * dx + dy * dy > max_gap2) {
      runs.push_back(run);
      run = {k, k};
    } else {
      run.last = k;
    }
  }
  runs.push_back(run);
  return runs;
}

}  // namespace topocut
