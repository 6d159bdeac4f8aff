#include "topocut/core/grid_array.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "topocut/core/error.h"

namespace topocut {
namespace {

void validate_shape(const GridArray& a) {
  if (a.width <= 0 || a.height <= 0)
    throw Error("the grid is empty (" + std::to_string(a.width) + " x " + std::to_string(a.height) + " cells)");
  if (a.data == nullptr) throw Error("the grid has no cell values");
  if (a.row_stride != 0 && std::llabs(static_cast<long long>(a.row_stride)) < a.width)
    throw Error("the grid's rows overlap: a row stride of " + std::to_string(a.row_stride) + " bytes is shorter than its " +
                std::to_string(a.width) + " cells");
}

void validate_frame(const GridArray& a) {
  if (!std::isfinite(a.resolution) || a.resolution <= 0.0)
    throw Error("the map resolution must be a positive number of metres per cell, got " + std::to_string(a.resolution));
  if (!std::isfinite(a.origin.x) || !std::isfinite(a.origin.y) || !std::isfinite(a.origin.yaw))
    throw Error("the map origin must be finite");
}

void validate_thresholds(const GridArray& a) {
  if (a.encoding == CellEncoding::kOccupancy) {
    if (!(a.free_thresh >= 0.0 && a.free_thresh <= a.occupied_thresh && a.occupied_thresh <= 1.0))
      throw Error("the thresholds must satisfy 0 <= free_thresh <= occupied_thresh <= 1");
  } else if (!(a.occupied_max >= 0 && a.occupied_max <= a.free_min && a.free_min <= 255)) {
    throw Error("the grey thresholds must satisfy 0 <= occupied threshold <= free threshold <= 255");
  }
}

// A nav_msgs/OccupancyGrid holds -1 or a percentage; anything else is a corrupt message.
// Each row is first tested whole without a branch per cell (a loop that vectorizes: a robot's node
// pays it on every map), and only a row that holds a bad value is searched for it.
void validate_occupancy_values(const GridArray& a) {
  for (int r = 0; r < a.height; ++r) {
    const auto* row = reinterpret_cast<const std::int8_t*>(grid_array_row(a, r));
    int bad = 0;
    for (int c = 0; c < a.width; ++c) bad |= static_cast<int>(row[c] < -1) | static_cast<int>(row[c] > 100);
    if (bad == 0) continue;
    for (int c = 0; c < a.width; ++c)
      if (row[c] < -1 || row[c] > 100)
        throw Error("occupancy value " + std::to_string(row[c]) + " at row " + std::to_string(r) + ", column " +
                    std::to_string(c) + " is outside -1..100");
  }
}

}  // namespace

void validate(const GridArray& array) {
  validate_shape(array);
  validate_frame(array);
  validate_thresholds(array);
  if (array.encoding == CellEncoding::kOccupancy) validate_occupancy_values(array);
}

}  // namespace topocut
