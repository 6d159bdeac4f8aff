#pragma once
// Which room a point of the map frame is in: the one lookup that the CLI (`segment --at`), the
// Python module (`Segmentation.room_at`) and the ROS node answer alike, from the labels.
#include "topocut/core/grid_array.h"
#include "topocut/core/geometry.h"
#include "topocut/core/segmentation.h"
#include "topocut/segmentation/grid_segmentation.h"

namespace topocut {

// The id of the room whose labelled cell holds point (map frame, metres) in segmentation, whose
// labels are in frame.row_order and whose grid frame.yaw turns about segmentation.origin; 0 ("none")
// when that cell is no room's (an obstacle, unknown or removed space) or the point is off the grid.
// A point on a cell edge belongs to the cell above or to the right. Throws Error for a non-finite point.
int room_at(const Segmentation& segmentation, const GridFrame& frame, const Point2& point);

// room_at() in the frame result was made for (segment_grid(), update_grid(), the array API).
inline int room_at(const GridSegmentation& result, const Point2& point) {
  return room_at(result.segmentation, result.frame, point);
}

}  // namespace topocut
