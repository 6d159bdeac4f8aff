#pragma once
// The library in one include, and the one-call array API: segment an occupancy grid held as values
// (a nav_msgs/OccupancyGrid's data, a numpy array, an image buffer). Link topocut::topocut.
//
//   topocut::GridArray a;                       // view of int8 -1/0..100 cells, ROS row order
//   a.data = msg.data.data(); a.width = w; a.height = h; a.resolution = 0.05; a.origin = {x, y, yaw};
//   topocut::GridSegmentation rooms = topocut::segment_grid(a);   // throws topocut::Error on bad input
//   rooms.segmentation.labels  // CV_32SC1, same row order as a; rooms, passages in the map frame
#include "topocut/core/error.h"
#include "topocut/core/grid_array.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/core/version.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/io/grid_from_array.h"
#include "topocut/io/map_loader.h"
#include "topocut/io/option_file.h"
#include "topocut/io/rooms_json.h"
#include "topocut/segmentation/grid_segmentation.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segment_switches.h"
#include "topocut/segmentation/segmentation_rules.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

// Segments the grid array holds into rooms (segment() with options); labels come back in array's
// row order, geometry in its map frame. Throws Error on bad input (validate(GridArray)) or options.
inline GridSegmentation segment_grid(const GridArray& array, const SegmentOptions& options = {}) {
  return segment_grid(grid_from_array(array), frame_of(array), options);
}

// One step of incremental segmentation on the grid array holds (IncrementalSegmenter::update): ids
// stay stable across calls; labels and geometry as segment_grid(). Throws Error like segment_grid().
inline GridSegmentation update_grid(IncrementalSegmenter& segmenter, const GridArray& array) {
  return update_grid(segmenter, grid_from_array(array), frame_of(array));
}

// The segmentation options of a robot's YAML file, as `topocut segment --config FILE` reads them: the
// same keys (concavity, robot_radius or robot-radius, no_merge: true, ...), checks and messages, over
// the `segment` defaults in settings. Throws Error (FileError, OptionFileError) naming the file and
// key on an unreadable file, bad YAML, a key that is no segmentation option (with the name meant) or
// a bad value or combination.
inline SegmentOptions load_segment_options(const std::string& path, SegmentSettings settings = {}) {
  apply_option_file(read_option_file(path), segment_option_rows(), settings, "a segmentation option");
  return to_segment_options(settings);
}

}  // namespace topocut
