#pragma once
// Loading occupancy grids from images and ROS map_server YAML files into the three-state grid.
#include <optional>
#include <string>

#include "topocut/core/occupancy_grid.h"

namespace topocut {

struct MapLoadOptions {
  // Used for plain images (a YAML's own resolution always wins); metres per cell.
  double resolution = 0.05;
  // Plain images: cells brighter than free_min are free, darker than occupied_max occupied, the
  // rest unknown (DESIGN.md: 0 occupied, 255 free, anything else unknown unless thresholds say so).
  int free_min = 250;
  int occupied_max = 50;
};

// Loads a map: a ROS map_server YAML (image, resolution, origin, negate, occupied_thresh,
// free_thresh, mode trinary/scale/raw, with ROS semantics) or any image OpenCV reads (grey, RGB,
// RGBA, grey+alpha). Throws Error naming the file and the problem on any bad input.
OccupancyGrid load_map(const std::string& path, const MapLoadOptions& options = {});

}  // namespace topocut
