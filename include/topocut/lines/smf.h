#pragma once
// Split-and-merge fuzzy (SMF) line extraction (Borges & Aldon 2004, "Line extraction in 2D range
// images for mobile robotics"). Split: a point set whose total-least-squares line has a dispersion
// sigma above sigma_max is split in two by fuzzy clustering of C = 2 lines in polar form (fuzzy
// c-lines with fuzzifier m; memberships u_ik = 1 / sum_j (d_ik / d_jk)^(2/(m-1)), lines refitted
// with weights u^m until the memberships settle), each point then going to its nearer line; the parts
// are split again until every set satisfies sigma <= sigma_max. Merge: each line is fused with the
// better (lower fused sigma) of its two nearest lines by centre of gravity while the fused line still
// satisfies sigma <= sigma_max. Unlike the sequential methods, a line's support need not be a run of
// consecutive beams (one wall seen in two pieces becomes one line, and a line can bridge a gap to a
// far collinear surface), but no beam belongs to two lines. A final step of ours moves boundary
// beams to the line of a scan neighbour they fit better (a set is accepted as soon as
// sigma <= sigma_max, so a few beams of the neighbouring wall can otherwise stay in it).
#include <cstddef>
#include <vector>

#include "topocut/lines/breakpoints.h"
#include "topocut/lines/line.h"
#include "topocut/scan/scan.h"

namespace topocut {

struct SmfOptions {
  BreakpointOptions breakpoints;  // the split phase starts from the breakpoint segments
  double sigma_max = 0.05;        // metres (the paper's 5 cm)
  double fuzzifier = 2.0;         // m > 1 (the paper's m = 2)
  int max_iterations = 100;       // fuzzy clustering iterations per split
  double tolerance = 1e-4;        // stop when no membership changes by more than this
  bool merge = true;
  std::size_t min_points = 5;     // lines with fewer beams are dropped after the merge
};

// Split-and-merge fuzzy extraction; lines are ordered by their first supporting beam.
std::vector<Line> extract_lines_smf(const Scan& scan, const SmfOptions& options = {});

}  // namespace topocut
