#include "lines/common.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "topocut/core/error.h"

namespace topocut::detail {

std::vector<ScanPoint> prepared_points(const Scan& scan) {
  validate(scan);
  std::vector<ScanPoint> points = valid_points(scan);
  for (std::size_t k = 1; k < points.size(); ++k) {
    if (!(scan.angles[points[k].index] > scan.angles[points[k - 1].index]))
      throw Error("the scan angles must be strictly increasing, but beam " + std::to_string(points[k].index) +
                  " does not follow beam " + std::to_string(points[k - 1].index));
  }
  return points;
}

Moments moments_of(const std::vector<ScanPoint>& points, const PointRun& run) {
  Moments m;
  for (std::size_t k = run.first; k <= run.last; ++k) m.add(points[k].point);
  return m;
}

double max_distance(const std::vector<ScanPoint>& points, const PointRun& run, const NormalForm& line) {
  double worst = 0.0;
  for (std::size_t k = run.first; k <= run.last; ++k) worst = std::max(worst, line.distance(points[k].point));
  return worst;
}

void refine_boundaries(const std::vector<ScanPoint>& points, std::vector<PointRun>& groups,
                       const std::vector<bool>& neighbours) {
  if (groups.size() < 2) return;
  std::vector<Moments> m(groups.size());
  std::vector<NormalForm> line(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) {
    m[g] = moments_of(points, groups[g]);
    line[g] = m[g].normal_form();
  }
  // A boundary can only settle once both neighbouring lines are clean, and cleaning one line may
  // move its other boundary: sweep again over the boundaries next to a changed group.
  std::vector<bool> dirty(groups.size(), true), next(groups.size(), false);
  for (int pass = 0; pass < 20; ++pass) {
    bool any = false;
    std::fill(next.begin(), next.end(), false);
    for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
      if (!neighbours[g] || (!dirty[g] && !dirty[g + 1])) continue;
      PointRun& a = groups[g];
      PointRun& b = groups[g + 1];
      // The cap guards against cycling on exact ties.
      for (std::size_t guard = 0; guard < a.size() + b.size(); ++guard) {
        bool moved = false;
        if (a.size() > 2) {
          const Point2& p = points[a.last].point;
          if (line[g + 1].distance(p) < line[g].distance(p)) {
            m[g].remove(p);
            m[g + 1].add(p);
            --a.last;
            --b.first;
            moved = true;
          }
        }
        if (!moved && b.size() > 2) {
          const Point2& p = points[b.first].point;
          if (line[g].distance(p) < line[g + 1].distance(p)) {
            m[g + 1].remove(p);
            m[g].add(p);
            ++a.last;
            ++b.first;
            moved = true;
          }
        }
        if (!moved) break;
        line[g] = m[g].normal_form();
        line[g + 1] = m[g + 1].normal_form();
        any = true;
        next[g] = next[g + 1] = true;
      }
    }
    if (!any) break;
    dirty.swap(next);
  }
}

void trim_run_ends(const std::vector<ScanPoint>& points, std::vector<PointRun>& groups,
                   const std::vector<bool>& neighbours) {
  // A lone point off the line: farther than 3 RMSE of the rest (a scale-free test; the absolute floor
  // keeps exactly collinear points, whose rest RMSE is rounding noise, from being dropped).
  auto outlying = [&](std::size_t end, const PointRun& rest) {
    const Moments m = moments_of(points, rest);
    const Point2& p = points[end].point;
    const double floor = 1e-9 * (1.0 + std::abs(p.x) + std::abs(p.y));
    return m.normal_form().distance(p) > 3.0 * m.sigma() + floor;
  };
  for (std::size_t g = 0; g < groups.size(); ++g) {
    PointRun& run = groups[g];
    const bool starts_run = g == 0 || !neighbours[g - 1];
    const bool ends_run = !neighbours[g];
    for (int i = 0; i < 2 && starts_run && run.size() > 3; ++i) {
      if (!outlying(run.first, {run.first + 1, run.last})) break;
      ++run.first;
    }
    for (int i = 0; i < 2 && ends_run && run.size() > 3; ++i) {
      if (!outlying(run.last, {run.first, run.last - 1})) break;
      --run.last;
    }
  }
}

void merge_collinear(const std::vector<ScanPoint>& points, std::vector<PointRun>& groups, std::vector<bool>& neighbours,
                     double tolerance) {
  if (groups.empty()) return;
  std::vector<PointRun> merged{groups.front()};
  std::vector<bool> merged_neighbours{neighbours.front()};
  for (std::size_t g = 1; g < groups.size(); ++g) {
    PointRun& last = merged.back();
    if (merged_neighbours.back()) {
      const Moments ma = moments_of(points, last), mb = moments_of(points, groups[g]);
      if ((ma + mb).sigma() <= std::max(ma.sigma(), mb.sigma()) + tolerance) {
        const PointRun fused{last.first, groups[g].last};
        last = fused;
        merged_neighbours.back() = neighbours[g];
        continue;
      }
    }
    merged.push_back(groups[g]);
    merged_neighbours.push_back(neighbours[g]);
  }
  groups = std::move(merged);
  neighbours = std::move(merged_neighbours);
}

void refine_labels(const std::vector<ScanPoint>& points, const std::vector<bool>& joined, std::vector<int>& labels,
                   std::vector<Moments>& lines) {
  std::vector<NormalForm> normal(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) normal[i] = lines[i].normal_form();
  for (int pass = 0; pass < 50; ++pass) {
    bool moved = false;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const int a = labels[k];
      if (a < 0) continue;
      for (int side = 0; side < 2; ++side) {
        const bool has = side == 0 ? (k > 0 && joined[k - 1]) : (k + 1 < points.size() && joined[k]);
        if (!has) continue;
        const int b = labels[side == 0 ? k - 1 : k + 1];
        if (b < 0 || b == a || lines[static_cast<std::size_t>(a)].n <= 2.0) continue;
        const Point2& p = points[k].point;
        if (normal[static_cast<std::size_t>(b)].distance(p) < normal[static_cast<std::size_t>(a)].distance(p)) {
          lines[static_cast<std::size_t>(a)].remove(p);
          lines[static_cast<std::size_t>(b)].add(p);
          normal[static_cast<std::size_t>(a)] = lines[static_cast<std::size_t>(a)].normal_form();
          normal[static_cast<std::size_t>(b)] = lines[static_cast<std::size_t>(b)].normal_form();
          labels[k] = b;
          moved = true;
          break;
        }
      }
    }
    if (!moved) break;
  }
}

Line line_from_positions(const std::vector<ScanPoint>& points, const std::vector<std::size_t>& positions) {
  std::vector<std::size_t> support;
  std::vector<Point2> xy;
  support.reserve(positions.size());
  xy.reserve(positions.size());
  for (const std::size_t k : positions) {
    support.push_back(points[k].index);
    xy.push_back(points[k].point);
  }
  return line_from_points(std::move(support), xy);
}

std::vector<Line> lines_from_runs(const Scan& scan, const std::vector<ScanPoint>& points,
                                  const std::vector<PointRun>& groups, std::size_t min_points) {
  std::vector<Line> lines;
  std::vector<std::size_t> positions;
  for (const PointRun& run : groups) {
    if (run.size() < std::max<std::size_t>(min_points, 2)) continue;
    positions.resize(run.size());
    for (std::size_t k = 0; k < run.size(); ++k) positions[k] = run.first + k;
    lines.push_back(line_from_positions(points, positions));
  }
  return lines;
}

void require_positive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0) throw Error(std::string("the option ") + name + " must be a positive number");
}

void SplitBudget::spend(std::size_t visits) {
  spent_ += visits;
  if (spent_ > kMaxSplitVisits)
    throw Error(std::string("the scan's ") + method_ + " split needs more than " + std::to_string(kMaxSplitVisits) +
                " point visits (the limit; a real scan needs a few per beam): a degenerate scan");
}

}  // namespace topocut::detail
