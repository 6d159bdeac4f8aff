#pragma once
// Pieces -> rooms: DuDe cuts a free-space component into nearly convex pieces, but rooms are not
// convex pieces (an L-shaped corridor is at least two). This stage merges pieces across cuts that
// are not door-like and folds pieces too small to be rooms into their neighbours. Everything is
// measured in metres, so one set of options fits every map resolution.
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/segmentation/merge_features.h"
#include "topocut/segmentation/merge_model.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut {

struct RoomMergeOptions {
  // false: the pieces are the rooms (the reference behaviour).
  bool enabled = true;
  // true: two rooms merge where the learned model (merge_model.h) finds them one room; false: the
  // hand rules below (door_ratio, width steps, furniture). Folding applies either way.
  bool learned = true;
  MergeModel model = default_merge_model();
  // A cut is door-like when it is narrower than door_ratio times the width of the room on each of
  // its sides (a door into a room, a room's opening onto a corridor); a cut at least this close to
  // the width of the narrower side (a corridor cut across, an L-room cut at its inner corner) is
  // not, and the rooms on its sides are merged, most clearly non-door-like cuts first.
  double door_ratio = 0.7;
  // How far into a room (metres) its width next to a cut is sampled: the width of a side is the
  // longest chord parallel to the cut within this depth. It must exceed the wall thickness, so that
  // a door's own frame does not count as the room behind it.
  double width_depth = 1.0;
  // Rooms smaller than this (m²) are folded into the neighbour they share the longest cut with
  // (slivers between cuts, free-space leaks through doors and windows).
  double min_room_area = 1.0;
  // Rooms whose widest chord parallel to any of their cuts (within width_depth of it) stays below
  // this (metres) are folded the same way: a strip this thin sticking out of a cut is a leak (laser
  // rays through a gap), not a room. 0 disables (the default: 0.4-0.8 m change nothing on the Bormann
  // maps, whose leaks are free-space components of their own).
  double min_room_width = 0.0;
  // Rooms thinner than this (metres; thickness = 2 area / perimeter: a strip's width, half a square's
  // side) are folded the same way: slivers between two parallel cuts or along a wall, the roots of
  // laser-ray fans. 0.6 m is the width of a person (the same disc the defect count uses).
  double min_room_thickness = 0.6;
  // Obstacles whose bounding box is at most this long on both sides (metres) are furniture: a cut
  // that ends on one is no room boundary (a room does not end at a table), so the rooms on its sides
  // merge. Larger obstacles (a building's core, a detached wall) may separate rooms. 0 disables.
  double furniture_size = 2.5;
  // Width steps: a room that opens across its whole width onto a space much wider than itself (its
  // width below step_ratio times the other side's) and at least step_min_wide_depth deep stays a room
  // of its own when both are at least step_min_area m², as people separate rooms of a floor plan
  // joined by wide openings. The depth test keeps a corridor (shallow behind its side openings)
  // merged with what opens onto it. step_ratio 0 disables.
  double step_ratio = 0.6;
  double step_min_area = 6.0;
  double step_min_wide_depth = 5.0;
  // Across a wall line (PieceSet::wall_lines: the narrow room's wall drawn on) the wider side need
  // only be this many times as deep as the narrow side is wide: a room opening onto a shallow hall.
  // An L-shaped corridor's corner is as deep as the corridor is wide, so it stays one room.
  double step_wall_line_depth = 1.25;
};

// Throws Error unless the options are usable (finite, non-negative, door_ratio > 0).
void validate(const RoomMergeOptions& options);

// Merges the pieces of one free-space component (grid coordinates: one unit per cell, as from the
// decomposition; resolution converts the options' metres) into rooms. component.polygon tells
// furniture (its small holes) from walls. The result's pieces are the
// rooms, each the exact union of the pieces merged into it (union_of_pieces), ordered by their
// first piece; its cuts are the cuts between two different rooms, in their input order. Cuts
// that do not separate two pieces (keyhole cuts) are dropped. With options.enabled false, the
// input is returned unchanged.
// If trace is given, every candidate merge the learned criterion weighs is appended to it.
PieceSet merge_rooms(const FreeSpaceComponent& component, const PieceSet& pieces, double resolution,
                     const RoomMergeOptions& options = {}, std::vector<MergeStep>* trace = nullptr);

// The union of pieces that tile a region without overlapping and meet only along whole shared
// edges (as DuDe's pieces do): every edge traversed in both directions is removed and the rest is
// linked into rings, outer ring counter-clockwise, holes clockwise. Vertices where a removed edge
// met the boundary stay, even where the boundary goes straight on through them.
// Throws Error if the pieces do not form one connected region.
PolygonWithHoles union_of_pieces(const std::vector<PolygonWithHoles>& pieces);

}  // namespace topocut
