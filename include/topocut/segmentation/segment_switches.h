#pragma once
// The options of segmentation as people give them (every command's flags, --config keys, the
// benchmarks' arguments, Python's keyword arguments) and what each does to SegmentOptions: defined
// once, so that every front end means the same thing by the same name.
#include <vector>

#include "topocut/core/option_table.h"
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
  bool no_wall_lines = false;     // --no-wall-lines
  bool no_island_cuts = false;    // --no-island-cuts
  // parity resets min-room-area to the reference's unless the caller gave it.
  bool min_room_area_given = false;
};

// Applies the switches to options (whose numbers the caller has set). The --parity rule: parity
// sets the reference behaviour (parity_segment_options at options' concavity: no door cuts, no
// merging, no simplification, no cleaning, absorbed obstacles not covered, the reference's smallest
// room area unless min_room_area_given); combined with a switch it already sets (no_doors,
// no_wall_openings, no_merge, no_simplify, no_clean, no_width_steps, no_furniture_rule,
// no_wall_lines, no_island_cuts) or with labels.cover_absorbed_obstacles it throws Error. Numbers it does not set
// (robot radius, hole area, ...) and trivial still apply.
void apply(const SegmentSwitches& switches, SegmentOptions& options);

// What a front end collects before apply(): the numbers in options, the switches beside them.
struct SegmentSettings {
  SegmentOptions options;
  SegmentSwitches switches;
};

// The segmentation options, in the order help lists them: concavity, trivial, parity, door-width,
// no-doors, ..., oversegment. Setting min-room-area also sets switches.min_room_area_given.
const std::vector<OptionRow<SegmentSettings>>& segment_option_rows();

// settings.options with the switches applied (apply()) and validated (validate()); throws Error.
SegmentOptions to_segment_options(const SegmentSettings& settings);

}  // namespace topocut
