#pragma once
// What the leave-out rows share with open rooms (open_rooms.cpp defines them): a labelled room's outline
// read in a window around its cells, as the open-rooms rule reads it, and the checks on a labelling
// they take. Private to the segmentation module.
#include <optional>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/map/room_outline.h"
#include "topocut/segmentation/open_rooms.h"

namespace topocut {

// The window of a grid of size cells around box (cells), wide enough that every cell a room's outline
// reads (a cell beyond its floor, band cells on) lies inside, with the occupied cells within wall_reach
// of it; inside the grid.
cv::Rect outline_window(const cv::Rect& box, const cv::Size& size, double resolution, const OpenRoomOptions& options);

// The outline of label id of labels (CV_32SC1, the grid's cells in a window; cells: the grid's cells
// there) with the open-rooms rule's wall reach and band (room_outline()); nothing when id has no cell.
std::optional<RoomOutline> window_outline(const cv::Mat& labels, int id, const cv::Mat& cells, double resolution,
                                          const OpenRoomOptions& options);

// Throws Error, named after caller, unless segmentation's labels are CV_32SC1 and floor CV_8UC1, both of
// grid's size, and its rooms are numbered 1..N in order.
void check_labelled(const Segmentation& segmentation, const OccupancyGrid& grid, const cv::Mat& floor, const char* caller);

}  // namespace topocut
