#include "topocut/map/building_inside.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "map/row_runs.h"
#include "topocut/core/error.h"
#include "topocut/core/occupancy_grid.h"

namespace topocut {

cv::Mat building_inside(const cv::Mat& cells, double closing) {
  if (cells.empty() || cells.type() != CV_8UC1) throw Error("building_inside: the cells must be a non-empty 8-bit grid");
  cv::Mat inside(cells.size(), CV_8UC1, cv::Scalar(0));
  if (!(closing > 0.0)) return inside;
  const long limit = std::max(cells.rows, cells.cols);  // a wider square closes no more
  const int n = static_cast<int>(std::clamp(std::lround(std::min(closing, 1e9) / 2.0), 1L, limit));
  write_mask(reached_from_edge(complement(close_square(runs_of_value(cells, kOccupied), n))), inside, 0, 255);
  return inside;
}

const cv::Mat& BuildingInside::at(double closing) {
  if (inside_.empty() || closing != closing_) {
    inside_ = building_inside(cells_, closing);
    closing_ = closing;
  }
  return inside_;
}

bool has_occupied_cell(const cv::Mat& cells) {
  for (int r = 0; r < cells.rows; ++r) {
    const unsigned char* row = cells.ptr<unsigned char>(r);
    if (std::memchr(row, kOccupied, static_cast<std::size_t>(cells.cols)) != nullptr) return true;
  }
  return false;
}

}  // namespace topocut
