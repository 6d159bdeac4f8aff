#include "topocut/lines/lowess.h"

#include <algorithm>
#include <cmath>

#include "topocut/core/error.h"

namespace topocut {

namespace {

double tricube(double u) {
  u = std::abs(u);
  if (u >= 1.0) return 0.0;
  const double t = 1.0 - u * u * u;
  return t * t * t;
}

double bisquare(double u) {
  u = std::abs(u);
  if (u >= 1.0) return 0.0;
  const double t = 1.0 - u * u;
  return t * t;
}

}  // namespace

std::vector<double> lowess(std::span<const double> x, std::span<const double> y, const LowessOptions& options) {
  const std::size_t n = x.size();
  if (y.size() != n) throw Error("lowess needs as many x as y values");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) throw Error("lowess needs finite values");
    if (i > 0 && x[i] < x[i - 1]) throw Error("lowess needs non-decreasing x values");
  }
  if (!(options.span > 0.0) && options.neighbours == 0) throw Error("the lowess span must be positive");
  if (options.iterations < 0) throw Error("the number of lowess robustness iterations must be >= 0");
  std::vector<double> fitted(y.begin(), y.end());
  if (n < 2) return fitted;

  std::size_t r = options.neighbours > 0 ? options.neighbours
                                         : static_cast<std::size_t>(std::llround(options.span * static_cast<double>(n)));
  r = std::clamp<std::size_t>(r, 2, n);

  double y_scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) y_scale = std::max(y_scale, std::abs(y[i]));
  std::vector<double> robustness(n, 1.0);
  std::vector<double> residuals(n);
  for (int round = 0; round <= options.iterations; ++round) {
    std::size_t lo = 0;
    for (std::size_t i = 0; i < n; ++i) {
      // Slide the window [lo, lo + r) to the r nearest neighbours of x[i] (x is sorted).
      while (lo + r < n && x[lo + r] - x[i] < x[i] - x[lo]) ++lo;
      const std::size_t hi = lo + r - 1;
      const double h = std::max(x[i] - x[lo], x[hi] - x[i]);
      double sw = 0.0, sx = 0.0, sy = 0.0;
      for (std::size_t j = lo; j <= hi; ++j) {
        const double d = std::abs(x[j] - x[i]);
        const double w = robustness[j] * (h > 0.0 ? tricube(d / h) : (d == 0.0 ? 1.0 : 0.0));
        sw += w;
        sx += w * x[j];
        sy += w * y[j];
      }
      if (sw <= 0.0) {
        fitted[i] = y[i];  // every neighbour was rejected: keep the observation
        continue;
      }
      const double mx = sx / sw, my = sy / sw;
      double sxx = 0.0, sxy = 0.0;
      for (std::size_t j = lo; j <= hi; ++j) {
        const double d = std::abs(x[j] - x[i]);
        const double w = robustness[j] * (h > 0.0 ? tricube(d / h) : (d == 0.0 ? 1.0 : 0.0));
        sxx += w * (x[j] - mx) * (x[j] - mx);
        sxy += w * (x[j] - mx) * (y[j] - my);
      }
      // A neighbourhood without spread in x supports only a constant (local mean).
      const double range = x[hi] - x[lo];
      const bool has_slope = sxx > 1e-14 * sw * range * range && range > 0.0;
      fitted[i] = has_slope ? my + (sxy / sxx) * (x[i] - mx) : my;
    }
    if (round == options.iterations) break;
    for (std::size_t i = 0; i < n; ++i) residuals[i] = std::abs(y[i] - fitted[i]);
    std::vector<double> sorted = residuals;
    const std::size_t mid = n / 2;
    std::nth_element(sorted.begin(), sorted.begin() + mid, sorted.end());
    double median = sorted[mid];
    if (n % 2 == 0) median = 0.5 * (median + *std::max_element(sorted.begin(), sorted.begin() + mid));
    // A median at rounding level means the curve is already exact; bisquare weights from rounding
    // noise would reject good points at random.
    if (median <= 1e-12 * y_scale) break;
    for (std::size_t i = 0; i < n; ++i) robustness[i] = bisquare(residuals[i] / (6.0 * median));
  }
  return fitted;
}

}  // namespace topocut
