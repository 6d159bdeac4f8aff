#pragma once
// The walls of a log as JSON, as `topocut walls --out-walls` writes them.
#include <cstddef>
#include <string>

#include "topocut/walls/walls_pipeline.h"

namespace topocut {

// {"units": "metres", "scans", "segments", "thickness", "walls": [{"id", "start": [x, y],
// "end": [x, y], "length", "observations", "polygon": [[x, y] ×4]}]}, metres rounded to micrometres.
std::string walls_to_json(const WallsResult& result, std::size_t scans, double thickness);

}  // namespace topocut
