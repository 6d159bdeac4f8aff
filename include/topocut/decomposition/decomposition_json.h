#pragma once
// The JSON of a decomposition, as `topocut decompose` prints it (docs/decompose.md).
#include <string>

#include "topocut/decomposition/decompose.h"

namespace topocut {

// {"pieces": [{"outer", "holes", "area"}...], "cuts": [[a, b]...], "absorbed_holes": [ring...]}
// in that key order, coordinates in the polygon's own units at full double precision; one line
// ending in a newline.
std::string decomposition_to_json(const Decomposition& decomposition);

}  // namespace topocut
