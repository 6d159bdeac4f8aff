#pragma once
// Cell values held by the caller (GridArray) -> the three-state grid every stage reads, with the same
// rules as the map loader: map_server's thresholds for occupancy values, the plain-image rule for grey.
#include "topocut/core/grid_array.h"
#include "topocut/core/occupancy_grid.h"

namespace topocut {

// The three-state grid of array (rows top-down, as OccupancyGrid wants; origin = array.origin's x, y:
// the yaw is the caller's to apply, see grid_segmentation.h). Occupancy values go through
// ros_cells() in raw mode with array's thresholds, grey values through plain_image_cells() with the
// detected or fixed palette. Throws Error like validate(GridArray) on bad input.
OccupancyGrid grid_from_array(const GridArray& array);

}  // namespace topocut
