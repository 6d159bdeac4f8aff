#pragma once
// How an array's or a map image's values become cells, as people give it (segment()'s keywords, the
// ROS node's parameters, the flags of every command that reads a map image): defined once, next to
// GridArray, and shared by the structs that hold the same rule (map_load_flags.h).
#include <vector>

#include "topocut/core/grid_array.h"
#include "topocut/core/option_table.h"

namespace topocut {

// fixed-thresholds, free-threshold, occupied-threshold of any struct holding the plain-image rule
// (fields detect_palette, free_min, occupied_max: GridArray, MapLoadOptions). Giving either threshold
// means fixed thresholds, as --fixed-thresholds does.
template <typename Target>
std::vector<OptionRow<Target>> grey_threshold_rows() {
  return {
      {"fixed-thresholds", "",
       "plain images: use --free-threshold and --occupied-threshold instead of reading the palette from the image",
       OptionRange::kSwitch, [](const Target& t) { return t.detect_palette ? 0.0 : 1.0; },
       [](Target& t, double on) { t.detect_palette = on == 0.0; }},
      {"free-threshold", "GREY",
       "plain images with --fixed-thresholds (or no readable palette): grey values above this are free",
       OptionRange::kGreyLevel, [](const Target& t) { return t.free_min; },
       [](Target& t, double v) {
         t.free_min = static_cast<int>(v);
         t.detect_palette = false;
       }},
      {"occupied-threshold", "GREY",
       "plain images with --fixed-thresholds: grey values below this are occupied (between the two: unknown)",
       OptionRange::kGreyLevel, [](const Target& t) { return t.occupied_max; },
       [](Target& t, double v) {
         t.occupied_max = static_cast<int>(v);
         t.detect_palette = false;
       }},
  };
}

// free-thresh, occupied-thresh: map_server's rule for occupancy values (CellEncoding::kOccupancy),
// the names of a map_server YAML's keys.
const std::vector<OptionRow<GridArray>>& occupancy_threshold_rows();

// Both rules' rows, for an array of either encoding: occupancy_threshold_rows(), then
// grey_threshold_rows<GridArray>().
const std::vector<OptionRow<GridArray>>& grid_array_option_rows();

}  // namespace topocut
