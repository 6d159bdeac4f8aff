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
#include "topocut/core/option_table.h"
#include "topocut/segmentation/cut_search_index.h"
#include "topocut/segmentation/door_like_cut.h"

namespace topocut {

// The options of every cut rule (docs/glossary.md: a cut rule finds cuts before the decomposition);
// the struct keeps its historical name. Each rule has its own switch: passages (the door rule),
// extend_walls, island_cuts, wall_lines; with all four off DuDe runs alone (--parity).
struct DoorOptions {
  // The door rule: cuts across narrow passages (--no-doors turns it off, and only it).
  bool passages = true;
  // Widest passage taken for a door, metres: doors are 0.8-1.2 m, double doors and openings 2 m.
  double max_width = 2.0;
  // A door is door-like (door_like_cut.h): narrower than 0.6 times the space on each side, the rooms
  // it joins. Its width_depth is also where the wall openings and wall lines measure their sides.
  DoorLikeCut door_like{.ratio = 0.6, .width_depth = 1.0};
  // Radians: corners turning less are bends of a wall, not wall corners.
  double min_turn = 0.5;
  // Wall openings (wall_openings.h): a thin wall that stops short continued to the next obstacle; a
  // room front open to a corridor is as wide as the room, so no width test finds it.
  bool extend_walls = true;
  double max_gap = 3.0;              // metres: longest opening a wall is continued across
  double max_wall_thickness = 0.25;  // metres: a partition (0.1-0.2) plus a cell; thicker is furniture
  double wall_end_probe = 0.15;      // metres behind the end (at most half the wall) of the thickness
  double min_wall_length = 0.3;      // metres: shorter walls give no direction
  double gap_alignment = 0.2;        // radians: a wall end across the gap this well aligned faces it
  double min_side_width = 1.0;       // metres: both sides of an opening at least this wide
  // Island cuts (island_cuts.h): door-like cuts onto a free-standing piece of wall (a partition whose
  // joint the sensor missed); ordinary cuts, so merging may remove them.
  bool island_cuts = true;
  double max_island_thickness = 0.25;  // metres, mean thickness (2 area / perimeter) of a wall island
  double min_island_length = 2.5;      // metres: shorter holes are furniture (the merging's size)
  // Wall lines (wall_lines.h): a straight wall continued across a wide opening to the next wall, as
  // people draw room boundaries.
  bool wall_lines = true;
  double max_wall_line = 5.0;           // metres of free space a line may cross
  double wall_line_wall = 2.5;          // metres: shortest straight wall continued
  double wall_line_straightness = 0.2;  // metres: every point of a straight wall this close to its line
  // Metres: of two lines this close along their whole length (a partition's two faces) only the
  // shorter is kept, since the strip between them is no room.
  double wall_line_spacing = 2.5;
  double wall_line_side = 1.0;  // metres: a wall line at least this long, leaving both sides this wide
};

// The fields of DoorOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<DoorOptions>>& door_option_rows();

// Throws Error unless the options are usable.
void validate(const DoorOptions& options);

// Narrow passages (the door rule): from every reflex corner of a free-space polygon (grid coordinates,
// one unit per cell; resolution converts the options' metres), the shortest cut across it to the same
// ring, kept where both sides are much wider (door_like); pairwise disjoint (they may share an end
// point), each splitting the polygon in two, narrowest first. Empty unless options.passages. Deterministic.
// index (cut_search_index.h), when given, holds the polygon's edges for every rule that searches it.
std::vector<Segment2> find_passage_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options = {},
                                        const CutSearchIndex* index = nullptr);

// The narrow passages (empty unless options.passages), then the wall openings (wall_openings.h, unless
// options.extend_walls is off) clear of them.
std::vector<Segment2> find_door_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options = {});

}  // namespace topocut
