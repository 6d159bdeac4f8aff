#pragma once
// Which rings of a polygon break the decomposition's input rule (rings simple and pairwise
// disjoint), so that a caller can repair just those: the segmenter keeps a ring's exact pixel
// outline where its simplification crossed or touched itself or a neighbour.
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut {

// The rings of polygon (0: the outer ring, 1..: the holes in order) with an edge that crosses or
// touches an edge of the same or another ring (other than the common vertex of two consecutive
// edges), found as decompose()'s validation finds them; empty when none does. Inputs too spiky
// for the validation's edge grid return every ring.
std::vector<int> intersecting_rings(const PolygonWithHoles& polygon);

}  // namespace topocut
