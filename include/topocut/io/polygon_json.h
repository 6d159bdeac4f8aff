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

// Reads and parses a polygon JSON file ("-": standard input) of at most kMaxPolygonJsonBytes
// (core/input_file.h); only regular files. Throws Error naming the path.
PolygonWithHoles read_polygon_json(const std::string& path);

}  // namespace topocut
