#pragma once
// Open rooms are not rooms: a region whose outline runs mostly into space the sensor never saw (a ray
// fan through a door or window, a scrap beyond the walls) is no room a person would draw. It joins the
// room it opens from; with no room beside it (free space outside the building), it is left out; and
// so is a room that is still open once labelled and holds the rays of a fan.
#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"
#include "topocut/map/building_inside.h"
#include "topocut/map/rasterize.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut {

struct OpenRoomOptions {
  bool enabled = true;
  // A room is open when more than share of its outline (room_outline.h) runs into never-seen space
  // and more than ragged_share of those edges turn (rays end raggedly, drawn walls run straight).
  // evaluate --maps counts open rooms by the same rule (DefectOptions).
  double min_area = 1.0;      // m²: smaller rooms are never open
  double share = 0.5;         // [0, 1] of the outline against walls and never-seen space
  double ragged_share = 0.3;  // [0, 1] of the never-seen edges that turn
  double wall_reach = 0.15;   // metres: never-seen cells this close to a wall count as wall (SLAM rim)
  double wall_band = 0.5;     // metres: never-seen bands this thin between free cells are drawn walls
  // A room with no room beside it is open too when less than floor_share of the cells the labelling
  // gives it are its floor: the rest are rays the cleaning removed (free cells of no piece, given to the
  // nearest piece along free space; counted within the room's longer side around its extent), so the
  // room a person sees is a fan seen only through a gap in a wall, however walled the floor under its
  // densest rays. Rooms beside others are not judged so (a room is not less a room for the fan through
  // its door).
  double floor_share = 0.5;  // [0, 1]; 0: off
  // A labelled room still open by its floor's outline that the labelling gave at least fan_ray_share of
  // its cells beyond its polygon (rays the cleaning removed; a drawn plan's rooms get almost none, 0.6 %
  // on Bormann's octagon hall drawn in grey, against 3-8 % on the fans of robot-made maps) is a fan seen
  // through a gap in a wall: no room at all (leave_out_fans()).
  double fan_ray_share = 0.02;  // [0, 1]; 0: off
  // A fan with more than fan_inside_share of its floor inside the building (leave_out_fans()) is a walled
  // room that holds the fan seen through its door, and stays (cut back to the inside: cut_outside_parts):
  // with the walls closed across 2 m, the fans outside robot-made offices have at most 6 % of their floor
  // inside, a hall or a small room by a home's front door with its fan 26-58 % (benchmarks/README.md,
  // "Fans of rays left out").
  double fan_inside_share = 0.25;  // [0, 1]; 1: every fan is left out
  // Metres: the walls are closed across gaps this wide to tell the building's inside; twice the
  // cleaning's inside_closing, since at 2 m a room whose outer wall has a wider window was taken as a fan.
  double fan_closing = 4.0;
  // A room that holds rays (fan_ray_share) with more than fan_inside_share of its floor inside the
  // building is walled, whatever its outline: its floor outside is a fan seen through its window that
  // merging joined to it, and no room's (leave_out_outside_parts(), outside_parts.h).
  bool cut_outside_parts = true;
};

// The fields of OpenRoomOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<OpenRoomOptions>>& open_room_option_rows();

// Throws Error unless the numbers are finite and non-negative and the shares lie in [0, 1].
void validate(const OpenRoomOptions& options);

// Whether the labelling gave room at least fan_ray_share of its cells beyond its polygon (labelled_area
// against area): the rays of a fan the cleaning removed, which a drawn plan's rooms hardly get.
bool holds_rays(const Room& room, const OpenRoomOptions& options);

// rooms (each piece one room, grid coordinates of grid; free cells of no piece are rays the cleaning
// removed) with every open room joined to the room it shares the longest boundary with (their union),
// and every open room with no room beside it (by its outline or its floor share) and less
// than half the area of the largest room left out (its cells stay unlabelled unless label completion
// gives them to a room nearby; a lone large one is the building, or what of it was explored). Cuts stay as they
// are (a cut inside one room separates nothing). Unchanged unless options.enabled, and on a grid
// without occupied cells (walls drawn in the unknown grey: walls and never-seen space cannot be told
// apart).
PieceSet join_open_rooms(const PieceSet& rooms, const OccupancyGrid& grid, const OpenRoomOptions& options = {});

// join_open_rooms() given the rooms' spans (polygon_spans(rooms.pieces, grid.cells.size())), which the
// labelling of the same rooms reads too: the rooms are rasterized once.
PieceSet join_open_rooms(const PieceSet& rooms, const OccupancyGrid& grid, const OpenRoomOptions& options,
                         const std::vector<CellSpan>& spans);

// segmentation (labels CV_32SC1 of grid; floor: the free space its rooms were made of, CV_8UC1
// nonzero) without the rooms that are fans of rays seen through a gap: open by their floor's outline as
// join_open_rooms() judges rooms; labelled_area at least area + fan_ray_share * labelled_area (Room: the
// cells the labelling gave them beyond their polygon, the rays); beside another room or under half the
// largest room's labelled area (not the building itself); and with at most fan_inside_share of their
// floor inside the building (building_inside(): not reached from the grid's edge once the occupied
// cells are closed across gaps up to fan_closing metres). Their cells get 0, they and their passages
// go, the other rooms keep their order, numbered 1..N again. Unchanged unless options.enabled and
// fan_ray_share > 0, and on a grid without occupied cells. Throws Error on bad options, sizes or types,
// rooms not numbered 1..N in order, or a label of no room. inside, if given, is grid's building inside,
// shared with the next row that reads it.
void leave_out_fans(Segmentation& segmentation, const OccupancyGrid& grid, const cv::Mat& floor,
                    const OpenRoomOptions& options = {}, BuildingInside* inside = nullptr);

}  // namespace topocut
