#include "topocut/io/polygon_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"

namespace topocut {
namespace {

Ring parse_ring(const nlohmann::json& value, const std::string& what, const std::string& source) {
  if (!value.is_array()) throw Error(source + ": " + what + " must be an array of [x, y] points");
  Ring ring;
  ring.reserve(value.size());
  for (const auto& point : value) {
    if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number()) {
      throw Error(source + ": " + what + " has a point that is not [x, y] with two numbers");
    }
    const Point2 p{point[0].get<double>(), point[1].get<double>()};
    // Why: JSON numbers beyond double range parse to inf; the geometry must never see them.
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw Error(source + ": " + what + " has a non-finite coordinate");
    ring.push_back(p);
  }
  return ring;
}

}  // namespace

PolygonWithHoles parse_polygon_json(const std::string& text, const std::string& source) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(source + " is not valid JSON: " + e.what());
  }
  if (!doc.is_object() || !doc.contains("outer")) {
    throw Error(source + " must be a JSON object with \"outer\" (and optionally \"holes\")");
  }
  PolygonWithHoles polygon;
  polygon.outer = parse_ring(doc["outer"], "\"outer\"", source);
  if (doc.contains("holes")) {
    const nlohmann::json& holes = doc["holes"];
    if (!holes.is_array()) throw Error(source + ": \"holes\" must be an array of rings");
    for (std::size_t i = 0; i < holes.size(); ++i) {
      polygon.holes.push_back(parse_ring(holes[i], "hole " + std::to_string(i), source));
    }
  }
  return polygon;
}

PolygonWithHoles read_polygon_json(const std::string& path) {
  return parse_polygon_json(read_input_file(path, "polygon JSON", kMaxPolygonJsonBytes, /*allow_stdin=*/true), path);
}

}  // namespace topocut
