#pragma once
// Robust locally weighted linear regression (LOWESS, Cleveland 1979): each y_i is replaced by the
// value at x_i of a straight line fitted to its nearest neighbours with tri-cube distance weights
// (1 - |d/h|^3)^3, h = distance to the farthest neighbour; then, for `iterations` rounds, the fits
// are repeated with bisquare robustness weights (1 - (e/6s)^2)^2, s = median |residual|, so that
// outliers stop pulling the curve.
#include <cstddef>
#include <span>
#include <vector>

namespace topocut {

struct LowessOptions {
  double span = 2.0 / 3.0;     // fraction of the points in each neighbourhood (Cleveland's default)
  std::size_t neighbours = 0;  // if > 0, the neighbourhood size in points (overrides span)
  int iterations = 2;          // robustness rounds (Cleveland recommends 2)
};

// Smoothed values of y at each x. x must be non-decreasing and as long as y, values finite (throws
// Error otherwise). Neighbourhoods hold at least 2 and at most n points; the farthest neighbour gets
// weight 0 (as in Cleveland's definition), points tied at distance 0 all get weight 1. The
// robustness rounds stop early once the residuals' median is at rounding level (1e-12 max|y|: the curve is exact); a point
// whose neighbours all have weight 0 keeps its observed value (as R's lowess does).
std::vector<double> lowess(std::span<const double> x, std::span<const double> y, const LowessOptions& options = {});

}  // namespace topocut
