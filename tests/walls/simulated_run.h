#pragma once
// Scans of a simulated laser (full circle, 0.5° beams, 12 m, seeded noise) on a floor plan of wall
// segments, one per pose: the logs of the walls tests.
#include <cmath>
#include <random>
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/scan/laser_simulator.h"
#include "topocut/walls/posed_scan.h"

namespace topocut::test {

inline std::vector<PosedScan> simulated_run(const std::vector<Segment2>& plan, const std::vector<Pose2>& poses,
                                     double noise = 0.01) {
  LaserSpec spec;
  spec.field_of_view = 2.0 * M_PI;
  spec.angular_resolution = M_PI / 360.0;
  spec.range_max = 12.0;
  spec.noise_stddev = noise;
  spec.seed = 5;
  std::mt19937 rng(spec.seed);
  std::vector<PosedScan> scans;
  for (const Pose2& pose : poses) {
    PosedScan s;
    s.scan = simulate_scan(plan, pose, spec, rng).scan;
    s.pose = pose;
    scans.push_back(s);
  }
  return scans;
}

}  // namespace topocut::test
