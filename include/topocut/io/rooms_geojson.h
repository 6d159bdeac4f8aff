#pragma once
// Rooms and passages as GeoJSON (RFC 7946), for GIS tools and web maps: a FeatureCollection in the
// map frame, in metres (not longitude/latitude: the map frame is the only frame topocut knows).
#include <string>
#include <vector>

#include "topocut/core/segmentation.h"

namespace topocut {

// Serialises a segmentation: one Polygon Feature per room (exterior ring counter-clockwise, holes
// clockwise, every ring closed; properties "kind": "room" or "corridor" (room_kinds.h), "id", "area" (the polygon's, m²),
// "labelled_area" (its cells', m²), "centroid", "inside"),
// then one LineString Feature per passage (its cut; properties "kind": "door" or "opening",
// "rooms": [a, b], "width" (m)). placements holds one entry per room (same order) for "inside"; when
// it is empty, "inside" is left out. Coordinates rounded to micrometres.
std::string rooms_to_geojson(const Segmentation& segmentation, const std::vector<RoomPlacement>& placements = {});

// Writes rooms_to_geojson() atomically; throws Error naming the path on failure.
void write_rooms_geojson(const std::string& path, const Segmentation& segmentation,
                         const std::vector<RoomPlacement>& placements = {});

}  // namespace topocut
