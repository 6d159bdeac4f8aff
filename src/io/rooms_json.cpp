#include "topocut/io/rooms_json.h"

#include <array>
#include <cmath>

#include <nlohmann/json.hpp>

#include "io/json_coordinates.h"
#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"

namespace topocut {

using json_coordinates::point;
using json_coordinates::rounded;
using nlohmann::json;

namespace {

// A coordinate as the library's serializer prints a double (its dump_float(): "null" unless finite,
// else its own shortest round-trip digits, nlohmann::detail::to_chars).
void append_number(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  std::array<char, 64> buffer{};
  const char* end = nlohmann::detail::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
  out.append(buffer.data(), static_cast<std::size_t>(end - buffer.data()));
}

// A ring as json_coordinates::ring(r).dump() prints it, without the tree of a node per number and a
// serializer per room (most of the cost of writing a real map's rooms).
void append_ring(std::string& out, const Ring& r) {
  out += '[';
  for (std::size_t k = 0; k < r.size(); ++k) {
    out += k ? ",[" : "[";
    append_number(out, rounded(r[k].x));
    out += ',';
    append_number(out, rounded(r[k].y));
    out += ']';
  }
  out += ']';
}

// A room as its JSON object's dump() prints it, its rings appended by append_ring() in the places of
// their keys in the object's (sorted) key order.
std::string room_text(const Room& room, const RoomPlacement* placement) {
  json entry = json_coordinates::room_properties(room, placement);
  entry["outer"] = nullptr;
  entry["holes"] = nullptr;
  std::string out = "{";
  for (auto it = entry.begin(); it != entry.end(); ++it) {
    if (it != entry.begin()) out += ',';
    out += json(it.key()).dump() + ':';
    if (it.key() == "outer") {
      append_ring(out, room.polygon.outer);
    } else if (it.key() == "holes") {
      out += '[';
      for (std::size_t h = 0; h < room.polygon.holes.size(); ++h) {
        if (h) out += ',';
        append_ring(out, room.polygon.holes[h]);
      }
      out += ']';
    } else {
      out += it.value().dump();
    }
  }
  return out + '}';
}

}  // namespace

std::string rooms_to_json(const Segmentation& s, const std::vector<RoomPlacement>& placements) {
  if (!placements.empty() && placements.size() != s.rooms.size())
    throw Error("rooms_to_json: " + std::to_string(placements.size()) + " placements for " + std::to_string(s.rooms.size()) + " rooms");
  // One room or passage per line: compact enough for big maps, still readable and diffable.
  std::string out = "{\"units\": \"metres\", \"frame\": \"map\", \"resolution\": " + json(s.resolution).dump() +
                    ", \"origin\": " + point(s.origin).dump() + ", \"size\": " +
                    json::array({s.labels.cols, s.labels.rows}).dump() + ",\n\"rooms\": [";
  for (std::size_t i = 0; i < s.rooms.size(); ++i) {
    out += (i ? ",\n " : "\n ") + room_text(s.rooms[i], placements.empty() ? nullptr : &placements[i]);
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
