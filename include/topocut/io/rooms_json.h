#pragma once
// The rooms JSON (DESIGN.md): rooms with id, area (m²), centroid, outer ring and holes (metres), and
// passages (the two room ids, the cut's end points, its width), for programs that consume rooms.
#include <string>

#include "topocut/core/segmentation.h"

namespace topocut {

// Serialises a segmentation:
// {"units": "metres", "resolution", "origin": [x, y], "size": [columns, rows],
//  "rooms": [{"id", "area", "centroid": [x, y], "outer": [[x, y], ...], "holes": [[[x, y], ...], ...]}],
//  "passages": [{"rooms": [a, b], "cut": [[x, y], [x, y]], "width"}]}.
// Coordinates are rounded to micrometres so the text stays short; rooms are in id order.
std::string rooms_to_json(const Segmentation& segmentation);

// Writes rooms_to_json() atomically; throws Error naming the path on failure.
void write_rooms_json(const std::string& path, const Segmentation& segmentation);

}  // namespace topocut
