#pragma once
// Rooms as a scalable vector drawing: room polygons (metres, y up in the world, flipped for SVG),
// ids, passages, optionally over the map itself.
#include <string>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"

namespace topocut {

struct SvgOptions {
  bool embed_map = true;  // the map as a PNG image under the polygons (makes the file larger)
};

// An SVG document whose user units are metres: x = world x - origin.x, y = map height - (world y -
// origin.y). Rooms are even-odd paths (holes stay open) in the overlay's colours, passages red
// lines with the room graph drawn through them, ids at room_anchor_points(). Throws Error if the
// grid and the segmentation differ in size.
std::string rooms_to_svg(const OccupancyGrid& grid, const Segmentation& segmentation, const SvgOptions& options = {});

// Writes rooms_to_svg() atomically; throws Error naming the path on failure.
void write_rooms_svg(const std::string& path, const OccupancyGrid& grid, const Segmentation& segmentation,
                     const SvgOptions& options = {});

}  // namespace topocut
