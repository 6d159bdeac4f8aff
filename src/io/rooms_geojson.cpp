#include "topocut/io/rooms_geojson.h"

#include <nlohmann/json.hpp>

#include "io/json_coordinates.h"
#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"

namespace topocut {
namespace {

using json_coordinates::point;
using nlohmann::json;

// RFC 7946 3.1.6: exterior counter-clockwise, holes clockwise, first position repeated at the end.
json closed_ring(const Ring& ring, bool counter_clockwise) {
  json out = json::array();
  for (const Point2& p : oriented(ring, counter_clockwise)) out.push_back(point(p));
  if (!out.empty()) out.push_back(out.front());
  return out;
}

json room_feature(const Room& room, const RoomPlacement* placement) {
  json rings = json::array({closed_ring(room.polygon.outer, true)});
  for (const Ring& hole : room.polygon.holes) rings.push_back(closed_ring(hole, false));
  json properties = json_coordinates::room_properties(room, placement);
  return {{"type", "Feature"}, {"id", room.id}, {"geometry", {{"type", "Polygon"}, {"coordinates", rings}}}, {"properties", properties}};
}

json passage_feature(const Passage& p) {
  return {{"type", "Feature"},
          {"geometry", {{"type", "LineString"}, {"coordinates", json::array({point(p.cut.a), point(p.cut.b)})}}},
          {"properties", json_coordinates::passage_properties(p)}};
}

}  // namespace

std::string rooms_to_geojson(const Segmentation& s, const std::vector<RoomPlacement>& placements) {
  if (!placements.empty() && placements.size() != s.rooms.size())
    throw Error("rooms_to_geojson: " + std::to_string(placements.size()) + " placements for " + std::to_string(s.rooms.size()) + " rooms");
  // One feature per line, as the rooms JSON: big maps stay readable and diffable.
  std::string out = "{\"type\": \"FeatureCollection\", \"features\": [";
  bool first = true;
  const auto add = [&](const json& feature) {
    out += (first ? "\n" : ",\n") + feature.dump();
    first = false;
  };
  for (std::size_t k = 0; k < s.rooms.size(); ++k) add(room_feature(s.rooms[k], placements.empty() ? nullptr : &placements[k]));
  for (const Passage& p : s.passages) add(passage_feature(p));
  out += "\n]}\n";
  return out;
}

void write_rooms_geojson(const std::string& path, const Segmentation& segmentation, const std::vector<RoomPlacement>& placements) {
  write_file_atomically(path, rooms_to_geojson(segmentation, placements));
}

}  // namespace topocut
