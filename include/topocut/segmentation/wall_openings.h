#pragma once
// Openings in walls: a room front open to a corridor is as wide as the room, so no width test finds it;
// a thin wall that stops short of the next obstacle does. From the end of a thin wall (a partition, not
// furniture or the building's outline), along the wall, to the first obstacle or to a wall end facing it.
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/segmentation/door_cuts.h"

namespace topocut {

// The wall openings of a free-space polygon (grid coordinates; options.max_gap, max_wall_thickness,
// wall_end_probe, min_wall_length, gap_alignment, min_side_width), clear of doors (which are not
// repeated); narrowest first, none crossing another. Empty unless options.extend_walls. index: as
// find_passage_cuts'.
std::vector<Segment2> find_wall_openings(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                                         const std::vector<Segment2>& doors, const CutSearchIndex* index = nullptr);

}  // namespace topocut
