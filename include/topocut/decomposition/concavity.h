#pragma once
// How far a polygon is from convex, measured the way DuDe measures it (dude-algorithm.md §3.4, §4.2):
// used to check decomposition results and to compare variants.
#include "topocut/core/geometry.h"

namespace topocut {

struct Concavity {
  // Largest distance of an outer-ring vertex from the convex-hull edge (bridge) that spans it: the
  // straight-line pocket depth of the reference code.
  double pocket_depth = 0.0;
  // Largest size of a hole, min(diameter, 2 * width about the diameter): the rule that decides
  // whether DuDe treats a hole as an obstacle or as noise.
  double hole = 0.0;

  double max() const { return pocket_depth > hole ? pocket_depth : hole; }
};

// Measures polygon (any orientation; rings may touch themselves, e.g. keyhole rings).
Concavity measure_concavity(const PolygonWithHoles& polygon);

}  // namespace topocut
