#pragma once
// The rooms JSON (DESIGN.md): rooms with id, area (m²), a point inside, centroid, outer ring and holes
// (metres, map frame), and passages (the two room ids, the cut's end points, its width and kind), for
// programs that consume rooms. It carries what the GeoJSON and the Python results carry.
#include <string>
#include <vector>

#include "topocut/core/segmentation.h"

namespace topocut {

// Serialises a segmentation:
// {"units": "metres", "frame": "map", "resolution", "origin": [x, y], "size": [columns, rows],
//  "rooms": [{"id", "area", "labelled_area", "kind": "room" | "corridor", "centroid": [x, y], "inside": [x, y],
//             "outer": [[x, y], ...], "holes": [[[x, y], ...], ...]}],
//  "passages": [{"rooms": [a, b], "width", "kind": "door" | "opening", "cut": [[x, y], [x, y]]}]}.
// "area" is the polygon's (outer minus holes), "labelled_area" that of the room's cells; placements
// holds one entry per room (same order) for "inside", which is left out when it is empty. Coordinates
// are rounded to micrometres so the text stays short; rooms are in id order.
std::string rooms_to_json(const Segmentation& segmentation, const std::vector<RoomPlacement>& placements = {});

// Writes rooms_to_json() atomically; throws Error naming the path on failure.
void write_rooms_json(const std::string& path, const Segmentation& segmentation,
                      const std::vector<RoomPlacement>& placements = {});

}  // namespace topocut
