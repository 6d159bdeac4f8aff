#pragma once
// Polygon-with-holes JSON, the input of `topocut decompose`:
//   {"outer": [[x, y], ...], "holes": [[[x, y], ...], ...]}   ("holes" optional)
#include <string>

#include "topocut/core/geometry.h"

namespace topocut {

// Parses polygon JSON text; `source` names it in errors. Rings keep their orientation and points
// as written (geometric validity is the decomposition's check). Throws Error on invalid JSON, a
// missing "outer", a ring that is not an array of [x, y] number pairs, or a non-finite coordinate.
PolygonWithHoles parse_polygon_json(const std::string& text, const std::string& source = "polygon");

}  // namespace topocut
