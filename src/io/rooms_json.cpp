#include "topocut/io/rooms_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "io/json_coordinates.h"
#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"

namespace topocut {

using json_coordinates::point;
using json_coordinates::ring;
using nlohmann::json;

std::string rooms_to_json(const Segmentation& s, const std::vector<RoomPlacement>& placements) {
  if (!placements.empty() && placements.size() != s.rooms.size())
    throw Error("rooms_to_json: " + std::to_string(placements.size()) + " placements for " + std::to_string(s.rooms.size()) + " rooms");
  // One room or passage per line: compact enough for big maps, still readable and diffable.
  std::string out = "{\"units\": \"metres\", \"frame\": \"map\", \"resolution\": " + json(s.resolution).dump() +
                    ", \"origin\": " + point(s.origin).dump() + ", \"size\": " +
                    json::array({s.labels.cols, s.labels.rows}).dump() + ",\n\"rooms\": [";
  for (std::size_t i = 0; i < s.rooms.size(); ++i) {
    const Room& room = s.rooms[i];
    json holes = json::array();
    for (const Ring& hole : room.polygon.holes) holes.push_back(ring(hole));
    json entry = json_coordinates::room_properties(room, placements.empty() ? nullptr : &placements[i]);
    entry["outer"] = ring(room.polygon.outer);
    entry["holes"] = holes;
    out += (i ? ",\n " : "\n ") + entry.dump();
  }
  out += "\n],\n\"passages\": [";
  for (std::size_t i = 0; i < s.passages.size(); ++i) {
    const Passage& p = s.passages[i];
    json entry = json_coordinates::passage_properties(p);
    entry["cut"] = json::array({point(p.cut.a), point(p.cut.b)});
    out += (i ? ",\n " : "\n ") + entry.dump();
  }
  out += "\n]}\n";
  return out;
}

void write_rooms_json(const std::string& path, const Segmentation& segmentation, const std::vector<RoomPlacement>& placements) {
  write_file_atomically(path, rooms_to_json(segmentation, placements));
}

}  // namespace topocut
