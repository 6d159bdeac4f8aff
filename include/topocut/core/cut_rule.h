#pragma once
// Which rule of the segmentation pipeline made a cut between two pieces of free space, so that every
// passage of the room graph can say why it is there (JSON, overlays) and merging can weigh the cut
// by its origin.
#include <string>

namespace topocut {

enum class CutRule : unsigned char {
  kDoor,           // a narrow passage between two wider spaces (door_cuts.h)
  kWallOpening,    // a thin wall continued to the next obstacle (wall_openings.h)
  kIslandCut,      // a door-like cut between the outline and a wall island (island_cuts.h)
  kWallLine,       // a straight wall continued across a wide opening (wall_lines.h)
  kDecomposition,  // a cut of the dual-space decomposition (decompose.h)
};

// The rule's name as written in JSON and shown in overlays: "door", "wall-opening", "island-cut",
// "wall-line", "decomposition".
std::string to_string(CutRule rule);

// Door cuts and wall openings: the cuts a person reads as a door into a room.
inline bool is_door_rule(CutRule rule) { return rule == CutRule::kDoor || rule == CutRule::kWallOpening; }

}  // namespace topocut
