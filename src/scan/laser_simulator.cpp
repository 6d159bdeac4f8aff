#include "topocut/scan/laser_simulator.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "topocut/core/error.h"
#include "topocut/core/infinity.h"
#include "topocut/scan/grid_ray.h"

namespace topocut {

namespace {

void validate_spec(const LaserSpec& spec) {
  if (!std::isfinite(spec.angular_resolution) || spec.angular_resolution <= 0.0)
    throw Error("the laser angular resolution must be a positive number of radians");
  if (!std::isfinite(spec.field_of_view) || spec.field_of_view <= 0.0 ||
      spec.field_of_view > 2.0 * std::numbers::pi + 1e-9)
    throw Error("the laser field of view must be in (0, 2*pi] radians");
  if (!(spec.range_min >= 0.0) || !(spec.range_max > spec.range_min))
    throw Error("the laser range limits must satisfy 0 <= range_min < range_max");
  if (!std::isfinite(spec.noise_stddev) || spec.noise_stddev < 0.0)
    throw Error("the laser noise standard deviation must be finite and >= 0");
}

Scan empty_scan(const LaserSpec& spec, const std::vector<double>& angles) {
  Scan scan;
  scan.angles = angles;
  scan.ranges.assign(angles.size(), kInfinity);
  scan.range_min = spec.range_min;
  scan.range_max = spec.range_max;
  return scan;
}

void add_noise(SimulatedScan& result, const LaserSpec& spec, std::mt19937& rng) {
  if (spec.noise_stddev <= 0.0) return;
  std::normal_distribution<double> noise(0.0, spec.noise_stddev);
  for (std::size_t i = 0; i < result.hit.size(); ++i) {
    if (result.hit[i] >= 0) result.scan.ranges[i] += noise(rng);
  }
}

}  // namespace

std::vector<double> beam_angles(const LaserSpec& spec) {
  validate_spec(spec);
  const double full = 2.0 * std::numbers::pi;
  std::size_t n = 0;
  if (spec.field_of_view >= full - 1e-9) {
    n = static_cast<std::size_t>(std::llround(full / spec.angular_resolution));
  } else {
    // The small tolerance keeps 270 deg / 0.6 deg at 451 beams despite rounding of the quotient.
    n = static_cast<std::size_t>(std::floor(spec.field_of_view / spec.angular_resolution + 1e-9)) + 1;
  }
  if (n > 10'000'000) throw Error("the laser would have more than 10 million beams");
  n = std::max<std::size_t>(n, 1);
  std::vector<double> angles(n);
  const double first = -0.5 * spec.field_of_view;
  for (std::size_t i = 0; i < n; ++i) angles[i] = first + static_cast<double>(i) * spec.angular_resolution;
  return angles;
}

SimulatedScan simulate_scan(const std::vector<Segment2>& walls, const Pose2& pose, const LaserSpec& spec,
                            std::mt19937& rng) {
  const std::vector<double> angles = beam_angles(spec);
  SimulatedScan result{empty_scan(spec, angles), std::vector<int>(angles.size(), -1)};
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double a = pose.theta + angles[i];
    const Point2 d{std::cos(a), std::sin(a)};
    double best = kInfinity;
    int best_index = -1;
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const Segment2& w = walls[k];
      const Point2 e = w.b - w.a;
      const double denom = cross(d, e);
      if (denom == 0.0) continue;  // parallel (a grazing beam sees no surface)
      const Point2 p = w.a - Point2{pose.x, pose.y};
      const double t = cross(p, e) / denom;  // distance along the beam
      const double s = cross(p, d) / denom;  // position along the wall
      if (t < 0.0 || s < 0.0 || s > 1.0) continue;
      if (t < best) {
        best = t;
        best_index = static_cast<int>(k);
      }
    }
    if (best_index >= 0 && best <= spec.range_max) {
      result.scan.ranges[i] = best;
      result.hit[i] = best_index;
    }
  }
  add_noise(result, spec, rng);
  return result;
}

SimulatedScan simulate_scan(const std::vector<Segment2>& walls, const Pose2& pose, const LaserSpec& spec) {
  std::mt19937 rng(spec.seed);
  return simulate_scan(walls, pose, spec, rng);
}

SimulatedScan simulate_scan(const OccupancyGrid& grid, const Pose2& pose, const LaserSpec& spec, std::mt19937& rng) {
  validate(grid);
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta))
    throw Error("the laser pose must be finite");
  const std::vector<double> angles = beam_angles(spec);
  SimulatedScan result{empty_scan(spec, angles), std::vector<int>(angles.size(), -1)};
  const int width = grid.width(), height = grid.height();
  const double res = grid.resolution;
  // Continuous cell coordinates: column axis u, bottom-up row axis v, one unit per cell.
  const double pu = (pose.x - grid.origin.x) / res;
  const double pv = (pose.y - grid.origin.y) / res;
  const double max_t = spec.range_max / res;
  auto blocks = [&](int column, int bottom_row) {
    const unsigned char value = grid.cells.ptr<unsigned char>(height - 1 - bottom_row)[column];
    if (value == kOccupied) return true;
    return spec.unknown_blocks && value != kFree;
  };
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double a = pose.theta + angles[i];
    const double du = std::cos(a), dv = std::sin(a);
    // Clip the beam to the grid rectangle [0,W]x[0,H] (slab method), so poses outside work too.
    double t_enter = 0.0, t_exit = max_t;
    bool misses = false;
    for (int axis = 0; axis < 2; ++axis) {
      const double p = axis == 0 ? pu : pv, d = axis == 0 ? du : dv, hi = axis == 0 ? width : height;
      if (d == 0.0) {
        if (p < 0.0 || p > hi) misses = true;
        continue;
      }
      double t0 = (0.0 - p) / d, t1 = (hi - p) / d;
      if (t0 > t1) std::swap(t0, t1);
      t_enter = std::max(t_enter, t0);
      t_exit = std::min(t_exit, t1);
    }
    if (misses || t_enter > t_exit) continue;
    walk_grid_ray(width, height, pu, pv, du, dv, t_enter, max_t, [&](int column, int row, double t) {
      if (!blocks(column, row)) return true;
      result.scan.ranges[i] = t * res;
      result.hit[i] = (height - 1 - row) * width + column;
      return false;
    });
  }
  add_noise(result, spec, rng);
  return result;
}

SimulatedScan simulate_scan(const OccupancyGrid& grid, const Pose2& pose, const LaserSpec& spec) {
  std::mt19937 rng(spec.seed);
  return simulate_scan(grid, pose, spec, rng);
}

}  // namespace topocut
