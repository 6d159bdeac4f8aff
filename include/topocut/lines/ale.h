#pragma once
// Adaptive line extraction (ALE, after Yaghobi et al.). Our reading of the method, step by step:
//  1. segmentation by range continuity (the adaptive breakpoint detector, breakpoints.h);
//  2. robust lowess smoothing of range against beam angle inside each segment (tri-cube distance
//     weights, bisquare robustness weights; lowess.h), which removes range noise but keeps corners;
//  3. from the first unassigned point a binary search finds the farthest end point whose smoothed
//     points still fit a line with RMSE <= the maximum threshold, and likewise for the minimum one;
//     between the two the threshold floats: the line ends at the first point where the RMSE gradient
//     jumps (the onset of a corner), else at the maximum-threshold end;
//  4. (ours) smoothing rounds corners and can leave a short extra piece next to one: neighbouring
//     pieces are fused when their common line's RMSE (raw points) is at most the larger of their
//     own RMSEs plus the scaled lower threshold; boundary beams move to the neighbouring line they
//     fit better, and lone outlying beams at segment ends are dropped, as in the sequential methods;
//  5. the lines are fitted (total least squares) to the raw points, never to the smoothed ones.
// Thresholds. The seeds' RMSE band (0.0025 ... 0.008 m) suits a laser with about 1 cm range noise;
// smoothed 5 cm noise alone has an RMSE above 0.008 m. So the band is scaled by the scan's estimated
// range noise relative to reference_noise (never below the seeds' values): the same defaults then
// serve the 5 cm simulation and real logs without tuning. The gradient test is relative:
// g(e) = n (RMSE(e+1) - RMSE(e)) / RMSE(e+1) with n the points so far; a point 3 RMSE off the line
// gives g = 4. Supports are runs of consecutive valid beams and never overlap; lines with fewer than
// min_points beams are dropped.
#include <cstddef>
#include <vector>

#include "topocut/lines/breakpoints.h"
#include "topocut/lines/line.h"
#include "topocut/lines/lowess.h"
#include "topocut/scan/scan.h"

namespace topocut {

struct AleOptions {
  BreakpointOptions breakpoints;
  LowessOptions smoothing{.span = 0.0, .neighbours = 15, .iterations = 2};
  double rmse_min = 0.0025;        // metres: below this (scaled) RMSE a line keeps growing
  double rmse_max = 0.008;         // metres: above this (scaled) RMSE a line never grows
  double gradient_max = 4.0;       // relative RMSE gradient that marks a corner (see above)
  double reference_noise = 0.01;   // metres: range noise for which the band holds unscaled; <= 0: never scale
  std::size_t min_points = 5;
};

// Adaptive line extraction.
std::vector<Line> extract_lines_ale(const Scan& scan, const AleOptions& options = {});

}  // namespace topocut
