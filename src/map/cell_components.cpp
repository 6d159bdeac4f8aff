#include "topocut/map/cell_components.h"

#include <algorithm>

#include "map/row_runs.h"
#include "topocut/core/error.h"

namespace topocut {

cv::Mat cell_components(const cv::Mat& mask, bool eight_connected, std::vector<long long>& sizes) {
  if (mask.empty() || mask.type() != CV_8UC1) throw Error("cell_components: the mask must be a non-empty 8-bit image");
  const RowRuns runs = runs_of(mask);
  int count = 0;
  const std::vector<int> part = run_components(runs, eight_connected, count);  // numbered by first run: raster order
  sizes.assign(static_cast<std::size_t>(count), 0);
  cv::Mat labels(mask.size(), CV_32SC1, cv::Scalar(0));
  for (int y = 0; y < mask.rows; ++y) {
    int* row = labels.ptr<int>(y);
    std::size_t k = runs.index_of_row(y);
    for (const CellRun& run : runs.row(y)) {
      const int p = part[k++];
      std::fill(row + run.begin, row + run.end, p + 1);
      sizes[static_cast<std::size_t>(p)] += run.end - run.begin;
    }
  }
  return labels;
}

}  // namespace topocut
