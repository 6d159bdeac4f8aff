#pragma once
// Splitting a free-space polygon along cuts: the door search's cuts (doors, island cuts, wall
// lines) divide a component into parts before each is decomposed on its own. The rings and the cuts
// form a planar graph; its faces are the parts.
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut {

// The chords (as for split_polygon) that have a different part of the polygon on either side, in
// their order: every chord joining two points of one ring, and those between rings that other
// chords complete (the doors on all sides of an island of wall).
std::vector<Segment2> separating_chords(const PolygonWithHoles& polygon, const std::vector<Segment2>& chords);

// Splits polygon (outer ring CCW, holes CW, rings pairwise disjoint) along chords: segments whose
// end points lie on the rings (vertices or points on edges), that lie inside the polygon and do not
// cross each other. Returns the parts (outer CCW, holes CW), which tile the polygon; every chord in
// separating_chords is an edge of the two parts it separates, the others (between two rings, with
// one part on both sides) are left out. Throws Error if a chord end point is not on the polygon's
// boundary.
std::vector<PolygonWithHoles> split_polygon(const PolygonWithHoles& polygon, const std::vector<Segment2>& chords);

}  // namespace topocut
