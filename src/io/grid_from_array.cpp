#include "topocut/io/grid_from_array.h"

#include <opencv2/core.hpp>

#include "topocut/io/map_loader.h"

namespace topocut {
namespace {

// Row r of the result is the array's row r (top-down) or height-1-r (bottom-up).
int source_row(const GridArray& array, int r) { return array.row_order == RowOrder::kTopDown ? r : array.height - 1 - r; }

// ros_cells() in raw mode reads a percentage from a grey level; -1 becomes 255, its "not a percentage".
cv::Mat occupancy_cells(const GridArray& array) {
  cv::Mat grey(array.height, array.width, CV_32FC1);
  for (int r = 0; r < array.height; ++r) {
    const auto* in = reinterpret_cast<const signed char*>(grid_array_row(array, source_row(array, r)));
    float* out = grey.ptr<float>(r);
    for (int c = 0; c < array.width; ++c) out[c] = in[c] < 0 ? 255.0f : static_cast<float>(in[c]);
  }
  RosMapMetadata metadata;
  metadata.mode = RosMapMode::kRaw;
  metadata.free_thresh = array.free_thresh;
  metadata.occupied_thresh = array.occupied_thresh;
  return ros_cells(grey, cv::Mat::zeros(grey.size(), CV_8UC1), metadata);
}

cv::Mat grey_cells(const GridArray& array) {
  cv::Mat levels(array.height, array.width, CV_8UC1);
  for (int r = 0; r < array.height; ++r) {
    const unsigned char* in = grid_array_row(array, source_row(array, r));
    std::copy(in, in + array.width, levels.ptr<unsigned char>(r));
  }
  MapLoadOptions options;
  options.detect_palette = array.detect_palette;
  options.free_min = array.free_min;
  options.occupied_max = array.occupied_max;
  const cv::Mat opaque = cv::Mat::zeros(levels.size(), CV_8UC1);
  return plain_image_cells(levels, opaque, plain_image_palette(levels, opaque, options));
}

}  // namespace

OccupancyGrid grid_from_array(const GridArray& array) {
  validate(array);
  OccupancyGrid grid;
  grid.cells = array.encoding == CellEncoding::kOccupancy ? occupancy_cells(array) : grey_cells(array);
  grid.resolution = array.resolution;
  grid.origin = {array.origin.x, array.origin.y};
  validate(grid);
  return grid;
}

}  // namespace topocut
