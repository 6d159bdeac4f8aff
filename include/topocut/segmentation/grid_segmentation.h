#pragma once
// Segmentation results as a caller of the array API wants them (GridArray, ROS, Python): labels in
// the caller's row order, geometry in the map frame (the origin's yaw applied), and for every room a
// point inside it and its bounding box, so that a label can be drawn and a room looked up.
#include <vector>

#include "topocut/core/grid_array.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

struct GridSegmentation {
  // labels in frame.row_order; room polygons and centroids, passage cuts in the map frame.
  // A passage's door flag tells a door (a narrow gap in a wall) from a wider opening.
  Segmentation segmentation;
  std::vector<RoomPlacement> placements;  // one per segmentation.rooms entry, same order
  GridFrame frame;
};

// Turns a segmentation of a top-down grid with yaw 0 (what segment() and IncrementalSegmenter give)
// into frame: labels flipped for kBottomUp, geometry rotated by frame.yaw about the origin.
GridSegmentation in_frame(Segmentation segmentation, const GridFrame& frame);

// segment() followed by in_frame(). Throws Error like segment().
GridSegmentation segment_grid(const OccupancyGrid& grid, const GridFrame& frame, const SegmentOptions& options = {},
                              SegmentationInput* input = nullptr);

// segmenter.update(grid) followed by in_frame() (ids stay those of the segmenter).
GridSegmentation update_grid(IncrementalSegmenter& segmenter, const OccupancyGrid& grid, const GridFrame& frame);

}  // namespace topocut
