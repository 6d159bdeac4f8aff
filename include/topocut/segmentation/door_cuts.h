#pragma once
// Doors before decomposition: DuDe cuts where the boundary is concave at the scale tau, which is
// not where people put room boundaries; a door is a narrow passage between two wider spaces. This
// stage finds such passages geometrically, at every wall corner that points into free space (a
// reflex vertex: door jambs, wall ends), as the shortest segment that resolves the corner, and
// keeps the segments that are much narrower than the space on both of their sides. DoorOptions also
// holds the options of the other cut rules, which share the search (wall_openings.h, island_cuts.h,
// wall_lines.h); the component is split along all their cuts, and each part is decomposed on its own.
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut {

struct DoorOptions {
  // false: no door detection (the reference behaviour: DuDe alone).
  bool enabled = true;
  // Widest passage (metres) taken for a door. Doors are about 0.8-1.2 m wide; double doors and
  // openings between rooms reach 2 m.
  double max_width = 2.0;
  // A passage is a door when it is narrower than door_ratio times the width of the space on each
  // of its sides (the longest chord parallel to it within width_depth).
  double door_ratio = 0.6;
  // How far (metres) beyond the passage the width of each side is sampled; more than a wall's
  // thickness, so that the door frame does not count as the space behind it.
  double width_depth = 1.0;
  // Corners that turn by less than this (radians) are not wall corners but bends of a wall.
  double min_turn = 0.5;
  // Openings in walls: from the end of a thin wall (at most max_wall_thickness thick, so not
  // furniture or the building's outline) along the wall to the first obstacle within max_gap, or
  // to a wall end there that faces it (within gap_alignment radians). A room front open to a
  // corridor is as wide as the room, so no width test can find it; a wall that stops short can.
  // Walls shorter than min_wall_length give no direction; both sides must be min_side_width wide.
  // The thickness is measured wall_end_probe behind the end (at most half the wall's length): an
  // interior partition is 0.1-0.2 m thick, plus a cell of outline simplification at 5 cm; a thicker
  // obstacle is a cupboard, a pillar or the outline. Below the 0.3 m within which two cuts count as
  // one, so the two corners of one wall end give one opening.
  bool extend_walls = true;
  double max_gap = 3.0;
  double max_wall_thickness = 0.25;
  double wall_end_probe = 0.15;
  double min_wall_length = 0.3;
  double gap_alignment = 0.2;
  double min_side_width = 1.0;
  // Island cuts (find_island_cuts): door-like cuts between the outline and a wall island, or two
  // islands. A wall island is a hole longer than min_island_length (the merging's furniture size:
  // anything smaller is furniture) whose mean thickness (2 area / perimeter) is at most
  // max_island_thickness: a piece of partition whose joint to the next wall the sensor missed, a
  // wall between two doors. A door onto such an island separates rooms only together with the cuts
  // on the island's other sides, so these are ordinary cuts that merging may remove.
  bool island_cuts = true;
  double max_island_thickness = 0.25;
  double min_island_length = 2.5;
  // Wall lines (find_wall_line_cuts): from a corner, a straight wall at least wall_line_wall long
  // (every point within wall_line_straightness of its line) continued across at most max_wall_line
  // metres of free space to the next wall (at least wall_line_side long, leaving both sides that
  // wide), as people draw room boundaries across wide openings. Of two lines closer than
  // wall_line_spacing along their whole length (the two faces of a partition continued across a
  // corridor) only the shorter is kept: the strip between them is no room.
  bool wall_lines = true;
  double max_wall_line = 5.0;
  double wall_line_wall = 2.5;
  double wall_line_straightness = 0.2;
  double wall_line_spacing = 2.5;
  // A wall line is at least this long (metres) and leaves both of its sides this wide.
  double wall_line_side = 1.0;
};

// Throws Error unless the options are usable.
void validate(const DoorOptions& options);

// Narrow passages (the door rule): from every reflex corner of a free-space polygon (grid coordinates,
// one unit per cell; resolution converts the options' metres), the shortest cut across it to the same
// ring, kept where both sides are much wider (door_ratio); pairwise disjoint (they may share an end
// point), each splitting the polygon in two, narrowest first. Empty unless options.enabled. Deterministic.
std::vector<Segment2> find_passage_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options = {});

// Every door cut: the narrow passages, then the wall openings (wall_openings.h) clear of them; empty
// unless options.enabled.
std::vector<Segment2> find_door_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options = {});

}  // namespace topocut
