#pragma once
// Internal: running first and second moments of a point set, so that fits of growing, shrinking or
// fused sets cost O(1). Used for decisions inside the extractors; the reported lines are refitted
// with the two-pass fit_line for accuracy.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include "topocut/lines/line_fit.h"

namespace topocut {

// Polar fit from a centroid and centred second moments (shared with fit_line).
LineFit from_moments(const Point2& centroid, double suu, double suv, double svv, double weight);

// Least-squares line through points (weights empty: all 1) in two passes, centroid first, which keeps
// the moments exact enough for noiseless data far from the origin; sigma is left 0. Empty or
// zero-weight input gives a default LineFit.
LineFit centred_fit(std::span<const Point2> points, std::span<const double> weights = {});

// A fitted line with its normal precomputed, for loops that measure many distances to one line.
struct NormalForm {
  double nx = 1.0, ny = 0.0, rho = 0.0;
  NormalForm() = default;
  explicit NormalForm(const LineFit& f) : nx(std::cos(f.alpha)), ny(std::sin(f.alpha)), rho(f.rho) {}
  double distance(const Point2& p) const { return std::abs(p.x * nx + p.y * ny - rho); }
};

struct Moments {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, syy = 0.0;

  void add(const Point2& p, double w = 1.0) {
    n += w;
    sx += w * p.x;
    sy += w * p.y;
    sxx += w * p.x * p.x;
    sxy += w * p.x * p.y;
    syy += w * p.y * p.y;
  }
  void remove(const Point2& p) { add(p, -1.0); }
  Moments operator+(const Moments& o) const {
    return {n + o.n, sx + o.sx, sy + o.sy, sxx + o.sxx, sxy + o.sxy, syy + o.syy};
  }
  Moments operator-(const Moments& o) const {
    return {n - o.n, sx - o.sx, sy - o.sy, sxx - o.sxx, sxy - o.sxy, syy - o.syy};
  }
  LineFit fit() const {
    if (n <= 0.0) return {};
    const Point2 c{sx / n, sy / n};
    const double suu = std::max(0.0, sxx - n * c.x * c.x);
    const double svv = std::max(0.0, syy - n * c.y * c.y);
    const double suv = sxy - n * c.x * c.y;
    return from_moments(c, suu, suv, svv, n);
  }
  // RMS perpendicular distance to the fitted line (smaller eigenvalue of the scatter matrix), without
  // computing the line.
  double sigma() const {
    if (n <= 0.0) return 0.0;
    const double cx = sx / n, cy = sy / n;
    const double suu = std::max(0.0, sxx - n * cx * cx);
    const double svv = std::max(0.0, syy - n * cy * cy);
    const double suv = sxy - n * cx * cy;
    const double half_diff = 0.5 * (suu - svv);
    const double lambda_min = 0.5 * (suu + svv) - std::sqrt(half_diff * half_diff + suv * suv);
    return std::sqrt(std::max(0.0, lambda_min) / n);
  }
  // The fitted line's normal form without trigonometry: the normal is the eigenvector of the
  // smallest eigenvalue of the 2x2 scatter matrix [[suu, suv], [suv, svv]] (the same line as fit()).
  NormalForm normal_form() const {
    NormalForm f;
    if (n <= 0.0) return f;
    const double cx = sx / n, cy = sy / n;
    const double suu = std::max(0.0, sxx - n * cx * cx);
    const double svv = std::max(0.0, syy - n * cy * cy);
    const double suv = sxy - n * cx * cy;
    const double half_diff = 0.5 * (suu - svv);
    const double root = std::sqrt(half_diff * half_diff + suv * suv);
    double nx, ny;
    if (root <= 1e-12 * (suu + svv) || root == 0.0) {
      nx = cx, ny = cy;  // no preferred direction: face the sensor, as fit_line does
      if (nx == 0.0 && ny == 0.0) nx = 1.0;
    } else if (half_diff >= 0.0) {
      // (S - lambda_min I) n = 0 with lambda_min = (suu + svv)/2 - root; pick the better-conditioned row.
      nx = suv, ny = -(half_diff + root);
    } else {
      nx = half_diff - root, ny = suv;
    }
    const double len = std::sqrt(nx * nx + ny * ny);
    f.nx = nx / len;
    f.ny = ny / len;
    f.rho = f.nx * cx + f.ny * cy;
    return f;
  }
};

}  // namespace topocut
