#pragma once
// Polygon simplification before the decomposition: pixel-edge rings follow every stair step of a
// slanted or noisy wall, so they carry many more vertices than the shape needs. Removing the steps
// (Douglas-Peucker with a tolerance below half a cell) keeps every ring within that tolerance of
// the pixels, so rings that were at least one cell apart cannot touch, and the decomposition has
// far fewer vertices to consider.
#include "topocut/core/geometry.h"

namespace topocut {

// Douglas-Peucker simplification of a closed ring: keeps a subset of its vertices such that every
// dropped vertex lies within tolerance of the kept polyline. The two vertices farthest apart are
// always kept. Rings of fewer than 4 vertices, or a non-positive tolerance, are returned unchanged.
Ring simplify_ring(const Ring& ring, double tolerance);

// simplify_ring on every ring of polygon; rings that would collapse below 3 vertices or to zero
// area are kept unchanged.
PolygonWithHoles simplify_polygon(const PolygonWithHoles& polygon, double tolerance);

}  // namespace topocut
