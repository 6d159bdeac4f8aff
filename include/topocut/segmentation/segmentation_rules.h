#pragma once
// The rules of segment(), in the order they run, in one list: what a reader reads to know the
// pipeline, what runs it (the cut rules before the decomposition; after it, the rows on each
// component's rooms with the criteria they ask, then the rows on all rooms), and where every front end
// takes its switches from (--no-NAME on the command line and in --config, no_NAME=True in Python, the
// ROS node's parameters), --parity (every rule off) and the ablation benchmark (each rule off in turn).
// Both schedules run the list: segment() and the incremental update (through segment_input()).
// Adding a rule means its file, its test and a row here (tests/segmentation/merge_rule_row_test.cpp
// adds a merge criterion that way).
//
//   clean           map/free_space_cleaning.h     ray fans, slivers and specks out of the free space
//   simplify        map/simplify.h                stair steps of the outline
//   doors           segmentation/door_cuts.h      cuts across narrow passages
//   wall-openings   segmentation/wall_openings.h  thin walls continued to the next obstacle
//   island-cuts     segmentation/island_cuts.h    cuts onto free-standing pieces of wall
//   wall-lines      segmentation/wall_lines.h     straight walls continued across wide openings
//   (decomposition) decomposition/decompose.h     DuDe at oversegment x tau (--trivial: none)
//   merge           segmentation/room_merging.h   on each component: pieces joined into rooms across the
//                                                 cuts the criteria below merge, the highest priority first
//   corridor-rule   segmentation/merge_criteria.h criterion (learned merging): a corridor going on merges
//   learned-merge   segmentation/merge_criteria.h criterion: the model's probability (off: the hand rules)
//   door-cuts       segmentation/merge_criteria.h criterion (hand rules): a door rule's cut stays
//   furniture-rule  segmentation/merge_criteria.h criterion (hand rules): cuts ending on furniture merge
//   width-steps     segmentation/merge_criteria.h criterion (hand rules): a room opening onto a much wider space
//   door-ratio      segmentation/merge_criteria.h criterion (hand rules): a cut spanning the narrower room merges
//   fold            segmentation/room_merging.h   on each component: rooms too small or thin folded
//   open-rooms      segmentation/open_rooms.h     on all rooms: rooms bounded mostly by never-seen space join
//                                                 their neighbour (with none beside them, outside the building:
//                                                 left out)
//
// door-cuts, door-ratio and fold have no switch (their numbers are options of RoomMergeOptions) and
// follow merge.
#include <functional>
#include <string>
#include <vector>

#include "topocut/core/cut_rule.h"
#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/segmentation/merge_criteria.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

enum class RuleStage {
  kClean,  // on the free-space image, before polygons
  kCut,    // on each component's polygon, before the decomposition
  kMerge,  // on each component's pieces after the decomposition: the merges, their criteria, the folding
  kRooms,  // on all rooms of the map, after kMerge
};

struct ComponentMerge;  // one component's rooms as they merge (internal: src/segmentation/room_graph.h)

struct SegmentationRule {
  std::string name;  // switch --no-NAME (rules with a turn_off)
  RuleStage stage = RuleStage::kCut;
  std::string help;  // what switching it off does, one line
  std::function<bool(const SegmentOptions&)> is_on;
  std::function<void(SegmentOptions&)> turn_off;  // empty: no switch, the rule is on with the stage
  // Cut rules: the rule's cuts of a component's polygon (grid coordinates), clear of the earlier
  // rules' cuts; and whether a failure of the decomposition after it retries without it (a cut that
  // grazes a corner may leave a degenerate part).
  CutRule cut_rule = CutRule::kDecomposition;
  std::function<std::vector<Segment2>(const PolygonWithHoles&, double resolution, const DoorOptions&,
                                      const std::vector<Segment2>& earlier)>
      find_cuts;
  bool may_fail = false;
  // Merge criteria (kMerge): the verdict on one candidate merge (merge_criteria.h).
  MergeCriterion judge;
  // Steps on one component's rooms (kMerge): the merges the criteria decide, the folding.
  std::function<void(ComponentMerge&)> on_component;
  // Steps on all rooms (kRooms), in the grid the rooms were cut from.
  std::function<PieceSet(const PieceSet& rooms, const OccupancyGrid& grid, const SegmentOptions&)> on_rooms;
};

// Every rule, in the order segment() applies them.
const std::vector<SegmentationRule>& segmentation_rules();

// The rule named name, or nullptr.
const SegmentationRule* find_segmentation_rule(const std::string& name);

// The names of the rules with a switch that are off in options although on by default, in list order.
std::vector<std::string> rules_off(const SegmentOptions& options);

}  // namespace topocut
