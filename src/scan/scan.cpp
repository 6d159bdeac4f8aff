#include "topocut/scan/scan.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "topocut/core/error.h"

namespace topocut {

void validate(const Scan& scan) {
  if (scan.angles.size() != scan.ranges.size())
    throw Error("a scan needs one angle per range, got " + std::to_string(scan.angles.size()) + " angles and " +
                std::to_string(scan.ranges.size()) + " ranges");
  if (std::isnan(scan.range_min) || std::isnan(scan.range_max) || scan.range_min < 0.0 ||
      scan.range_max < scan.range_min)
    throw Error("the scan range limits must satisfy 0 <= range_min <= range_max");
}

std::size_t count_valid(const Scan& scan) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < scan.size(); ++i) n += scan.is_valid(i) ? 1 : 0;
  return n;
}

std::vector<ScanPoint> valid_points(const Scan& scan) {
  std::vector<ScanPoint> points;
  points.reserve(scan.size());
  const std::size_t n = std::min(scan.size(), scan.angles.size());
  // Lasers space their beams evenly; then rotating (cos, sin) by the step replaces one sincos call
  // per beam (the bulk of the cost of small extractors). Re-anchoring every 32 beams keeps the
  // rounding drift below 1e-14.
  bool even = n >= 3;
  const double step = even ? (scan.angles[n - 1] - scan.angles[0]) / static_cast<double>(n - 1) : 0.0;
  for (std::size_t i = 0; even && i < n; ++i) {
    const double expected = scan.angles[0] + static_cast<double>(i) * step;
    even = std::abs(scan.angles[i] - expected) <= 1e-13 * std::max(1.0, std::abs(expected));
  }
  if (!even) {
    for (std::size_t i = 0; i < n; ++i)
      if (scan.is_valid(i)) points.push_back({beam_point(scan, i), i});
    return points;
  }
  const double cs = std::cos(step), ss = std::sin(step);
  double c = 0.0, s = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 32 == 0) {
      c = std::cos(scan.angles[i]);
      s = std::sin(scan.angles[i]);
    } else {
      const double c_next = c * cs - s * ss;
      s = s * cs + c * ss;
      c = c_next;
    }
    if (scan.is_valid(i)) points.push_back({{scan.ranges[i] * c, scan.ranges[i] * s}, i});
  }
  return points;
}

Point2 beam_point(const Scan& scan, std::size_t i) {
  const double r = scan.ranges.at(i);
  const double a = scan.angles.at(i);
  return {r * std::cos(a), r * std::sin(a)};
}

Point2 to_world(const Pose2& pose, const Point2& local) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  return {pose.x + c * local.x - s * local.y, pose.y + s * local.x + c * local.y};
}

Point2 to_local(const Pose2& pose, const Point2& world) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double dx = world.x - pose.x, dy = world.y - pose.y;
  return {c * dx + s * dy, -s * dx + c * dy};
}

}  // namespace topocut
