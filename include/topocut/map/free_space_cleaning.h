#pragma once
// The real-map front end. A SLAM map's free space holds rays fanning out through windows and doors,
// slivers along walls and specks of clutter inside rooms: left in, they become rooms nobody would draw
// and multiply every outline's vertices. This stage keeps the floor (free space a person fits into,
// walled-in narrow space, obstacle specks inside it); removed cells inside the building join the room
// next to them, those outside belong to no room. Free specks are left to the contour stage.
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/option_table.h"

namespace topocut {

struct FreeSpaceCleaningOptions {
  // Metres: a non-free region enclosed by free space whose box is at most this long both ways is a
  // speck and counts as floor (no hole, no door jamb: clutter, chair legs). 0 keeps every obstacle.
  double max_obstacle_speck = 0.3;
  // Metres, a person's width: free space beyond min_width / 4 of every disc this wide is thin, and a
  // thin part bordered more by unknown than by walls (rays, not a closet) is removed. 0 disables.
  double min_width = 0.6;
  // Metres: a removed cell is inside the building when floor and walls enclose it once gaps this wide
  // (doors, windows, unseen wall) are closed; rays into the open are outside. 0: all outside.
  double inside_closing = 2.0;
};

// The fields of FreeSpaceCleaningOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<FreeSpaceCleaningOptions>>& cleaning_option_rows();

// What happened to a cell (CleanedFreeSpace::removed).
enum CleanedCell : unsigned char {
  kCellUntouched = 0,     // kept floor, or never free
  kCellObstacleSpeck = 1, // non-free cell that counts as floor
  kCellRemovedInside = 2, // free cell removed (thin or a speck) inside the building: joins the nearest room
  kCellRemovedOutside = 3,// free cell removed outside the building: no room
};

struct CleanedFreeSpace {
  cv::Mat floor;    // CV_8UC1, 255 where the decomposition sees free space (kept floor and obstacle specks)
  cv::Mat removed;  // CV_8UC1, a CleanedCell per cell
  int removed_cells = 0;  // free cells removed (inside or outside)
  int outside_cells = 0;  // of those, outside the building
  int speck_cells = 0;    // obstacle specks that count as floor (kCellObstacleSpeck)
  cv::Rect window;        // the cells the cleaning looked at: beyond it floor and removed are 0
  // The bounding box of every thin part (8-connected) the cleaning judged as a whole, ray or not: a
  // caller cleaning a window of a larger map knows its verdicts hold only for parts inside it.
  std::vector<cv::Rect> thin_parts;
};

// Cleans a free-space mask (CV_8UC1, nonzero = free) of a map whose cells (CV_8UC1, kFree /
// kOccupied / kUnknown, same size) tell walls from unknown, at the given resolution (metres per
// cell). Every free cell is either floor or removed; floor is free space plus obstacle specks.
// Throws Error on an empty or non-8-bit mask, mismatched cells, a bad resolution or negative /
// non-finite options.
CleanedFreeSpace clean_free_space(const cv::Mat& free, const cv::Mat& cells, double resolution,
                                  const FreeSpaceCleaningOptions& options = {});

// A picture of the cleaning for people (CV_8UC3, BGR, one pixel per cell): free white, occupied
// black, unknown grey; removed cells outside the building red, inside orange, obstacle specks that
// count as floor light blue. cells is the grid (kFree / kOccupied / kUnknown); an empty cleaned
// result draws the grid alone.
cv::Mat render_cleaned_map(const cv::Mat& cells, const CleanedFreeSpace& cleaned);

// The grid's cells (kFree / kOccupied / kUnknown) as the labelling sees them after the cleaning:
// removed cells outside the building are unknown (they belong to no room) and unknown obstacle
// specks free (floor the sensor never reported; occupied specks such as chair legs stay). cells
// itself, not a copy, when the cleaning changes none of them.
cv::Mat cells_after_cleaning(const cv::Mat& cells, const CleanedFreeSpace& cleaned);

// Throws Error unless the options are finite and non-negative.
void validate(const FreeSpaceCleaningOptions& options);

}  // namespace topocut
