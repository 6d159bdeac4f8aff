#pragma once
// Wall lines: people close a wide opening between two rooms by drawing the wall on. From a reflex corner,
// a straight wall continued across the free space to the next wall is a candidate room boundary that
// merging may remove.
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/segmentation/door_cuts.h"

namespace topocut {

// Candidate room boundaries beside the doors (empty unless options.wall_lines): from every reflex
// corner, each of its straight walls (options.wall_line_*) continued to the first wall of the same
// ring within options.max_wall_line metres, at least options.wall_line_side long and leaving both
// sides that wide; shortest first, none crossing a door or another, none within
// options.wall_line_spacing of a shorter one along its whole length. Doors are not repeated. index:
// as find_passage_cuts'.
std::vector<Segment2> find_wall_line_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                                          const std::vector<Segment2>& doors, const CutSearchIndex* index = nullptr);

}  // namespace topocut
