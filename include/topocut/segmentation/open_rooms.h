#pragma once
// Open rooms are not rooms: a region whose outline runs mostly into space the sensor never saw (a ray
// fan through a door or window, a scrap beyond the walls) is no room a person would draw. It joins the
// room it opens from; with no room beside it (a room seen only through its door), it stays.
#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut {

struct OpenRoomOptions {
  bool enabled = true;
  // A room is open when it is at least min_area m² and more than share of its outline against walls
  // and never-seen space (room_outline.h) runs into never-seen space. Never-seen cells within
  // wall_reach metres of an occupied cell count as wall (SLAM maps leave a rim of them along walls),
  // and so do bands of them at most wall_band metres thick between free cells (walls drawn in the
  // unknown grey). And more than ragged_share of those edges must turn: laser rays end at ragged
  // frontiers, while a drawing's walls in the unknown grey run straight. The same rule counts open rooms
  // in evaluate --maps (DefectOptions).
  double min_area = 1.0;
  double share = 0.5;
  double ragged_share = 0.3;
  double wall_reach = 0.15;
  double wall_band = 0.5;
};

// Throws Error unless the numbers are finite and non-negative and share lies in [0, 1].
void validate(const OpenRoomOptions& options);

// rooms (each piece one room, grid coordinates of grid) with every open room joined to the room it
// shares the longest boundary with (their union), and an open room with no room beside it (free space
// seen through a gap, outside the building) left out: its cells stay unlabelled unless label completion
// gives them to a room nearby. Cuts stay as they are (a cut inside one room
// separates nothing). Unchanged unless options.enabled, and on a grid without occupied cells (walls
// drawn in the unknown grey: walls and never-seen space cannot be told apart).
PieceSet join_open_rooms(const PieceSet& rooms, const OccupancyGrid& grid, const OpenRoomOptions& options = {});

}  // namespace topocut
