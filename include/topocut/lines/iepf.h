#pragma once
// Iterative end-point fit (IEPF, split-and-merge). Like all sequential extractors compared by Borges & Aldon (2004) it
// walks the valid beams in scan order: every line's support is a run of consecutive valid beams,
// no two lines share a beam, and lines with fewer than min_points beams are dropped (their beams
// stay unassigned). Two steps of ours follow every sequential method: beams at a boundary between
// two lines move to the line they fit better (the split point and the tracking lag are otherwise
// assigned arbitrarily), and a lone beam at the end of a segment lying more than 3 RMSE off its
// line is dropped. Reported lines are total-least-squares fits of their beams.
#include <cstddef>
#include <vector>

#include "topocut/lines/breakpoints.h"
#include "topocut/lines/line.h"
#include "topocut/scan/scan.h"

namespace topocut {

struct IepfOptions {
  BreakpointOptions breakpoints;  // segments split first at breakpoints
  // Split a run at its point farthest from the chord between its end points while that distance
  // exceeds T_max (Borges & Aldon: 10 cm); then merge neighbouring lines whose fused
  // total-least-squares line keeps every point within T_max.
  double t_max = 0.1;  // metres
  bool merge = true;
  std::size_t min_points = 5;
};

// Iterative end-point fit with a merge of collinear neighbours.
std::vector<Line> extract_lines_iepf(const Scan& scan, const IepfOptions& options = {});

}  // namespace topocut
