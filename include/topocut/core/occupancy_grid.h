#pragma once
// An occupancy grid in the three states every stage understands, with its place in the world.
#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"

namespace topocut {

// Cell values of OccupancyGrid::cells (CV_8UC1). Loaders map every input encoding to these.
inline constexpr unsigned char kOccupied = 0;
inline constexpr unsigned char kUnknown = 128;
inline constexpr unsigned char kFree = 255;

struct OccupancyGrid {
  cv::Mat cells;             // CV_8UC1, values kOccupied / kUnknown / kFree; row 0 is the top row
  double resolution = 0.05;  // metres per cell
  Point2 origin;             // world position of the lower-left corner of the lower-left cell (ROS)

  int width() const { return cells.cols; }
  int height() const { return cells.rows; }
};

// World position of the centre of cell (column, row): DESIGN.md's grid/world convention.
Point2 cell_center_world(const OccupancyGrid& grid, int column, int row);

// Cell containing a world point, as (column, row); may lie outside the grid.
cv::Point world_to_cell(const OccupancyGrid& grid, const Point2& world);

// Converts a point in grid coordinates (x = column, y = height-1-row, unit = one cell, y up, cell
// centres at integers) to world metres. Polygons traced from images use grid coordinates.
Point2 grid_to_world(const OccupancyGrid& grid, const Point2& grid_point);

// The part of grid inside box (its cells copied), at the same place in the world: its origin moves
// to the box's lower-left corner. box must lie inside the grid.
OccupancyGrid crop(const OccupancyGrid& grid, const cv::Rect& box);

// The box of the cells (CV_8UC1, OccupancyGrid::cells) that are not kUnknown; empty when every cell
// is unknown. Reads each row only beyond the box found so far: SLAM maps are mostly unknown around
// the building, and their known part is what the stages work on.
cv::Rect known_box(const cv::Mat& cells);

// The inverse of crop() for an image of any type: an image of the given size holding part at box
// (box.size() == part.size(), inside the image) and value everywhere else; every cell is written
// once (the rows and columns around box are filled, not the whole image first).
cv::Mat uncrop(const cv::Mat& part, const cv::Size& size, const cv::Rect& box, double value);

// Throws Error unless the grid is non-empty, CV_8UC1, and its resolution and origin lie in the ranges
// of value_ranges.h.
void validate(const OccupancyGrid& grid);

}  // namespace topocut
