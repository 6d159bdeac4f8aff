#pragma once
// The pipeline of segment(), every stage a row, in the order the stages run: what a reader reads to
// know the pipeline, what runs it, and where every front end takes its switches from (--no-NAME on
// the command line and in --config, no_NAME=True in Python, the ROS node's parameters), --parity
// (every switch off) and the ablation benchmark (each switch off in turn). Both schedules run the
// list: segment() and the incremental update (segmentation_input() over a window, then
// segment_input()). A row runs where its stage says (RuleStage) with the one function its stage
// takes; adding a stage or a rule means its file, its test and a row here
// (tests/segmentation/merging/merge_rule_row_test.cpp adds a merge criterion that way,
// tests/segmentation/pipeline_rows_test.cpp checks that both schedules run the rows in order).
//
// `topocut rules` prints the list, one row a line in order: its name, its stage, its switch and what
// it does (rule_listing(); Python's topocut.segmentation_rules()). Each row names the function it runs;
// the function's file is where its stage keeps such files (src/map/ for clean and simplify,
// src/segmentation/cuts/, src/decomposition/, src/segmentation/merging/, src/segmentation/rooms/),
// its public header flat in include/topocut/ (segmentation/door_cuts.h, ...). The rows without a
// switch are on with their stage (their numbers are options of their stage); door-cuts, door-ratio
// and fold follow merge.
#include <functional>
#include <string>
#include <vector>

#include "topocut/core/cut_rule.h"
#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/map/building_inside.h"
#include "topocut/map/free_space_cleaning.h"
#include "topocut/map/rasterize.h"
#include "topocut/segmentation/merge_criteria.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

// Where a row runs, in pipeline order; each stage calls one function of its rows.
enum class RuleStage {
  kClean,      // clean: on the free-space image, before polygons
  kOutline,    // outline: on each component's polygon, the outline the cuts and decomposition start from
               // (each outline row on the one before's)
  kCut,        // find_cuts: on each component's polygon, before the decomposition
  kDecompose,  // decompose: on each part of the polygon the cuts leave
  kMerge,      // judge, on_component: on each component's pieces: the merges, their criteria, the folding
  kRooms,      // on_rooms: on all rooms of the map, after kMerge
  kLabel,      // label: the rooms' labels and passages
  kLeaveOut,   // leave_out: labelled rooms no person draws taken out (their cells no room's)
  kDescribe,   // describe: on the labelled rooms
};

struct ComponentMerge;  // one component's rooms as they merge (internal: src/segmentation/merging/room_graph.h)

struct SegmentationRule {
  std::string name;  // switch --no-NAME (rules with a turn_off)
  RuleStage stage = RuleStage::kCut;
  std::string does;  // what the row does, one line: the rule list's description of it
  std::string help;  // rows with a switch: what switching it off does, one line (the switch's help)
  std::function<bool(const SegmentOptions&)> is_on;
  std::function<void(SegmentOptions&)> turn_off;  // empty: no switch, the rule is on with the stage
  // kClean: the free space (255 = free) cleaned, given the grid's cells as the sensor saw them
  // (resolution: metres per cell); each cleaning row cleans the floor the one before left.
  std::function<CleanedFreeSpace(const cv::Mat& free, const cv::Mat& cells, double resolution, const SegmentOptions&)> clean;
  // kOutline: the outline to decompose first; the exact one is the fallback if it fails.
  std::function<PolygonWithHoles(const PolygonWithHoles& exact, const SegmentOptions&)> outline;
  // kCut: the rule's cuts of a component's polygon (grid coordinates), clear of the earlier rules'
  // cuts; and whether a failure of the decomposition after it retries without it (a cut that grazes a
  // corner may leave a degenerate part). index: the polygon's edges, which every cut row searches.
  CutRule cut_rule = CutRule::kDecomposition;
  std::function<std::vector<Segment2>(const PolygonWithHoles&, double resolution, const DoorOptions&,
                                      const std::vector<Segment2>& earlier, const CutSearchIndex* index)>
      find_cuts;
  bool may_fail = false;
  // kDecompose: the pieces of one part (grid coordinates, resolution metres per cell) and their cuts.
  std::function<Decomposition(const PolygonWithHoles& part, double resolution, const SegmentOptions&)> decompose;
  // kMerge: the verdict on one candidate merge (merge_criteria.h).
  MergeCriterion judge;
  // kMerge: a step on one component's rooms (the merges the criteria decide, the folding).
  std::function<void(ComponentMerge&)> on_component;
  // kRooms: a step on all rooms, in the grid the rooms were cut from; spans: the rooms' polygon_spans()
  // at the grid's size, which the kRooms and kLabel rows share while the rooms stay the same.
  std::function<PieceSet(const PieceSet& rooms, const OccupancyGrid& grid, const SegmentOptions&,
                         const std::vector<CellSpan>& spans)>
      on_rooms;
  // kLabel: the segmentation of the grid's free cells into the rooms (spans: theirs, as for kRooms).
  std::function<Segmentation(const OccupancyGrid& grid, const PieceSet& rooms, const SegmentOptions&,
                             const std::vector<CellSpan>& spans)>
      label;
  // kLeaveOut: the labelled rooms of grid without those no person draws; floor: the free space the
  // rooms were made of (CV_8UC1, the grid's size), so that the rays the labelling gave a room are seen;
  // inside: grid's building inside, computed by the first row that reads it, for the rows after it.
  std::function<void(Segmentation&, const OccupancyGrid& grid, const cv::Mat& floor, const SegmentOptions&, BuildingInside& inside)>
      leave_out;
  // kDescribe: what is measured on the labelled rooms; whole_map: only where every room is labelled
  // whole (a window labelling part of its cells leaves it to its caller).
  std::function<void(Segmentation&, const SegmentOptions&)> describe;
  bool whole_map = false;
};

// Every row, in the order segment() runs them.
const std::vector<SegmentationRule>& segmentation_rules();

// The stage's name as the rule list shows it: "clean", "outline", "cut", "decompose", "merge", "rooms",
// "label", "leave-out" or "describe".
std::string to_string(RuleStage stage);

// One row as the rule list shows it.
struct RuleListing {
  std::string name, stage;
  std::string switch_name;  // "no-NAME"; empty: no switch, on with its stage
  std::string does;
};

// rules as a reader sees them, in their order.
std::vector<RuleListing> rule_listing(const std::vector<SegmentationRule>& rules);

// rule_listing(rules) as text, one line a row in columns: name, stage, --no-NAME or "no switch", what it does.
std::string rule_list_text(const std::vector<SegmentationRule>& rules);

// The rule named name, or nullptr.
const SegmentationRule* find_segmentation_rule(const std::string& name);

// The names of the rules with a switch that are off in options although on by default, in list order.
std::vector<std::string> rules_off(const SegmentOptions& options);

// options with every leave-out row switched off: for a whole-map update of a growing map that windowed
// updates go on updating. A windowed update gives every free cell of its region a room, so what such a
// row leaves out would come back as a room at the next one and go again at the next whole-map update,
// each time under a new id; the map at rest is segmented with them.
SegmentOptions without_leave_out(const SegmentOptions& options);

// The names of the rows run (their stage's function called) while it lives, in the order they ran,
// over every thread; merge criteria are asked inside merge and not listed. For tests that check a
// schedule runs the list; one at a time.
class RuleTrace {
 public:
  RuleTrace();
  RuleTrace(const RuleTrace&) = delete;
  RuleTrace& operator=(const RuleTrace&) = delete;
  ~RuleTrace();
  std::vector<std::string> rows() const;
};

// Whether row is one of stage's rows and is on in options.
bool row_is_on(const SegmentationRule& row, RuleStage stage, const SegmentOptions& options);

// Records in the living RuleTrace, if any, that row ran; what the schedules call before each row.
void note_rule_run(const SegmentationRule& row);

}  // namespace topocut
