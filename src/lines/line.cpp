#include "topocut/lines/line.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "topocut/core/error.h"
#include "lines/common.h"
#include "lines/moments.h"
#include "topocut/lines/line_fit.h"

namespace topocut {

namespace detail {

Line line_from_points(std::vector<std::size_t> support, const std::vector<Point2>& points) {
  // fit_line without its residual pass: a Line carries no sigma.
  const LineFit fit = centred_fit(points);
  Line line;
  line.rho = fit.rho;
  line.alpha = fit.alpha;
  // Position along the line direction (-sin, cos); the extremes bound the observed wall.
  const double nx = std::cos(fit.alpha), ny = std::sin(fit.alpha);
  const double tx = -ny, ty = nx;
  double t_lo = 0.0, t_hi = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double t = points[k].x * tx + points[k].y * ty;
    if (k == 0 || t < t_lo) t_lo = t;
    if (k == 0 || t > t_hi) t_hi = t;
  }
  // The projection of a point is rho * n + t * direction.
  const Point2 a{fit.rho * nx + t_lo * tx, fit.rho * ny + t_lo * ty};
  const Point2 b{fit.rho * nx + t_hi * tx, fit.rho * ny + t_hi * ty};
  // Start on the side of the first (lowest) row, so sequential lines run in scan order.
  const double t_first = points[0].x * tx + points[0].y * ty;
  const bool first_near_lo = std::abs(t_first - t_lo) <= std::abs(t_first - t_hi);
  line.start = first_near_lo ? a : b;
  line.end = first_near_lo ? b : a;
  line.support = std::move(support);
  return line;
}

}  // namespace detail

Line make_line(const Scan& scan, std::vector<std::size_t> support) {
  std::sort(support.begin(), support.end());
  support.erase(std::unique(support.begin(), support.end()), support.end());
  if (support.empty()) throw Error("a line needs at least one supporting beam");
  std::vector<Point2> points;
  points.reserve(support.size());
  for (const std::size_t row : support) {
    if (!scan.is_valid(row)) throw Error("beam " + std::to_string(row) + " is not a valid reading of the scan");
    points.push_back(beam_point(scan, row));
  }
  return detail::line_from_points(std::move(support), points);
}

double length(const Line& line) { return distance(line.start, line.end); }

}  // namespace topocut
