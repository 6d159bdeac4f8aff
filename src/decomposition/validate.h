#pragma once
// Input hygiene for the decomposition: what decompose() accepts and how it normalises it.
#include "topocut/core/geometry.h"

namespace topocut::dude {

// Returns the polygon with consecutive duplicate vertices (and a repeated closing vertex) removed,
// the outer ring counter-clockwise and the holes clockwise. A reversed ring keeps its first vertex,
// so the result does not depend on the input orientation. Throws Error when a ring has non-finite
// coordinates or fewer than 3 distinct vertices, when rings intersect or touch (themselves or each
// other), when a hole is not strictly inside the outer ring, when a hole lies inside another, or
// when the polygon is outside the scale of value_ranges.h (|coordinate| <= 1e12, extent >= 1e-6).
PolygonWithHoles clean_and_validate(const PolygonWithHoles& polygon);

// The intersection test used for inputs whose edges are too long for the grid: throws Error unless
// the rings are simple and pairwise disjoint (exposed for tests; clean_and_validate chooses).
void check_rings_by_triangulation(const PolygonWithHoles& polygon);

// True when a simple ring is counter-clockwise; exact (orientation at its lowest-leftmost vertex),
// so it does not suffer from cancellation far from the origin as the shoelace sum does.
bool is_counter_clockwise(const Ring& ring);

// Reverses a ring but keeps its first vertex first: v0, v(n-1), ..., v1.
Ring reversed_keep_first(const Ring& ring);

}  // namespace topocut::dude
