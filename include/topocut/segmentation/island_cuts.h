#pragma once
// Island cuts: a partition whose joint to the next wall the sensor missed stands free in the map (a wall
// island), and every door of the rooms beside it leads round it. Door-like cuts from the outline to such
// an island separate rooms only together, so they are ordinary cuts that merging may remove.
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/segmentation/door_cuts.h"

namespace topocut {

// Door-like cuts between rings (empty unless options.island_cuts): from a reflex corner of the outline
// or of a wall island (a hole longer than min_island_length, at most max_island_thickness thick on
// average) to the nearest point of another of these, found and tested as doors are, not crossing the
// doors; only those that, with the doors and each other, have a different part of the polygon on either
// side (separating_chords). Doors are not repeated. index: as find_passage_cuts'.
std::vector<Segment2> find_island_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                                       const std::vector<Segment2>& doors, const CutSearchIndex* index = nullptr);

}  // namespace topocut
