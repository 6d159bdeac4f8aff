#include "topocut/lines/line_fit.h"

#include <cmath>
#include <numbers>

#include "lines/moments.h"
#include "topocut/core/error.h"

namespace topocut {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

// Polar parameters from centred second moments (eq. 8: tan 2 alpha = -2 Suv / (Svv - Suu)) and the
// centroid (eq. 9: rho = xc cos alpha + yc sin alpha), then the sign normalisation rho >= 0.
LineFit from_moments(const Point2& c, double suu, double suv, double svv, double weight) {
  LineFit fit;
  fit.centroid = c;
  fit.weight = weight;
  const double spread = suu + svv;
  double normal = 0.0;
  // No direction to speak of: all points coincide (up to rounding relative to their position).
  const double scale = weight * (c.x * c.x + c.y * c.y) + spread;
  if (spread <= 1e-24 * scale || spread == 0.0) {
    normal = (c.x == 0.0 && c.y == 0.0) ? 0.0 : std::atan2(c.y, c.x);
  } else {
    normal = 0.5 * std::atan2(-2.0 * suv, svv - suu);
  }
  const LineFit polar = polar_line(c, normal);
  fit.rho = polar.rho;
  fit.alpha = polar.alpha;
  // The minimum of the quadratic form is its smaller eigenvalue.
  const double half_diff = 0.5 * (suu - svv);
  const double lambda_min = 0.5 * spread - std::sqrt(half_diff * half_diff + suv * suv);
  fit.sigma = weight > 0.0 ? std::sqrt(std::max(0.0, lambda_min) / weight) : 0.0;
  return fit;
}

double normalize_angle(double angle) {
  if (!std::isfinite(angle)) return angle;
  if (angle > -kPi && angle <= kPi) return angle;
  double a = std::remainder(angle, 2.0 * kPi);  // in [-pi, pi]
  if (a <= -kPi) a += 2.0 * kPi;
  return a;
}

double angle_difference(double a, double b) { return std::abs(normalize_angle(a - b)); }

LineFit polar_line(const Point2& on_line, double normal_angle) {
  LineFit fit;
  double alpha = normalize_angle(normal_angle);
  double rho = on_line.x * std::cos(alpha) + on_line.y * std::sin(alpha);
  if (rho < 0.0) {
    rho = -rho;
    alpha = normalize_angle(alpha + kPi);
  }
  fit.rho = rho;
  fit.alpha = alpha;
  fit.centroid = on_line;
  return fit;
}

namespace {

// The eigenvalue formula loses half the digits to cancellation (sigma ~ 1e-8 for exact lines); a
// pass over the residuals about the centroid keeps sigma exact for collinear points.
double residual_rms(std::span<const Point2> points, std::span<const double> weights, const LineFit& fit) {
  const double nx = std::cos(fit.alpha), ny = std::sin(fit.alpha);
  double sum = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = (points[i].x - fit.centroid.x) * nx + (points[i].y - fit.centroid.y) * ny;
    sum += (weights.empty() ? 1.0 : weights[i]) * d * d;
  }
  return fit.weight > 0.0 ? std::sqrt(sum / fit.weight) : 0.0;
}

}  // namespace

LineFit centred_fit(std::span<const Point2> points, std::span<const double> weights) {
  auto weight = [&](std::size_t i) { return weights.empty() ? 1.0 : weights[i]; };
  double w_sum = 0.0;
  Point2 c;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double w = weight(i);
    w_sum += w;
    c.x += w * points[i].x;
    c.y += w * points[i].y;
  }
  if (w_sum <= 0.0) return {};
  c.x /= w_sum;
  c.y /= w_sum;
  double suu = 0.0, suv = 0.0, svv = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double u = points[i].x - c.x, v = points[i].y - c.y, w = weight(i);
    suu += w * u * u;
    suv += w * u * v;
    svv += w * v * v;
  }
  return from_moments(c, suu, suv, svv, w_sum);
}

LineFit fit_line(std::span<const Point2> points) {
  if (points.empty()) return {};
  LineFit fit = centred_fit(points);
  fit.sigma = residual_rms(points, {}, fit);
  return fit;
}

LineFit fit_line(std::span<const Point2> points, std::span<const double> weights) {
  if (points.size() != weights.size()) throw Error("fit_line needs one weight per point");
  for (const double w : weights) {
    if (!(w >= 0.0) || !std::isfinite(w)) throw Error("fit_line weights must be finite and >= 0");
  }
  LineFit fit = centred_fit(points, weights);
  if (fit.weight <= 0.0) return fit;
  fit.sigma = residual_rms(points, weights, fit);
  return fit;
}

double signed_distance(double rho, double alpha, const Point2& p) {
  return p.x * std::cos(alpha) + p.y * std::sin(alpha) - rho;
}

}  // namespace topocut
