#pragma once
// The outside of a building is no room: the cells a walled room holds beyond its walls (a fan of rays
// seen through its window, merged with it) get no room, and its polygon loses that part.
#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/segmentation/open_rooms.h"

namespace topocut {

// segmentation (labels CV_32SC1 of grid; floor: the free space its rooms were made of, CV_8UC1
// nonzero) with every room that holds rays (labelled_area at least area + fan_ray_share *
// labelled_area, as leave_out_fans() reads them) and has more than walled_share of its floor inside
// the building (building_inside(), walls closed across fan_closing metres) cut back to the inside: its
// cells outside get 0, its polygon loses the outside cells' squares (its largest part is kept), its
// labelled area and centroid are its cells', and its passages whose cut's middle lies outside go.
// Rooms keep their ids. Unchanged unless options.enabled, fan_ray_share > 0 and walled_share < 1, and
// on a grid without occupied cells. Throws Error on bad options, sizes or types, rooms not numbered
// 1..N in order, or a label of no room.
void leave_out_outside_parts(Segmentation& segmentation, const OccupancyGrid& grid, const cv::Mat& floor,
                             const OpenRoomOptions& options = {});

}  // namespace topocut
