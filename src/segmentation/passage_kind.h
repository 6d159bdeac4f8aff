#pragma once
// Door or wider opening: one rule for every segmenter that makes passages.
#include "topocut/core/segmentation.h"
#include "topocut/segmentation/door_cuts.h"

namespace topocut {

// A passage is a door (Passage::door) when its cut is at most the door width (--door-width,
// DoorOptions::max_width), a wider one is an opening.
inline bool is_door(const Passage& passage, const DoorOptions& doors) { return passage.width <= doors.max_width + 1e-9; }

}  // namespace topocut
