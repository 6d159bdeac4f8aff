#pragma once
// Saving occupancy grids as ROS map_server maps (a YAML file and its image), so other tools and the
// loader read them back unchanged.
#include <string>

#include "topocut/core/occupancy_grid.h"

namespace topocut {

struct MapSaveOptions {
  // Format of the image written next to the YAML, named after it (map.yaml -> map.pgm).
  std::string image_extension = ".pgm";
};

// Writes grid as yaml_path (ROS map_server fields, trinary mode, thresholds 0.65 / 0.196) and an
// image in the same folder with map_saver's values (free 254, occupied 0, unknown 205). Both files
// are written atomically, the image first. Throws Error naming the file on failure.
void save_map(const std::string& yaml_path, const OccupancyGrid& grid, const MapSaveOptions& options = {});

// The image save_map writes beside yaml_path (its name with the image extension).
std::string map_image_path(const std::string& yaml_path, const MapSaveOptions& options = {});

// The image map_saver would write for grid: free 254, occupied 0, unknown 205 (CV_8UC1).
cv::Mat ros_map_image(const OccupancyGrid& grid);

}  // namespace topocut
