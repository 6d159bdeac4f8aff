#include "topocut/lines/iepf.h"
#include "topocut/lines/line_tracking.h"
#include "topocut/lines/sef.h"

#include <cmath>

#include "lines/common.h"
#include "topocut/core/error.h"

namespace topocut {

namespace {

// The infinite line through a and b, for distances (from a itself when the points coincide).
struct Chord {
  Point2 a;
  Point2 normal;  // unit
  bool degenerate = true;
  Chord(const Point2& from, const Point2& to) : a(from) {
    const Point2 d = to - from;
    const double len = std::sqrt(dot(d, d));
    if (len > 0.0) normal = {-d.y / len, d.x / len}, degenerate = false;
  }
  double distance(const Point2& p) const {
    if (degenerate) return std::sqrt(dot(p - a, p - a));
    return std::abs(dot(p - a, normal));
  }
};

// Whether p lies within t of the line through a and b (of a itself when they coincide), without
// square roots: |cross(b - a, p - a)|^2 <= t^2 |b - a|^2.
bool within_chord(const Point2& a, const Point2& b, const Point2& p, double t) {
  const Point2 d = b - a, w = p - a;
  const double len2 = dot(d, d);
  if (len2 == 0.0) return dot(w, w) <= t * t;
  const double c = cross(d, w);
  return c * c <= t * t * len2;
}

// Groups of one run never touch groups of another run; inside a run they all touch.
void append_groups(std::vector<PointRun>& groups, std::vector<bool>& neighbours, const std::vector<PointRun>& inside) {
  if (!groups.empty()) neighbours.back() = false;
  for (const PointRun& g : inside) {
    groups.push_back(g);
    neighbours.push_back(true);
  }
}

}  // namespace

std::vector<Line> extract_lines_sef(const Scan& scan, const SefOptions& options) {
  detail::require_positive(options.d_max, "D_max");
  detail::require_positive(options.t_max, "T_max");
  const std::vector<ScanPoint> points = detail::prepared_points(scan);
  std::vector<PointRun> groups;
  std::vector<bool> neighbours;
  for (const PointRun& run : split_at_gaps(points, options.d_max)) {
    std::vector<PointRun> inside;
    PointRun current{run.first, run.first};
    for (std::size_t k = run.first + 1; k <= run.last; ++k) {
      // The edge runs from the line's first point through its middle point: unlike the chord to the
      // last point it cannot bend round a corner one small step at a time.
      const std::size_t middle = current.first + (current.last - current.first + 1) / 2;
      const bool follows = current.size() < 2 ||
                           within_chord(points[current.first].point, points[middle].point, points[k].point, options.t_max);
      if (follows) {
        current.last = k;
      } else {
        inside.push_back(current);
        current = {k, k};
      }
    }
    inside.push_back(current);
    append_groups(groups, neighbours, inside);
  }
  detail::refine_boundaries(points, groups, neighbours);
  detail::trim_run_ends(points, groups, neighbours);
  return detail::lines_from_runs(scan, points, groups, options.min_points);
}

std::vector<Line> extract_lines_lt(const Scan& scan, const LtOptions& options) {
  detail::require_positive(options.d_max, "D_max");
  detail::require_positive(options.t_max, "T_max");
  const std::vector<ScanPoint> points = detail::prepared_points(scan);
  std::vector<PointRun> groups;
  std::vector<bool> neighbours;
  for (const PointRun& run : split_at_gaps(points, options.d_max)) {
    std::vector<PointRun> inside;
    PointRun current{run.first, run.first};
    Moments m;
    m.add(points[run.first].point);
    for (std::size_t k = run.first + 1; k <= run.last; ++k) {
      const Point2& p = points[k].point;
      bool tracks = current.size() < 2;
      if (!tracks) {
        tracks = m.normal_form().distance(p) <= options.t_max;
      }
      if (tracks) {
        current.last = k;
        m.add(p);
      } else {
        inside.push_back(current);
        current = {k, k};
        m = Moments{};
        m.add(p);
      }
    }
    inside.push_back(current);
    append_groups(groups, neighbours, inside);
  }
  detail::refine_boundaries(points, groups, neighbours);
  detail::trim_run_ends(points, groups, neighbours);
  return detail::lines_from_runs(scan, points, groups, options.min_points);
}

std::vector<Line> extract_lines_iepf(const Scan& scan, const IepfOptions& options) {
  detail::require_positive(options.t_max, "T_max");
  const std::vector<ScanPoint> points = detail::prepared_points(scan);
  std::vector<PointRun> groups;
  std::vector<bool> neighbours;
  std::vector<PointRun> stack;
  detail::SplitBudget budget("IEPF");
  for (const PointRun& run : split_at_breakpoints(scan, points, options.breakpoints)) {
    // Split phase (depth-first, left part first, so pieces come out in scan order).
    std::vector<PointRun> pieces;
    stack.assign(1, run);
    while (!stack.empty()) {
      const PointRun r = stack.back();
      stack.pop_back();
      budget.spend(r.size());
      const Chord chord(points[r.first].point, points[r.last].point);
      double worst = 0.0;
      std::size_t at = r.first;
      for (std::size_t k = r.first + 1; k < r.last; ++k) {
        const double d = chord.distance(points[k].point);
        if (d > worst) worst = d, at = k;
      }
      if (worst > options.t_max) {
        stack.push_back({at + 1, r.last});
        stack.push_back({r.first, at});
      } else {
        pieces.push_back(r);
      }
    }
    // Merge phase: fuse neighbours whose common line still holds every point within T_max.
    if (options.merge && pieces.size() > 1) {
      std::vector<PointRun> merged{pieces.front()};
      for (std::size_t i = 1; i < pieces.size(); ++i) {
        const PointRun fused{merged.back().first, pieces[i].last};
        if (detail::max_distance(points, fused, detail::moments_of(points, fused).normal_form()) <= options.t_max) {
          merged.back() = fused;
        } else {
          merged.push_back(pieces[i]);
        }
      }
      pieces = std::move(merged);
    }
    append_groups(groups, neighbours, pieces);
  }
  detail::refine_boundaries(points, groups, neighbours);
  detail::trim_run_ends(points, groups, neighbours);
  return detail::lines_from_runs(scan, points, groups, options.min_points);
}

}  // namespace topocut
