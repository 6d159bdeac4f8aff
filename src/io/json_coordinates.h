#pragma once
// Coordinates as the JSON writers print them (rooms JSON, GeoJSON): metres rounded to micrometres,
// so the text stays short and diffable, never "-0".
#include <cmath>

#include <nlohmann/json.hpp>

#include "topocut/core/geometry.h"

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

}  // namespace topocut::json_coordinates
