#pragma once
// An extracted line: its polar parameters, its extent and the scan rows that support it.
#include <cstddef>
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/scan/scan.h"

namespace topocut {

struct Line {
  double rho = 0.0;    // >= 0, metres (sensor frame)
  double alpha = 0.0;  // normal direction, (-pi, pi]
  Point2 start;        // extreme projection of the support points, on the side of the lowest row
  Point2 end;          // the other extreme projection
  std::vector<std::size_t> support;  // rows of the scan (valid beams), strictly increasing
};

// The line fitted (total least squares) to the given rows of the scan, with its end points: the two
// extreme projections of the support points along the line. Rows are sorted and deduplicated;
// throws Error if a row is out of range or not a valid beam, or if there are none.
Line make_line(const Scan& scan, std::vector<std::size_t> support);

// Distance between the end points.
double length(const Line& line);

}  // namespace topocut
