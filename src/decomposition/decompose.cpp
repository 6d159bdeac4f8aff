#include "topocut/decomposition/decompose.h"

#include <cmath>

#include "decomposition/validate.h"
#include "topocut/core/error.h"

namespace topocut {

Decomposition decompose(const PolygonWithHoles& polygon, const DecompositionOptions& options) {
  if (!(options.tau > 0.0) || !std::isfinite(options.tau)) throw Error("tau must be a positive finite number");
  if (options.max_rounds < 1) throw Error("max_rounds must be at least 1");
  Decomposition result;
  result.pieces.push_back(dude::clean_and_validate(polygon));
  return result;
}

}  // namespace topocut
