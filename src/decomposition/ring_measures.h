#pragma once
// Size measures of a ring used by the hole rules (§4.2) and the pocket-less outer ring (§3.6).
#include <vector>

#include "decomposition/dude.h"

namespace topocut::dude {

struct Diameter {
  int m1 = -1, m2 = -1;  // corners of the farthest pair (ties: smallest point first)
  double length = 0.0;   // |m1 m2|
  double width2 = 0.0;   // twice the largest distance of a ring vertex from the line m1 m2
};

// Diameter of the given corners (one ring).
Diameter diameter_of(const Poly& poly, const std::vector<int>& ring);

}  // namespace topocut::dude
