#pragma once
// Binarization (Fermin-Leon et al., Algorithm 1): the three-state grid becomes a free-space mask,
// optionally with obstacles inflated by the robot's radius and speckle filtered out of free space.
#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"

namespace topocut {

struct BinarizeOptions {
  // Cells whose centre lies within this distance (metres) of an obstacle cell's centre are not
  // free. 0 keeps the raw free space (what the evaluation uses).
  double robot_radius = 0.0;
  // Also inflate unknown cells (a cautious robot); by default only occupied cells are inflated,
  // as a costmap does.
  bool inflate_unknown = false;
  // Morphological opening of free space with a square of this side (metres): removes free
  // specks and one-cell spurs thinner than the square. 0 disables.
  double opening_size = 0.0;
  // Median filter of free space with a square window of this side (metres, rounded to an odd
  // number of cells >= 3). 0 disables.
  double median_size = 0.0;
};

// The fields of BinarizeOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<BinarizeOptions>>& binarize_option_rows();

// The free-space mask (CV_8UC1, 255 free, 0 not): cells == kFree, minus the inflated obstacles,
// filtered. Filters only ever remove free cells: unknown and occupied cells are never free.
// Throws Error on an invalid grid or negative / non-finite option values.
cv::Mat free_space_mask(const OccupancyGrid& grid, const BinarizeOptions& options = {});

}  // namespace topocut
