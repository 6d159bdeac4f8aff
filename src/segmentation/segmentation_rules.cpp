#include "topocut/segmentation/segmentation_rules.h"

#include <algorithm>
#include <atomic>
#include <mutex>

#include "segmentation/merging/room_graph.h"
#include "segmentation/passage_kind.h"
#include "topocut/segmentation/door_cuts.h"
#include "topocut/segmentation/island_cuts.h"
#include "topocut/segmentation/open_rooms.h"
#include "topocut/segmentation/outside_parts.h"
#include "topocut/segmentation/room_kinds.h"
#include "topocut/segmentation/rooms_from_pieces.h"
#include "topocut/segmentation/wall_lines.h"
#include "topocut/segmentation/wall_openings.h"

namespace topocut {

namespace {

// A row: what it does, and with a turn_off its switch's help (what switching it off does).
SegmentationRule stage_rule(std::string name, RuleStage stage, std::string does, std::string help,
                            std::function<bool(const SegmentOptions&)> is_on, std::function<void(SegmentOptions&)> turn_off) {
  SegmentationRule rule;
  rule.name = std::move(name);
  rule.stage = stage;
  rule.does = std::move(does);
  rule.help = std::move(help);
  rule.is_on = std::move(is_on);
  rule.turn_off = std::move(turn_off);
  return rule;
}

// A rule without a switch, on whenever is_on says (its stage's switch).
SegmentationRule unswitched_rule(std::string name, RuleStage stage, std::string does, std::function<bool(const SegmentOptions&)> is_on) {
  return stage_rule(std::move(name), stage, std::move(does), "", std::move(is_on), nullptr);
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
bool always(const SegmentOptions&) { return true; }

SegmentationRule cut_rule(SegmentationRule rule, CutRule kind, decltype(SegmentationRule::find_cuts) find, bool may_fail) {
  rule.cut_rule = kind;
  rule.find_cuts = std::move(find);
  rule.may_fail = may_fail;
  return rule;
}

std::vector<SegmentationRule> make_rules() {
  SegmentationRule clean = stage_rule("clean", RuleStage::kClean, "ray fans, slivers and specks out of the free space (real maps)",
                                      "decompose the free space as it is: keep laser-ray fans, slivers, free and obstacle specks",
                                      [](const SegmentOptions& o) { return o.clean; }, [](SegmentOptions& o) { o.clean = false; });
  clean.clean = [](const cv::Mat& free, const cv::Mat& cells, double resolution, const SegmentOptions& o) {
    return clean_free_space(free, cells, resolution, o.cleaning);
  };
  SegmentationRule simplify = stage_rule("simplify", RuleStage::kOutline, "stair steps out of each component's outline",
                                         "decompose the exact pixel-edge polygons (slower)",
                                         [](const SegmentOptions& o) { return o.simplify > 0.0; },
                                         [](SegmentOptions& o) { o.simplify = 0.0; });
  simplify.outline = [](const PolygonWithHoles& exact, const SegmentOptions& o) { return simplified_where_valid(exact, o.simplify); };
  SegmentationRule decomposition = unswitched_rule(
      "decomposition", RuleStage::kDecompose,
      "DuDe on each part the cuts leave, at tau = --concavity (times --oversegment with merging); --trivial: neither the cuts "
      "nor this, each component is one piece",
      [](const SegmentOptions& o) { return o.decompose; });
  decomposition.decompose = [](const PolygonWithHoles& part, double resolution, const SegmentOptions& o) {
    DecompositionOptions d = o.decomposition;
    d.tau = o.concavity * (o.merge.enabled ? o.oversegment : 1.0) / resolution;  // the polygons are in cells
    return topocut::decompose(part, d);
  };
  SegmentationRule labelling = unswitched_rule(
      "labelling", RuleStage::kLabel, "every free cell gets its room's label; the rooms' outlines and the passages between them", always);
  labelling.label = [](const OccupancyGrid& grid, const PieceSet& rooms, const SegmentOptions& o, const std::vector<CellSpan>& spans) {
    return rooms_from_pieces(grid, rooms, spans, o.labels);
  };
  SegmentationRule fans = stage_rule(
      "open-fans", RuleStage::kLeaveOut,
      "labelled rooms still bounded mostly by never-seen space that hold the rays of a fan (at least --open-fan-ray-share "
      "of their cells beyond their polygon; a drawn plan's rooms hold almost none) and lie mostly outside the building "
      "are no rooms: their cells get no room",
      "keep open rooms that hold a fan's rays (a fan seen through a window or an open door) as rooms",
      [](const SegmentOptions& o) { return o.open_rooms.enabled && o.open_rooms.fan_ray_share > 0.0; },
      [](SegmentOptions& o) { o.open_rooms.fan_ray_share = 0.0; });
  fans.leave_out = [](Segmentation& s, const OccupancyGrid& grid, const cv::Mat& floor, const SegmentOptions& o, BuildingInside& inside) {
    leave_out_fans(s, grid, floor, o.open_rooms, &inside);
  };
  fans.whole_map = true;  // the windowed update gives every free cell of its region a room
  SegmentationRule outside = stage_rule(
      "outside-parts", RuleStage::kLeaveOut,
      "the cells a room holding a fan's rays has outside the building get no room when more than --open-fan-inside-share "
      "of its floor is inside: a fan seen through its window, merged with it; its polygon loses them",
      "keep the fans merged with walled rooms in those rooms",
      [](const SegmentOptions& o) { return o.open_rooms.enabled && o.open_rooms.fan_ray_share > 0.0 && o.open_rooms.cut_outside_parts; },
      [](SegmentOptions& o) { o.open_rooms.cut_outside_parts = false; });
  outside.leave_out = [](Segmentation& s, const OccupancyGrid& grid, const cv::Mat& floor, const SegmentOptions& o, BuildingInside& inside) {
    // The rays it reads are the cells the cleaning removed: without it (--no-clean: the free space
    // decomposed as it is) the cells beyond a room's polygon are specks, and a fan stays in its room.
    if (o.clean) leave_out_outside_parts(s, grid, floor, o.open_rooms, &inside);
  };
  outside.whole_map = true;  // as the fans
  SegmentationRule door_flags = unswitched_rule("door-flags", RuleStage::kDescribe, "a passage at most --door-width wide is a door", always);
  door_flags.describe = [](Segmentation& s, const SegmentOptions& o) {
    for (Passage& passage : s.passages) passage.door = is_door(passage, o.doors);
  };
  SegmentationRule room_kinds = unswitched_rule(
      "room-kinds", RuleStage::kDescribe,
      "each room a corridor or a room (whole map only: the incremental update measures the rooms it changed itself)", always);
  room_kinds.describe = [](Segmentation& s, const SegmentOptions& o) { assign_room_kinds(s, o.kinds); };
  room_kinds.whole_map = true;  // a room's kind counts the rooms it opens onto
  return {
      std::move(clean),
      std::move(simplify),
      cut_rule(stage_rule("doors", RuleStage::kCut, "cuts across narrow passages (doors)",
                          "no cuts across narrow passages (doors) before the decomposition",
                          [](const SegmentOptions& o) { return o.doors.passages; }, [](SegmentOptions& o) { o.doors.passages = false; }),
               CutRule::kDoor,
               [](const PolygonWithHoles& p, double res, const DoorOptions& d, const std::vector<Segment2>&, const CutSearchIndex* index) {
                 return find_passage_cuts(p, res, d, index);
               },
               false),
      cut_rule(stage_rule("wall-openings", RuleStage::kCut, "thin walls that stop short continued to the next obstacle",
                          "no cuts where a thin wall stops short of the next obstacle (a room front open to a corridor)",
                          [](const SegmentOptions& o) { return o.doors.extend_walls; },
                          [](SegmentOptions& o) { o.doors.extend_walls = false; }),
               CutRule::kWallOpening, find_wall_openings, false),
      cut_rule(stage_rule("island-cuts", RuleStage::kCut, "cuts from the outline onto free-standing pieces of wall",
                          "no door-like cuts from the outline to a free-standing piece of wall (longer than 2.5 m, at most "
                          "0.25 m thick: a partition whose joint the sensor missed), which separate rooms only together",
                          [](const SegmentOptions& o) { return o.doors.island_cuts; },
                          [](SegmentOptions& o) { o.doors.island_cuts = false; }),
               CutRule::kIslandCut, find_island_cuts, true),
      cut_rule(stage_rule("wall-lines", RuleStage::kCut, "straight walls continued across wide openings to the next wall",
                          "no cuts where a straight wall continued across free space meets the next wall (room boundaries "
                          "across wide openings)",
                          [](const SegmentOptions& o) { return o.doors.wall_lines; },
                          [](SegmentOptions& o) { o.doors.wall_lines = false; }),
               CutRule::kWallLine, find_wall_line_cuts, true),
      std::move(decomposition),
      component_step(stage_rule("merge", RuleStage::kMerge,
                                "on each component: pieces joined into rooms across the cuts the criteria below merge (asked "
                                "in order, the first that does not abstain decides)",
                                "keep DuDe's pieces as rooms instead of merging them", merging,
                                [](SegmentOptions& o) { o.merge.enabled = false; }),
                     merge_by_criteria),
      criterion(stage_rule("corridor-rule", RuleStage::kMerge,
                           "criterion (learned merging): a corridor continued across a cut is one room whatever the model says",
                           "(learned merging) no forced merge where a corridor continues across a cut (both sides strips of one "
                           "thickness, at most 2.5 m, each 3 times as long as thick): the model decides alone",
                           [](const SegmentOptions& o) { return o.merge.corridor_rule; },
                           [](SegmentOptions& o) { o.merge.corridor_rule = false; }),
                corridor_continues),
      criterion(stage_rule("learned-merge", RuleStage::kMerge,
                           "criterion: merge where the model finds one room (merge_model.h); off: the hand rules below",
                           "merge by the hand rules (a cut spanning the narrower room, width steps) instead of the learned model",
                           [](const SegmentOptions& o) { return o.merge.learned; }, [](SegmentOptions& o) { o.merge.learned = false; }),
                learned_merge),
      criterion(unswitched_rule("door-cuts", RuleStage::kMerge,
                                "criterion (hand rules): a cut of the door rule or a wall opening stays", merging),
                door_cuts_stay),
      criterion(stage_rule("furniture-rule", RuleStage::kMerge,
                           "criterion (hand rules): cuts ending on furniture separate no rooms; for the model, no obstacle "
                           "is furniture",
                           "(hand rules) cuts that end on furniture-sized obstacles (at most 2.5 m a side) may separate rooms",
                           [](const SegmentOptions& o) { return o.merge.furniture_size > 0.0; },
                           [](SegmentOptions& o) { o.merge.furniture_size = 0.0; }),
                furniture_rule),
      criterion(stage_rule("width-steps", RuleStage::kMerge,
                           "criterion (hand rules): a room opening onto a much wider space stays apart",
                           "(hand rules) merge a room into a much wider space it opens onto across its whole width",
                           [](const SegmentOptions& o) { return o.merge.step_ratio > 0.0; },
                           [](SegmentOptions& o) { o.merge.step_ratio = 0.0; }),
                width_step),
      criterion(unswitched_rule("door-ratio", RuleStage::kMerge,
                                "criterion (hand rules): a cut at least door_like.ratio times the narrower room's width "
                                "merges, the clearest first",
                                merging),
                door_ratio_rule),
      component_step(unswitched_rule("fold", RuleStage::kMerge,
                                     "on each component: rooms too small or thin to be rooms join the neighbour sharing the "
                                     "longest cut",
                                     merging),
                     fold_small_rooms),
      component_step(stage_rule("fragments", RuleStage::kMerge,
                                "on each component (learned merging): a room under fragment-area, bounded more by never-seen "
                                "cells than by walls and entered through a gap narrower than a person, joins the room beyond "
                                "the gap where the model leaned towards one room",
                                "(learned merging) keep small rooms bounded more by never-seen cells than by walls and "
                                "entered through a gap narrower than a person (scraps of floor beside a room) as rooms",
                                [](const SegmentOptions& o) { return o.merge.enabled && o.merge.fragment_area > 0.0; },
                                [](SegmentOptions& o) { o.merge.fragment_area = 0.0; }),
                     fold_fragments),
      component_step(stage_rule("bays", RuleStage::kMerge,
                                "on each component (learned merging): a room cut off a much larger one along a large share of "
                                "its outline (a bay, a wedge, a strip along a wall line) joins it where the model leaned "
                                "towards one room",
                                "(learned merging) keep rooms cut off a much larger room along a large share of their "
                                "outline (bays, wedges, strips along a wall line) as rooms",
                                [](const SegmentOptions& o) { return o.merge.enabled && o.merge.bay_share > 0.0; },
                                [](SegmentOptions& o) { o.merge.bay_share = 0.0; }),
                     fold_bays),
      rooms_step(stage_rule("open-rooms", RuleStage::kRooms,
                            "on all rooms: rooms bounded mostly by never-seen space join their neighbour; with none beside "
                            "them (outside the building) they are left out, and so are floor islands with no room beside "
                            "them that fill less than half the cells the labelling would give them (the rest rays of a fan seen "
                            "through a gap in a wall)",
                            "keep rooms whose outline runs mostly into never-seen space (ray fans, scraps beyond the walls) as rooms",
                            [](const SegmentOptions& o) { return o.open_rooms.enabled; },
                            [](SegmentOptions& o) { o.open_rooms.enabled = false; }),
                 [](const PieceSet& rooms, const OccupancyGrid& grid, const SegmentOptions& o, const std::vector<CellSpan>& spans) {
                   return join_open_rooms(rooms, grid, o.open_rooms, spans);
                 }),
      std::move(labelling),
      std::move(fans),
      std::move(outside),
      std::move(door_flags),
      std::move(room_kinds),
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

std::string to_string(RuleStage stage) {
  switch (stage) {
    case RuleStage::kClean: return "clean";
    case RuleStage::kOutline: return "outline";
    case RuleStage::kCut: return "cut";
    case RuleStage::kDecompose: return "decompose";
    case RuleStage::kMerge: return "merge";
    case RuleStage::kRooms: return "rooms";
    case RuleStage::kLabel: return "label";
    case RuleStage::kLeaveOut: return "leave-out";
    case RuleStage::kDescribe: return "describe";
  }
  return "?";
}

std::vector<RuleListing> rule_listing(const std::vector<SegmentationRule>& rules) {
  std::vector<RuleListing> listing;
  for (const SegmentationRule& rule : rules)
    listing.push_back({rule.name, to_string(rule.stage), rule.turn_off ? "no-" + rule.name : "", rule.does});
  return listing;
}

std::string rule_list_text(const std::vector<SegmentationRule>& rules) {
  const std::vector<RuleListing> listing = rule_listing(rules);
  std::vector<std::string> switches;
  std::size_t name_width = 0, stage_width = 0, switch_width = 0;
  for (const RuleListing& row : listing) {
    switches.push_back(row.switch_name.empty() ? "no switch" : "--" + row.switch_name);
    name_width = std::max(name_width, row.name.size());
    stage_width = std::max(stage_width, row.stage.size());
    switch_width = std::max(switch_width, switches.back().size());
  }
  const auto padded = [](const std::string& text, std::size_t width) { return text + std::string(width - text.size() + 2, ' '); };
  std::string text;
  for (std::size_t i = 0; i < listing.size(); ++i)
    text += padded(listing[i].name, name_width) + padded(listing[i].stage, stage_width) + padded(switches[i], switch_width) +
            listing[i].does + "\n";
  return text;
}

std::vector<std::string> rules_off(const SegmentOptions& options) {
  const SegmentOptions defaults;
  std::vector<std::string> off;
  for (const SegmentationRule& rule : segmentation_rules())
    if (rule.turn_off && rule.is_on(defaults) && !rule.is_on(options)) off.push_back(rule.name);
  return off;
}

SegmentOptions without_leave_out(const SegmentOptions& options) {
  SegmentOptions result = options;
  for (const SegmentationRule& rule : segmentation_rules())
    if (rule.stage == RuleStage::kLeaveOut && rule.turn_off) rule.turn_off(result);
  return result;
}

namespace {

// The living RuleTrace's rows; the lock guards them against schedules on other threads.
std::atomic<bool> tracing{false};
std::mutex trace_mutex;
std::vector<std::string> traced;

}  // namespace

RuleTrace::RuleTrace() {
  const std::lock_guard<std::mutex> lock(trace_mutex);
  traced.clear();
  tracing = true;
}

RuleTrace::~RuleTrace() { tracing = false; }

std::vector<std::string> RuleTrace::rows() const {
  const std::lock_guard<std::mutex> lock(trace_mutex);
  return traced;
}

bool row_is_on(const SegmentationRule& row, RuleStage stage, const SegmentOptions& options) {
  return row.stage == stage && row.is_on(options);
}

void note_rule_run(const SegmentationRule& row) {
  if (!tracing.load(std::memory_order_relaxed)) return;
  const std::lock_guard<std::mutex> lock(trace_mutex);
  traced.push_back(row.name);
}

}  // namespace topocut
