#pragma once
// Line tracking (LT). Like all sequential extractors compared by Borges & Aldon (2004) it
// walks the valid beams in scan order: every line's support is a run of consecutive valid beams,
// no two lines share a beam, and lines with fewer than min_points beams are dropped (their beams
// stay unassigned). Two steps of ours follow every sequential method: beams at a boundary between
// two lines move to the line they fit better (the split point and the tracking lag are otherwise
// assigned arbitrarily), and a lone beam at the end of a segment lying more than 3 RMSE off its
// line is dropped. Reported lines are total-least-squares fits of their beams.
#include <cstddef>
#include <vector>

#include "topocut/lines/line.h"
#include "topocut/scan/scan.h"

namespace topocut {

struct LtOptions {
  double d_max = 0.2;  // metres: gap between consecutive points that always ends a line
  // A point joins the current line while its distance to the line's total-least-squares fit is at
  // most T_max (Borges & Aldon: 10 cm).
  double t_max = 0.1;  // metres
  std::size_t min_points = 5;
};

// Line tracking: a point joins the current line while it lies within T_max of its fit.
std::vector<Line> extract_lines_lt(const Scan& scan, const LtOptions& options = {});

}  // namespace topocut
