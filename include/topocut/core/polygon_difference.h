#pragma once
// What is left of a polygon once regions are cut out of it, in exact arithmetic: the outside part of a
// room (a fan seen through its window) taken off its polygon without moving the cuts it shares with
// its neighbours.
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut {

// The parts of polygon covered by none of minus (regions that may overlap one another), largest first, outer rings counter-clockwise and holes clockwise; exact predicates and constructions,
// rounded to doubles at the end. Throws Error when a ring of any of them is not simple or a hole not
// inside its outer ring (CGAL's conditions for a polygon with holes).
std::vector<PolygonWithHoles> polygon_difference(const PolygonWithHoles& polygon, const std::vector<PolygonWithHoles>& minus);

}  // namespace topocut
