#include "topocut/walls/wall_extraction.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "topocut/core/error.h"

namespace topocut {

void validate(const WallExtractionOptions& options) {
  if (!(options.max_range > 0.0)) throw Error("the maximum wall range must be positive");
  if (options.min_points < 2) throw Error("a wall line needs at least 2 supporting points");
  if (!(options.max_gap > 0.0)) throw Error("the largest gap inside a wall must be a positive number of metres");
}

std::vector<WallSegment> extract_wall_segments(const Scan& scan, const Pose2& pose, const WallExtractionOptions& options,
                                               int scan_index) {
  validate(scan);
  validate(options);
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta))
    throw Error("scan " + std::to_string(scan_index) + " has a non-finite pose");

  // Beams beyond max_range take no part: they are made invalid, keeping the rows.
  const Scan* source = &scan;
  Scan limited;
  if (std::isfinite(options.max_range)) {
    limited = scan;
    for (double& r : limited.ranges)
      if (r > options.max_range) r = std::numeric_limits<double>::quiet_NaN();
    source = &limited;
  }
  const Labeling labeling = label_scan(*source, options.labeling);

  LineExtractionOptions lines = options.lines;
  lines.sef.min_points = lines.lt.min_points = lines.iepf.min_points = lines.smf.min_points =
      lines.ale.min_points = options.min_points;

  std::vector<std::pair<std::size_t, WallSegment>> found;
  Scan part;
  std::vector<std::pair<double, int>> along;  // (position along the line, beam)
  part.range_min = source->range_min;
  part.range_max = source->range_max;
  for (const std::vector<int>& beams : labeling.segments) {
    if (beams.size() < options.min_points) continue;
    part.angles.clear();
    part.ranges.clear();
    for (int b : beams) {
      part.angles.push_back(source->angles[static_cast<std::size_t>(b)]);
      part.ranges.push_back(source->ranges[static_cast<std::size_t>(b)]);
    }
    for (const Line& line : extract_lines(part, lines)) {
      if (line.support.size() < options.min_points) continue;
      // Support points by their position along the line, cut at gaps.
      const Point2 u{-std::sin(line.alpha), std::cos(line.alpha)};
      const Point2 foot{line.rho * std::cos(line.alpha), line.rho * std::sin(line.alpha)};
      along.clear();
      for (std::size_t row : line.support) {
        const Point2 p = beam_point(part, row);
        along.emplace_back(dot(p, u), beams[row]);
      }
      std::sort(along.begin(), along.end());
      std::size_t begin = 0;
      for (std::size_t k = 1; k <= along.size(); ++k) {
        if (k < along.size() && along[k].first - along[k - 1].first <= options.max_gap) continue;
        if (k - begin >= options.min_points) {
          const double t0 = along[begin].first, t1 = along[k - 1].first;
          WallSegment wall;
          wall.segment = {to_world(pose, foot + t0 * u), to_world(pose, foot + t1 * u)};
          wall.scan = scan_index;
          wall.points = k - begin;
          int first_beam = along[begin].second;
          for (std::size_t j = begin; j < k; ++j) first_beam = std::min(first_beam, along[j].second);
          found.emplace_back(static_cast<std::size_t>(first_beam), wall);
        }
        begin = k;
      }
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<WallSegment> out;
  out.reserve(found.size());
  for (auto& [first, wall] : found) out.push_back(wall);
  return out;
}

}  // namespace topocut
