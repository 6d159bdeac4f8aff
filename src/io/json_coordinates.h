#pragma once
// Coordinates and room properties as the JSON writers print them (rooms JSON, GeoJSON): metres
// rounded to micrometres, so the text stays short and diffable, never "-0".
#include <cmath>

#include <nlohmann/json.hpp>

#include "topocut/core/geometry.h"
#include "topocut/core/segmentation.h"

namespace topocut::json_coordinates {

inline double rounded(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0.0 ? 0.0 : r;
}

inline nlohmann::json point(const Point2& p) { return nlohmann::json::array({rounded(p.x), rounded(p.y)}); }

inline nlohmann::json ring(const Ring& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const Point2& p : r) out.push_back(point(p));
  return out;
}

// What the rooms JSON and GeoJSON say of a room besides its rings: id, area (the polygon's, m²),
// labelled_area (its cells', m²), kind ("room" or "corridor"), centroid and, with a placement, inside.
inline nlohmann::json room_properties(const Room& room, const RoomPlacement* placement) {
  nlohmann::json out = nlohmann::json::object();
  out["id"] = room.id;
  out["area"] = rounded(room.area);
  out["labelled_area"] = rounded(room.labelled_area);
  out["kind"] = room_kind_name(room.kind);
  out["centroid"] = point(room.centroid);
  if (placement) out["inside"] = point(placement->inside);
  return out;
}

// What both say of a passage besides its cut: the two rooms, width (m), kind (door or opening) and
// the pipeline rule that made its cut (segmentation_rules.h).
inline nlohmann::json passage_properties(const Passage& passage) {
  nlohmann::json out = nlohmann::json::object();
  out["rooms"] = nlohmann::json::array({passage.room_a, passage.room_b});
  out["width"] = rounded(passage.width);
  out["kind"] = passage_kind(passage);
  out["rule"] = to_string(passage.rule);
  return out;
}

}  // namespace topocut::json_coordinates
