#pragma once
// The exact cell traversal of a ray over a grid (Amanatides & Woo, 1987), shared by the laser
// simulator, which stops at the first blocking cell, and the explorer, which marks the cells a beam
// crossed, so that both always agree on which cells a beam touches.
#include <algorithm>
#include <cmath>

#include "topocut/core/infinity.h"

namespace topocut {

// Visits, in order, the cells of a width x height grid that the ray (pu, pv) + t (du, dv) crosses
// from t = t_start, in continuous cell coordinates (u = column, v = row counted from the bottom, one
// unit per cell; (du, dv) a unit vector). visit(column, row, t) gets each cell with the t at which
// the ray enters it (t_start for the first) and returns false to stop; the walk also stops once t
// exceeds max_t or the ray leaves the grid. The first cell is clamped into the grid.
template <typename Visit>
void walk_grid_ray(int width, int height, double pu, double pv, double du, double dv, double t_start, double max_t,
                   Visit&& visit) {
  int column = std::clamp(static_cast<int>(std::floor(pu + t_start * du)), 0, width - 1);
  int row = std::clamp(static_cast<int>(std::floor(pv + t_start * dv)), 0, height - 1);
  const int step_u = du > 0.0 ? 1 : -1, step_v = dv > 0.0 ? 1 : -1;
  const double delta_u = du != 0.0 ? 1.0 / std::abs(du) : kInfinity;
  const double delta_v = dv != 0.0 ? 1.0 / std::abs(dv) : kInfinity;
  double next_u = du != 0.0 ? ((column + (du > 0.0 ? 1 : 0)) - pu) / du : kInfinity;
  double next_v = dv != 0.0 ? ((row + (dv > 0.0 ? 1 : 0)) - pv) / dv : kInfinity;
  double t = t_start;
  while (visit(column, row, t)) {
    if (next_u < next_v) {
      t = next_u;
      next_u += delta_u;
      column += step_u;
    } else {
      t = next_v;
      next_v += delta_v;
      row += step_v;
    }
    if (t > max_t || column < 0 || column >= width || row < 0 || row >= height) return;
  }
}

}  // namespace topocut
