#pragma once
// The outside of a building is no room: the cells a walled room holds beyond its walls (a fan of rays
// seen through its window, merged with it) get no room, and its polygon loses that part.
#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/map/building_inside.h"
#include "topocut/segmentation/open_rooms.h"

namespace topocut {

// segmentation (labels CV_32SC1 of grid; floor: the free space its rooms were made of, CV_8UC1
// nonzero) with every room cut back to the building's inside (building_inside(), walls closed across
// fan_closing metres) that holds rays (holds_rays(), as leave_out_fans() reads them), has more than
// fan_inside_share of its floor inside, whose floor outside is open (room_outline(): mostly against
// never-seen cells, those edges ragged) and whose floor inside is not: its cells outside get 0, and so do the parts of it but the
// largest that touch the outside (bits of the fan the closing enclosed); its polygon becomes the outline
// of the floor cells it keeps (their largest part, along the cells' edges, specks filled as in the free
// space's polygons); its labelled area and centroid become its cells'; its passages whose cut's middle
// lies outside go.
// Rooms keep their ids. Nothing is cut where a room without rays (labelled_area <= area) has most of its
// floor outside: the map's walls do not enclose its rooms. Unchanged unless options.enabled,
// fan_ray_share > 0 and cut_outside_parts, and on a grid without occupied cells. Throws Error on bad
// options, sizes or types, rooms not numbered 1..N in order, or a label of no room. inside, if given, is
// grid's building inside, shared with the row before.
void leave_out_outside_parts(Segmentation& segmentation, const OccupancyGrid& grid, const cv::Mat& floor,
                             const OpenRoomOptions& options = {}, BuildingInside* inside = nullptr);

}  // namespace topocut
