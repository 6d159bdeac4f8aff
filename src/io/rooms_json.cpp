#include "topocut/io/rooms_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "io/json_coordinates.h"
#include "topocut/io/atomic_file.h"

namespace topocut {

using json_coordinates::point;
using json_coordinates::ring;
using json_coordinates::rounded;
using nlohmann::json;

std::string rooms_to_json(const Segmentation& s) {
  // One room or passage per line: compact enough for big maps, still readable and diffable.
  std::string out = "{\"units\": \"metres\", \"resolution\": " + json(s.resolution).dump() +
                    ", \"origin\": " + point(s.origin).dump() + ", \"size\": " +
                    json::array({s.labels.cols, s.labels.rows}).dump() + ",\n\"rooms\": [";
  for (std::size_t i = 0; i < s.rooms.size(); ++i) {
    const Room& room = s.rooms[i];
    json holes = json::array();
    for (const Ring& hole : room.polygon.holes) holes.push_back(ring(hole));
    json entry = json::object();
    entry["id"] = room.id;
    entry["area"] = rounded(room.area);
    entry["centroid"] = point(room.centroid);
    entry["outer"] = ring(room.polygon.outer);
    entry["holes"] = holes;
    out += (i ? ",\n " : "\n ") + entry.dump();
  }
  out += "\n],\n\"passages\": [";
  for (std::size_t i = 0; i < s.passages.size(); ++i) {
    const Passage& p = s.passages[i];
    json entry = json::object();
    entry["rooms"] = json::array({p.room_a, p.room_b});
    entry["cut"] = json::array({point(p.cut.a), point(p.cut.b)});
    entry["width"] = rounded(p.width);
    out += (i ? ",\n " : "\n ") + entry.dump();
  }
  out += "\n]}\n";
  return out;
}

void write_rooms_json(const std::string& path, const Segmentation& segmentation) {
  write_file_atomically(path, rooms_to_json(segmentation));
}

}  // namespace topocut
