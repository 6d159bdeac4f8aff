#pragma once
// Breakpoints: where consecutive valid beams of a scan cannot belong to the same surface, so no line
// may span them. Every extractor except SEF/LT (which use their own D_max) starts from these
// segments.
#include <cstddef>
#include <numbers>
#include <vector>

#include "topocut/scan/scan.h"

namespace topocut {

struct BreakpointOptions {
  // Adaptive breakpoint detector (Borges & Aldon 2004): consecutive points p_{n-1}, p_n (angular
  // step dphi) are split when |p_n - p_{n-1}| > r_{n-1} sin(dphi) / sin(lambda - dphi) + 3 sigma_r,
  // i.e. when the surface through them would be seen at a grazing angle below lambda.
  double lambda = 10.0 * std::numbers::pi / 180.0;  // radians (the paper's 10 degrees)
  // Range noise sigma_r in metres; <= 0 means "estimate it from the scan" (estimate_range_noise).
  double sigma_r = 0.0;
  // Floor of the estimated sigma_r, so a noiseless scan keeps a sane tolerance.
  double sigma_r_floor = 0.005;
};

// A run of consecutive valid points: positions [first, last] into valid_points(scan).
struct PointRun {
  std::size_t first = 0;
  std::size_t last = 0;
  std::size_t size() const { return last - first + 1; }
};

// Robust estimate of the range noise (metres) from second differences of consecutive valid ranges
// (1.4826 * median |r[i-1] - 2 r[i] + r[i+1]| / sqrt 6): walls are smooth in range at laser
// resolution, so the median difference is noise. 0 if fewer than 3 consecutive valid beams.
double estimate_range_noise(const Scan& scan);

// Splits the valid points (in beam order, as returned by valid_points(scan)) into runs at the
// breakpoints. A beam that is invalid between two valid ones also separates them when the angular
// step across it is used in the test (larger steps allow larger gaps).
std::vector<PointRun> split_at_breakpoints(const Scan& scan, const std::vector<ScanPoint>& points,
                                           const BreakpointOptions& options = {});

// Splits the valid points into runs wherever consecutive points are more than max_gap metres apart
// (the fixed D_max of the sequential methods).
std::vector<PointRun> split_at_gaps(const std::vector<ScanPoint>& points, double max_gap);

}  // namespace topocut
