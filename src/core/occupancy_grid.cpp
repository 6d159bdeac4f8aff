#include "topocut/core/occupancy_grid.h"

#include <cmath>
#include <string>

#include "topocut/core/error.h"
#include "topocut/core/value_ranges.h"

namespace topocut {

Point2 cell_center_world(const OccupancyGrid& grid, int column, int row) {
  return {grid.origin.x + (column + 0.5) * grid.resolution,
          grid.origin.y + (grid.height() - row - 0.5) * grid.resolution};
}

cv::Point world_to_cell(const OccupancyGrid& grid, const Point2& world) {
  const double c = (world.x - grid.origin.x) / grid.resolution;
  const double r_from_bottom = (world.y - grid.origin.y) / grid.resolution;
  return {static_cast<int>(std::floor(c)), grid.height() - 1 - static_cast<int>(std::floor(r_from_bottom))};
}

Point2 grid_to_world(const OccupancyGrid& grid, const Point2& g) {
  return {grid.origin.x + (g.x + 0.5) * grid.resolution, grid.origin.y + (g.y + 0.5) * grid.resolution};
}

Point2 world_to_grid(const OccupancyGrid& grid, const Point2& w) {
  return {(w.x - grid.origin.x) / grid.resolution - 0.5, (w.y - grid.origin.y) / grid.resolution - 0.5};
}

OccupancyGrid crop(const OccupancyGrid& grid, const cv::Rect& box) {
  if (box.empty() || (box & cv::Rect(0, 0, grid.width(), grid.height())) != box)
    throw Error("the box to crop must be a non-empty part of the map");
  OccupancyGrid part;
  part.cells = grid.cells(box).clone();
  part.resolution = grid.resolution;
  part.origin = {grid.origin.x + box.x * grid.resolution,
                 grid.origin.y + (grid.height() - box.y - box.height) * grid.resolution};
  return part;
}

void validate(const OccupancyGrid& grid) {
  if (grid.cells.empty()) throw Error("the map is empty (0 cells)");
  if (grid.cells.type() != CV_8UC1) throw Error("the occupancy grid must be a single-channel 8-bit image");
  check_resolution(grid.resolution, "the map resolution");
  check_world_coordinate(grid.origin.x, "the map origin's x");
  check_world_coordinate(grid.origin.y, "the map origin's y");
}

}  // namespace topocut
