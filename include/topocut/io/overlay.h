#pragma once
// Pictures of a segmentation for people: rooms in distinct colours over the map, room ids, and the
// room graph (passages drawn from room to room through their door).
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"

namespace topocut {

struct OverlayOptions {
  // Pixels per map cell; 0 picks the smallest integer (at most 4) that makes the longer side at
  // least 800 pixels, so ids stay legible on small maps.
  int scale = 0;
  bool draw_ids = true;
  bool draw_passages = true;
  bool colour_by_kind = false;  // rooms tinted by kind (room_kind_colour()) instead of each its own colour
};

// A distinct, deterministic colour for room id (BGR); neighbouring ids get far-apart hues.
cv::Vec3b room_colour(int id);

// The colour (BGR) rooms of a kind are tinted in with OverlayOptions::colour_by_kind: corridors
// orange, rooms blue.
cv::Vec3b room_kind_colour(RoomKind kind);

// The colour (BGR) a passage's cut is drawn in, by the rule that made it: doors red, wall openings
// orange, island cuts magenta, wall lines blue, decomposition cuts green.
cv::Vec3b cut_rule_colour(CutRule rule);

// A point inside each room (world metres) to anchor its id and graph node: the centroid when it
// lies in the room at least two cells from its border, otherwise the centre of the room cell
// farthest from the room's border. Same order as rooms.
std::vector<Point2> room_anchor_points(const Segmentation& segmentation);

// Renders the overlay (CV_8UC3, BGR): the map in grey (obstacles dark, unknown light grey), rooms
// tinted in their colours with darker borders, ids at the anchors, and each passage as its cut (in
// its rule's colour, with a legend of the rules drawn when the image is at least 300 pixels wide)
// plus a line from one room's anchor through the cut's midpoint to the other's. Throws Error if the
// grid and the segmentation differ in size.
cv::Mat render_overlay(const OccupancyGrid& grid, const Segmentation& segmentation, const OverlayOptions& options = {});

// Writes render_overlay() as an image (format by extension), atomically. Throws Error on failure.
void write_overlay(const std::string& path, const OccupancyGrid& grid, const Segmentation& segmentation,
                   const OverlayOptions& options = {});

}  // namespace topocut
