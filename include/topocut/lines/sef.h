#pragma once
// Successive edge following (SEF). Like all sequential extractors compared by Borges & Aldon (2004) it
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

struct SefOptions {
  // A line ends where consecutive points are more than D_max apart ...
  double d_max = 0.2;  // metres (the seeds suggest 0.1-0.2 m; 0.2 tolerates 5 cm noise)
  // ... or where the next point leaves the edge being followed by more than T_max. Our reading of
  // "the edge": the chord from the line's first point through its middle point (a chord to the last
  // accepted point would bend round any corner in small steps and never end a line).
  double t_max = 0.1;  // metres
  std::size_t min_points = 5;
};

// Successive edge following: lines end at gaps over D_max or where a point leaves the followed edge.
std::vector<Line> extract_lines_sef(const Scan& scan, const SefOptions& options = {});

}  // namespace topocut
