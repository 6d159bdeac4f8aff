#include "topocut/segmentation/segmentation_rules.h"

#include "segmentation/merging/room_graph.h"
#include "topocut/segmentation/door_cuts.h"
#include "topocut/segmentation/island_cuts.h"
#include "topocut/segmentation/open_rooms.h"
#include "topocut/segmentation/wall_lines.h"
#include "topocut/segmentation/wall_openings.h"

namespace topocut {

namespace {

SegmentationRule stage_rule(std::string name, RuleStage stage, std::string help, std::function<bool(const SegmentOptions&)> is_on,
                            std::function<void(SegmentOptions&)> turn_off) {
  SegmentationRule rule;
  rule.name = std::move(name);
  rule.stage = stage;
  rule.help = std::move(help);
  rule.is_on = std::move(is_on);
  rule.turn_off = std::move(turn_off);
  return rule;
}

// A rule without a switch, on whenever is_on says (its stage's switch).
SegmentationRule unswitched_rule(std::string name, RuleStage stage, std::string help, std::function<bool(const SegmentOptions&)> is_on) {
  return stage_rule(std::move(name), stage, std::move(help), std::move(is_on), nullptr);
}

SegmentationRule criterion(SegmentationRule rule, MergeCriterion judge) {
  rule.judge = std::move(judge);
  return rule;
}

SegmentationRule component_step(SegmentationRule rule, std::function<void(ComponentMerge&)> step) {
  rule.on_component = std::move(step);
  return rule;
}

SegmentationRule rooms_step(SegmentationRule rule, decltype(SegmentationRule::on_rooms) step) {
  rule.on_rooms = std::move(step);
  return rule;
}

bool merging(const SegmentOptions& o) { return o.merge.enabled; }

SegmentationRule cut_rule(SegmentationRule rule, CutRule kind, decltype(SegmentationRule::find_cuts) find, bool may_fail) {
  rule.cut_rule = kind;
  rule.find_cuts = std::move(find);
  rule.may_fail = may_fail;
  return rule;
}

std::vector<SegmentationRule> make_rules() {
  return {
      stage_rule("clean", RuleStage::kClean,
                 "decompose the free space as it is: keep laser-ray fans, slivers, free and obstacle specks",
                 [](const SegmentOptions& o) { return o.clean; }, [](SegmentOptions& o) { o.clean = false; }),
      stage_rule("simplify", RuleStage::kCut, "decompose the exact pixel-edge polygons (slower)",
                 [](const SegmentOptions& o) { return o.simplify > 0.0; }, [](SegmentOptions& o) { o.simplify = 0.0; }),
      cut_rule(stage_rule("doors", RuleStage::kCut, "no cuts across narrow passages (doors) before the decomposition",
                          [](const SegmentOptions& o) { return o.doors.passages; }, [](SegmentOptions& o) { o.doors.passages = false; }),
               CutRule::kDoor,
               [](const PolygonWithHoles& p, double res, const DoorOptions& d, const std::vector<Segment2>&) {
                 return find_passage_cuts(p, res, d);
               },
               false),
      cut_rule(stage_rule("wall-openings", RuleStage::kCut,
                          "no cuts where a thin wall stops short of the next obstacle (a room front open to a corridor)",
                          [](const SegmentOptions& o) { return o.doors.extend_walls; },
                          [](SegmentOptions& o) { o.doors.extend_walls = false; }),
               CutRule::kWallOpening, find_wall_openings, false),
      cut_rule(stage_rule("island-cuts", RuleStage::kCut,
                          "no door-like cuts from the outline to a free-standing piece of wall (longer than 2.5 m, at most "
                          "0.25 m thick: a partition whose joint the sensor missed), which separate rooms only together",
                          [](const SegmentOptions& o) { return o.doors.island_cuts; },
                          [](SegmentOptions& o) { o.doors.island_cuts = false; }),
               CutRule::kIslandCut, find_island_cuts, true),
      cut_rule(stage_rule("wall-lines", RuleStage::kCut,
                          "no cuts where a straight wall continued across free space meets the next wall (room boundaries "
                          "across wide openings)",
                          [](const SegmentOptions& o) { return o.doors.wall_lines; },
                          [](SegmentOptions& o) { o.doors.wall_lines = false; }),
               CutRule::kWallLine, find_wall_line_cuts, true),
      component_step(stage_rule("merge", RuleStage::kMerge, "keep DuDe's pieces as rooms instead of merging them", merging,
                                [](SegmentOptions& o) { o.merge.enabled = false; }),
                     merge_by_criteria),
      criterion(stage_rule("corridor-rule", RuleStage::kMerge,
                           "(learned merging) no forced merge where a corridor continues across a cut (both sides strips of one "
                           "thickness, at most 2.5 m, each 3 times as long as thick): the model decides alone",
                           [](const SegmentOptions& o) { return o.merge.corridor_rule; },
                           [](SegmentOptions& o) { o.merge.corridor_rule = false; }),
                corridor_continues),
      criterion(stage_rule("learned-merge", RuleStage::kMerge,
                           "merge by the hand rules (a cut spanning the narrower room, width steps) instead of the learned model",
                           [](const SegmentOptions& o) { return o.merge.learned; }, [](SegmentOptions& o) { o.merge.learned = false; }),
                learned_merge),
      criterion(unswitched_rule("door-cuts", RuleStage::kMerge, "(hand rules) a door rule's cut separates rooms", merging),
                door_cuts_stay),
      criterion(stage_rule("furniture-rule", RuleStage::kMerge,
                           "(hand rules) cuts that end on furniture-sized obstacles (at most 2.5 m a side) may separate rooms",
                           [](const SegmentOptions& o) { return o.merge.furniture_size > 0.0; },
                           [](SegmentOptions& o) { o.merge.furniture_size = 0.0; }),
                furniture_rule),
      criterion(stage_rule("width-steps", RuleStage::kMerge,
                           "(hand rules) merge a room into a much wider space it opens onto across its whole width",
                           [](const SegmentOptions& o) { return o.merge.step_ratio > 0.0; },
                           [](SegmentOptions& o) { o.merge.step_ratio = 0.0; }),
                width_step),
      criterion(unswitched_rule("door-ratio", RuleStage::kMerge,
                                "(hand rules) a cut at least door_like.ratio times the narrower room's width merges", merging),
                door_ratio_rule),
      component_step(unswitched_rule("fold", RuleStage::kMerge, "rooms too small or too thin to be rooms join a neighbour", merging),
                     fold_small_rooms),
      rooms_step(stage_rule("open-rooms", RuleStage::kRooms,
                            "keep rooms whose outline runs mostly into never-seen space (ray fans, scraps beyond the walls) as rooms",
                            [](const SegmentOptions& o) { return o.open_rooms.enabled; },
                            [](SegmentOptions& o) { o.open_rooms.enabled = false; }),
                 [](const PieceSet& rooms, const OccupancyGrid& grid, const SegmentOptions& o) {
                   return join_open_rooms(rooms, grid, o.open_rooms);
                 }),
  };
}

}  // namespace

const std::vector<SegmentationRule>& segmentation_rules() {
  static const std::vector<SegmentationRule> rules = make_rules();
  return rules;
}

const SegmentationRule* find_segmentation_rule(const std::string& name) {
  for (const SegmentationRule& rule : segmentation_rules())
    if (rule.name == name) return &rule;
  return nullptr;
}

std::vector<std::string> rules_off(const SegmentOptions& options) {
  const SegmentOptions defaults;
  std::vector<std::string> off;
  for (const SegmentationRule& rule : segmentation_rules())
    if (rule.turn_off && rule.is_on(defaults) && !rule.is_on(options)) off.push_back(rule.name);
  return off;
}

}  // namespace topocut
