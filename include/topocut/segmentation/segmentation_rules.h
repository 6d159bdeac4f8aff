#pragma once
// The rules of segment(), in the order they run, in one list: what a reader reads to know the
// pipeline, and where every front end takes its switches from (--no-NAME on the command line and in
// --config, no_NAME=True in Python, the ROS node's parameters), --parity (every rule off) and the
// ablation benchmark (each rule off in turn). Each rule is its own file with its own test; adding one
// means its file, its test and a row here.
//
//   clean           map/free_space_cleaning.h     ray fans, slivers and specks out of the free space
//   simplify        map/simplify.h                stair steps of the outline
//   doors           segmentation/door_cuts.h      cuts across narrow passages
//   wall-openings   segmentation/wall_openings.h  thin walls continued to the next obstacle
//   island-cuts     segmentation/island_cuts.h    cuts onto free-standing pieces of wall
//   wall-lines      segmentation/wall_lines.h     straight walls continued across wide openings
//   (decomposition) decomposition/decompose.h     DuDe at oversegment x tau (--trivial: none)
//   merge           segmentation/room_merging.h   pieces joined into rooms, then rooms too small or thin
//                                                 to be rooms folded
//   learned-merge   segmentation/merge_model.h    by the learned model (off: by the hand rules below)
//   furniture-rule  segmentation/room_merging.h   (hand rules) cuts ending on furniture separate no rooms
//   width-steps     segmentation/room_merging.h   (hand rules) a room opening onto a much wider space
//   open-rooms      segmentation/open_rooms.h     rooms bounded mostly by never-seen space join their neighbour
//                                                 (with none beside them, outside the building: left out)
#include <functional>
#include <string>
#include <vector>

#include "topocut/core/cut_rule.h"
#include "topocut/core/geometry.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

enum class RuleStage {
  kClean,  // on the free-space image, before polygons
  kCut,    // on each component's polygon, before the decomposition
  kMerge,  // on the pieces, after the decomposition
};

struct SegmentationRule {
  std::string name;  // switch --no-NAME
  RuleStage stage = RuleStage::kCut;
  std::string help;  // what switching it off does, one line
  std::function<bool(const SegmentOptions&)> is_on;
  std::function<void(SegmentOptions&)> turn_off;
  // Cut rules: the rule's cuts of a component's polygon (grid coordinates), clear of the earlier
  // rules' cuts; and whether a failure of the decomposition after it retries without it (a cut that
  // grazes a corner may leave a degenerate part).
  CutRule cut_rule = CutRule::kDecomposition;
  std::function<std::vector<Segment2>(const PolygonWithHoles&, double resolution, const DoorOptions&,
                                      const std::vector<Segment2>& earlier)>
      find_cuts;
  bool may_fail = false;
};

// Every rule, in the order segment() applies them.
const std::vector<SegmentationRule>& segmentation_rules();

// The rule named name, or nullptr.
const SegmentationRule* find_segmentation_rule(const std::string& name);

// The names of the rules that are off in options although on by default, in list order.
std::vector<std::string> rules_off(const SegmentOptions& options);

}  // namespace topocut
