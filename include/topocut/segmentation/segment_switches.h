#pragma once
// The on/off switches of segmentation as people give them (the segment command's flags, Python's
// keyword arguments), and what each does to SegmentOptions: defined once, so that every front end
// means the same thing by the same name.
#include "topocut/segmentation/segmenter.h"

namespace topocut {

struct SegmentSwitches {
  bool trivial = false;           // --trivial: one room per free-space component
  bool parity = false;            // --parity: the reference behaviour (parity_segment_options)
  bool no_doors = false;          // --no-doors
  bool no_wall_openings = false;  // --no-wall-openings
  bool no_merge = false;          // --no-merge
  bool no_simplify = false;       // --no-simplify
  bool no_clean = false;          // --no-clean
  bool no_width_steps = false;    // --no-width-steps
  bool no_furniture_rule = false; // --no-furniture-rule
  // parity resets min-room-area to the reference's unless the caller gave it.
  bool min_room_area_given = false;
};

// Applies the switches to options (whose numbers the caller has set). Throws Error if parity is
// combined with a switch or option it already overrides.
void apply(const SegmentSwitches& switches, SegmentOptions& options);

}  // namespace topocut
