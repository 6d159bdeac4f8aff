#pragma once
// The options of segmentation as people give them (every command's flags, --config keys, the
// benchmarks' arguments, Python's keyword arguments) and what each does to SegmentOptions: defined
// once, so that every front end means the same thing by the same name.
#include <cstddef>
#include <string>
#include <vector>

#include "topocut/core/option_table.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

struct SegmentSwitches {
  bool trivial = false;                 // --trivial: one room per free-space component
  bool parity = false;                  // --parity: the reference behaviour (parity_segment_options)
  std::vector<std::string> rules_off;   // --no-NAME: rules of segmentation_rules() switched off
  // parity resets min-room-area to the reference's unless the caller gave it.
  bool min_room_area_given = false;
  // A merge model was given (--merge-model, merge_model=): learned merging must be on to use it.
  bool merge_model_given = false;
};

// The merge model: the one segmentation option that is no number, so no row. The command line and
// --config take the model's FILE, Python's merge_model= its text; absent (None) means the shipped model.
struct TextOption {
  const char* name;
  const char* value_name;
  const char* help;
};
inline constexpr TextOption kMergeModelOption{
    "merge-model", "FILE",
    "a learned merge model (as scripts/train_merge_model.py writes one) to merge with instead of the shipped one; "
    "an error with learned merging off"};

// Applies the switches to options (whose numbers the caller has set). The --parity rule: parity
// sets the reference behaviour (parity_segment_options at options' concavity: every rule of
// segmentation_rules() off, absorbed obstacles not covered, the reference's smallest room area unless
// min_room_area_given); combined with a rule switched off or with labels.cover_absorbed_obstacles it
// throws Error. Numbers it does not set (robot radius, hole area, ...) and trivial still apply. A
// merge model given while the switches leave no learned merging to use it is an Error too.
void apply(const SegmentSwitches& switches, SegmentOptions& options);

// What a front end collects before apply(): the numbers in options, the switches beside them.
struct SegmentSettings {
  SegmentOptions options;
  SegmentSwitches switches;
};

// The segmentation options, in the order help lists them: concavity, trivial, parity, a no-NAME switch
// per rule of segmentation_rules() that has a switch, in the pipeline's order, then the fields of every options struct
// under SegmentOptions by that struct's own table (binarize_option_rows(), door_option_rows(), ...) in
// the pipeline's order. Setting min-room-area also sets switches.min_room_area_given.
const std::vector<OptionRow<SegmentSettings>>& segment_option_rows();

// A run of consecutive rows of segment_option_rows() under one heading (the rows of one options
// struct), for a help text that a reader can find an option in.
struct OptionGroup {
  std::string heading;
  std::size_t rows = 0;
};

// segment_option_rows() in consecutive groups, one per options struct, each with the heading a help
// text shows above it; the groups' row counts add up to the table's.
const std::vector<OptionGroup>& segment_option_groups();

// The heading of the merging rows (RoomMergeOptions), under which front ends list the merge model.
inline constexpr const char* kMergingHeading = "Merging pieces into rooms";

// settings.options with the switches applied (apply()) and validated (validate()); throws Error.
SegmentOptions to_segment_options(const SegmentSettings& settings);

}  // namespace topocut
