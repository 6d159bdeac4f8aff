#pragma once
// Door-like: a cut much narrower than the space on each of its sides, which are then two rooms. One
// definition, and one measure of a side's width (the widest chord parallel to the cut near it), for
// the two stages that ask, each with its own numbers: the door rule keeps a narrow passage only when
// it is door-like (DoorOptions::door_like), and merging by the hand rules keeps door-like cuts and
// merges across the others (RoomMergeOptions::door_like).

namespace topocut {

struct DoorLikeCut {
  // A cut narrower than ratio (> 0) times the width of the space on each of its sides is door-like.
  double ratio = 0.6;
  // Metres beyond the cut where each side's width (its longest chord parallel to the cut) is sampled:
  // more than a wall, so that a door's frame is not the room behind it.
  double width_depth = 1.0;
};

}  // namespace topocut
