#include "topocut/walls/walls_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "topocut/walls/wall_map.h"

namespace topocut {

namespace {
// Micrometres are plenty for metres and keep the text short.
double rounded(double v) { return std::round(v * 1e6) / 1e6; }
}  // namespace

std::string walls_to_json(const WallsResult& result, std::size_t scans, double thickness) {
  nlohmann::json out;
  out["units"] = "metres";
  out["scans"] = scans;
  out["segments"] = result.segments.size();
  out["thickness"] = thickness;
  nlohmann::json walls = nlohmann::json::array();
  for (std::size_t i = 0; i < result.walls.size(); ++i) {
    const Wall& w = result.walls[i];
    nlohmann::json polygon = nlohmann::json::array();
    for (const Point2& p : wall_polygon(w.segment, thickness)) polygon.push_back({rounded(p.x), rounded(p.y)});
    walls.push_back({{"id", i},
                     {"start", {rounded(w.segment.a.x), rounded(w.segment.a.y)}},
                     {"end", {rounded(w.segment.b.x), rounded(w.segment.b.y)}},
                     {"length", rounded(distance(w.segment.a, w.segment.b))},
                     {"observations", w.observations},
                     {"polygon", polygon}});
  }
  out["walls"] = walls;
  return out.dump(1) + "\n";
}

}  // namespace topocut
