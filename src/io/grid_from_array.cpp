#include "topocut/io/grid_from_array.h"

#include <cstdint>
#include <optional>

#include <opencv2/core.hpp>

#include "topocut/io/map_loader.h"

namespace topocut {
namespace {

// Row r of the result is the array's row r (top-down) or height-1-r (bottom-up).
int source_row(const GridArray& array, int r) { return array.row_order == RowOrder::kTopDown ? r : array.height - 1 - r; }

// The occupancy table (by the value's byte) over the values a valid map holds (-1..100, validate())
// as two cuts: free from 0 to free_max, occupied from occupied_min, unknown between and for -1.
// Compared rather than looked up, the cells of a row come 16 at a time (a lookup per cell was most
// of a node's conversion).
struct OccupancyCuts {
  std::int8_t free_max = -1, occupied_min = 101;
};

// The table's cuts, or none when it is not of that form (then it is looked up).
std::optional<OccupancyCuts> cuts_of(const unsigned char* state) {
  const auto at = [state](int value) { return state[static_cast<unsigned char>(static_cast<std::int8_t>(value))]; };
  OccupancyCuts cuts;
  while (cuts.free_max < 100 && at(cuts.free_max + 1) == kFree) ++cuts.free_max;
  while (cuts.occupied_min > 0 && at(cuts.occupied_min - 1) == kOccupied) --cuts.occupied_min;
  for (int value = -1; value <= 100; ++value) {
    const unsigned char expected = value >= cuts.occupied_min ? kOccupied : value >= 0 && value <= cuts.free_max ? kFree : kUnknown;
    if (at(value) != expected) return std::nullopt;
  }
  return cuts;
}

void cells_by_cuts(const std::int8_t* __restrict in, int n, const OccupancyCuts& cuts, unsigned char* __restrict out) {
  for (int c = 0; c < n; ++c) {
    const std::int8_t v = in[c];
    const unsigned char free_or_unknown = (v >= 0) & (v <= cuts.free_max) ? kFree : kUnknown;
    out[c] = v >= cuts.occupied_min ? kOccupied : free_or_unknown;
  }
}

// ros_cells() in raw mode reads a percentage from a grey level; -1 becomes 255, its "not a percentage".
// An int8 cell holds one of 256 values, so ros_cells() runs once over all of them and the cells are
// looked up: the same states, without a float image and a rounding per cell (a robot's node pays
// this on every map it receives).
cv::Mat occupancy_cells(const GridArray& array) {
  cv::Mat grey(1, 256, CV_32FC1);
  for (int b = 0; b < 256; ++b) {
    const auto value = static_cast<signed char>(b);
    grey.at<float>(0, b) = value < 0 ? 255.0f : static_cast<float>(value);
  }
  RosMapMetadata metadata;
  metadata.mode = RosMapMode::kRaw;
  metadata.free_thresh = array.free_thresh;
  metadata.occupied_thresh = array.occupied_thresh;
  const cv::Mat table = ros_cells(grey, cv::Mat::zeros(grey.size(), CV_8UC1), metadata);
  const unsigned char* state = table.ptr<unsigned char>(0);
  cv::Mat cells(array.height, array.width, CV_8UC1);
  const std::optional<OccupancyCuts> cuts = cuts_of(state);
  for (int r = 0; r < array.height; ++r) {
    const unsigned char* in = grid_array_row(array, source_row(array, r));
    unsigned char* out = cells.ptr<unsigned char>(r);
    if (cuts) {
      cells_by_cuts(reinterpret_cast<const std::int8_t*>(in), array.width, *cuts, out);
    } else {
      for (int c = 0; c < array.width; ++c) out[c] = state[in[c]];
    }
  }
  return cells;
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
