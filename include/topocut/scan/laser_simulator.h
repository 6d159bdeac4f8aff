#pragma once
// Simulated planar laser: rays cast from a pose against wall segments or against the occupied cells
// of an OccupancyGrid, with optional Gaussian range noise from a caller-seeded std::mt19937 (the
// same seed and inputs give the same scan). Each beam also reports what it hit, so that benchmarks
// can tell which wall produced which point.
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/scan/scan.h"

namespace topocut {

struct LaserSpec {
  // Beams are spread evenly over the field of view, centred on the heading, first beam at
  // -field_of_view/2; a full circle has no duplicated beam at +pi.
  double field_of_view = 2.0 * std::numbers::pi;          // radians
  double angular_resolution = std::numbers::pi / 360.0;  // radians between beams (0.5 degrees)
  double range_min = 0.0;                                 // metres
  double range_max = 5.0;                                 // metres; farther walls give no return
  double noise_stddev = 0.0;                              // metres, Gaussian noise added to each hit
  std::uint32_t seed = 0;                                 // used by the overloads without an rng
  // Grid simulator only: whether unknown cells stop a beam like occupied ones.
  bool unknown_blocks = false;
};

// A simulated scan and, per beam, what the beam hit: the index of the segment (segment simulator) or
// the cell row * width + column (grid simulator); -1 where the beam had no return (range +inf).
struct SimulatedScan {
  Scan scan;
  std::vector<int> hit;
};

// Beam angles of the spec, relative to the heading. Throws Error on a non-positive resolution or a
// field of view outside (0, 2*pi].
std::vector<double> beam_angles(const LaserSpec& spec);

// Casts the beams of `spec` from `pose` against `walls` (nearest intersection, ties to the lower
// index). Noise is drawn from `rng` once per beam that hits, in beam order.
SimulatedScan simulate_scan(const std::vector<Segment2>& walls, const Pose2& pose, const LaserSpec& spec,
                            std::mt19937& rng);
SimulatedScan simulate_scan(const std::vector<Segment2>& walls, const Pose2& pose, const LaserSpec& spec);

// Casts the beams against the grid's occupied cells (exact cell traversal, Amanatides & Woo); the
// range is the distance to the boundary of the first blocking cell. A pose inside a blocking cell
// gives range 0 (invalid) on every beam; beams leaving the grid have no return.
SimulatedScan simulate_scan(const OccupancyGrid& grid, const Pose2& pose, const LaserSpec& spec, std::mt19937& rng);
SimulatedScan simulate_scan(const OccupancyGrid& grid, const Pose2& pose, const LaserSpec& spec);

}  // namespace topocut
