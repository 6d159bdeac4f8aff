#pragma once
// A planar laser scan: one (angle, range) pair per beam, in the sensor frame (x forward, y left,
// angles counter-clockwise from x). Invalid readings stay in place so that beam indices always equal
// the rows of the input; every consumer skips them through is_valid().
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut {

struct Scan {
  std::vector<double> angles;  // radians, one per beam
  std::vector<double> ranges;  // metres, one per beam; +inf means "no return"
  double range_min = 0.0;      // readings below (or equal to zero) are invalid
  double range_max = std::numeric_limits<double>::infinity();  // readings above are invalid

  std::size_t size() const { return ranges.size(); }

  // True when beam i has a usable reading: finite, > 0, within [range_min, range_max], finite angle.
  bool is_valid(std::size_t i) const {
    if (i >= ranges.size() || i >= angles.size()) return false;
    const double r = ranges[i];
    return std::isfinite(r) && std::isfinite(angles[i]) && r > 0.0 && r >= range_min && r <= range_max;
  }
};

// A valid beam as a point in the sensor frame, with the row it came from.
struct ScanPoint {
  Point2 point;
  std::size_t index = 0;  // row of the scan (beam index)
};

// Robot (or sensor) pose in the world: position in metres, heading in radians.
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
  friend bool operator==(const Pose2&, const Pose2&) = default;
};

// Throws Error unless angles and ranges have the same length and the range limits are sane.
void validate(const Scan& scan);

// Number of valid beams.
std::size_t count_valid(const Scan& scan);

// The valid beams as sensor-frame points in beam order (invalid beams skipped, indices kept).
std::vector<ScanPoint> valid_points(const Scan& scan);

// Sensor-frame point of beam i (range·cos, range·sin), whether valid or not.
Point2 beam_point(const Scan& scan, std::size_t i);

// Maps a point from the frame of `pose` into the world frame.
Point2 to_world(const Pose2& pose, const Point2& local);

// Maps a world point into the frame of `pose` (inverse of to_world).
Point2 to_local(const Pose2& pose, const Point2& world);

}  // namespace topocut
