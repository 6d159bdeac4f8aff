#pragma once
// An occupancy grid handed over as raw cell values (a nav_msgs/OccupancyGrid's data, a numpy array,
// an image buffer) together with its place in the world: what callers outside the library hold
// instead of a map file. The values are viewed, never owned.
#include <cstddef>

namespace topocut {

// How the cell values are encoded.
enum class CellEncoding {
  kOccupancy,  // signed 8-bit: -1 unknown, 0..100 occupancy percent (nav_msgs/OccupancyGrid)
  kGrey,       // unsigned 8-bit grey level of a map image: 255 free, 0 occupied
};

// Which row of the values comes first.
enum class RowOrder {
  kBottomUp,  // row 0 is at the map origin, the bottom of the picture (nav_msgs/OccupancyGrid)
  kTopDown,   // row 0 is the top of the picture (images, OpenCV)
};

// The world pose of the lower-left corner of the lower-left cell (ROS map_server's origin).
struct MapPose {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;  // radians, counter-clockwise rotation of the grid about (x, y)
};

// How results are handed back to a caller of the array API: labels in its row order, geometry
// rotated by the origin's yaw about the origin (the map frame).
struct GridFrame {
  RowOrder row_order = RowOrder::kTopDown;
  double yaw = 0.0;
};

struct GridArray {
  const void* data = nullptr;    // width * height values, one byte each, rows row_stride bytes apart
  int width = 0;                 // cells per row
  int height = 0;                // rows
  std::ptrdiff_t row_stride = 0; // bytes from the start of one row to the next (may be negative); 0: width
  CellEncoding encoding = CellEncoding::kOccupancy;
  RowOrder row_order = RowOrder::kBottomUp;
  double resolution = 0.05;      // metres per cell
  MapPose origin;
  // kOccupancy, map_server's rule: free if value / 100 < free_thresh, occupied if > occupied_thresh,
  // otherwise (and -1) unknown.
  double free_thresh = 0.196;
  double occupied_thresh = 0.65;
  // kGrey, the plain-image rule (map_loader.h): the palette read from the values when detect_palette,
  // else free above free_min, occupied below occupied_max, unknown between.
  bool detect_palette = false;
  int free_min = 250;
  int occupied_max = 50;
};

// The frame results for array are given in.
inline GridFrame frame_of(const GridArray& array) { return {array.row_order, array.origin.yaw}; }

// The first value of row (in the array's own row order); no bounds check.
inline const unsigned char* grid_array_row(const GridArray& array, int row) {
  const std::ptrdiff_t stride = array.row_stride != 0 ? array.row_stride : array.width;
  return static_cast<const unsigned char*>(array.data) + stride * row;
}

// Throws Error (one line naming the problem) unless the array is usable: data given, positive width
// and height, a row stride of at least width bytes in magnitude, finite positive resolution, finite
// origin, thresholds in order (0 <= free_thresh <= occupied_thresh <= 1, 0 <= occupied_max <=
// free_min <= 255), and, for kOccupancy, every value -1..100.
void validate(const GridArray& array);

}  // namespace topocut
