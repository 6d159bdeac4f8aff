#include "topocut/decomposition/decomposition_json.h"

#include <nlohmann/json.hpp>

namespace topocut {
namespace {

nlohmann::ordered_json ring_json(const Ring& ring) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Point2& p : ring) out.push_back({p.x, p.y});
  return out;
}

}  // namespace

std::string decomposition_to_json(const Decomposition& decomposition) {
  nlohmann::ordered_json out;
  nlohmann::ordered_json pieces = nlohmann::ordered_json::array();
  for (const PolygonWithHoles& piece : decomposition.pieces) {
    nlohmann::ordered_json holes = nlohmann::ordered_json::array();
    for (const Ring& hole : piece.holes) holes.push_back(ring_json(hole));
    pieces.push_back({{"outer", ring_json(piece.outer)}, {"holes", holes}, {"area", area(piece)}});
  }
  out["pieces"] = pieces;
  nlohmann::ordered_json cuts = nlohmann::ordered_json::array();
  for (const Cut& cut : decomposition.cuts) {
    cuts.push_back({{cut.segment.a.x, cut.segment.a.y}, {cut.segment.b.x, cut.segment.b.y}});
  }
  out["cuts"] = cuts;
  nlohmann::ordered_json absorbed = nlohmann::ordered_json::array();
  for (const Ring& hole : decomposition.absorbed_holes) absorbed.push_back(ring_json(hole));
  out["absorbed_holes"] = absorbed;
  return out.dump() + "\n";
}

}  // namespace topocut
