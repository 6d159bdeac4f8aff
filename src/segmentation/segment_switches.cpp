#include "topocut/segmentation/segment_switches.h"

#include <algorithm>

#include "topocut/core/error.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace topocut {

void apply(const SegmentSwitches& s, SegmentOptions& options) {
  if (s.parity && (!s.rules_off.empty() || options.labels.cover_absorbed_obstacles))
    throw Error("--parity already switches every improvement off; give it alone");
  if (s.parity) {
    const SegmentOptions reference = parity_segment_options(options.concavity);
    for (const SegmentationRule& rule : segmentation_rules())
      if (rule.turn_off) rule.turn_off(options);
    options.labels = reference.labels;
    if (!s.min_room_area_given) options.contours.min_component_area = reference.contours.min_component_area;
  }
  for (const std::string& name : s.rules_off) {
    const SegmentationRule* rule = find_segmentation_rule(name);
    if (rule == nullptr || !rule->turn_off) throw Error("no segmentation rule with a switch is called '" + name + "'");
    rule->turn_off(options);
  }
  options.decompose = !s.trivial;
  if (s.merge_model_given && (s.trivial || !options.merge.enabled || !options.merge.learned))
    throw Error("a merge model is given, but learned merging is off (--no-learned-merge, --no-merge, --parity or "
                "--trivial): give one or the other");
}

namespace {

using Row = OptionRow<SegmentSettings>;

// A row for a number field; field is a generic lambda returning a reference to it in a (const) SegmentSettings.
template <typename Field>
Row number(const char* name, const char* value_name, OptionRange range, Field field, const char* help) {
  return {name, value_name, help, range, [field](const SegmentSettings& s) { return field(s); },
          [field](SegmentSettings& s, double v) { field(s) = v; }};
}

// A row for a switch: a bool of SegmentSwitches or SegmentOptions.
template <typename Field>
Row on_off(const char* name, Field field, const char* help) {
  return {name, "", help, OptionRange::kSwitch,
          [field](const SegmentSettings& s) { return field(s) ? 1.0 : 0.0; },
          [field](SegmentSettings& s, double on) { field(s) = on != 0.0; }};
}

// min-room-area: a value given wins over --parity's reference value.
Row given(Row row) {
  row.set = [set = row.set](SegmentSettings& s, double v) {
    set(s, v);
    s.switches.min_room_area_given = true;
  };
  return row;
}

// rows with a --no-NAME switch for every rule of the pipeline after the first three (concavity,
// trivial, parity), in the pipeline's order.
std::vector<Row> with_rule_switches(std::vector<Row> rows) {
  std::vector<Row> switches;
  for (const SegmentationRule& rule : segmentation_rules()) {
    if (!rule.turn_off) continue;
    const std::string name = rule.name;
    switches.push_back({"no-" + name, "", rule.help, OptionRange::kSwitch,
                        [name](const SegmentSettings& s) {
                          const auto& off = s.switches.rules_off;
                          return std::find(off.begin(), off.end(), name) != off.end() ? 1.0 : 0.0;
                        },
                        [name](SegmentSettings& s, double on) {
                          auto& off = s.switches.rules_off;
                          std::erase(off, name);
                          if (on != 0.0) off.push_back(name);
                        }});
  }
  rows.insert(rows.begin() + 3, switches.begin(), switches.end());
  return rows;
}

}  // namespace

const std::vector<OptionRow<SegmentSettings>>& segment_option_rows() {
  static const std::vector<Row> rows = with_rule_switches({
      number("concavity", "M", OptionRange::kLength, [](auto& s) -> auto& { return s.options.concavity; },
             "maximum concavity tau in metres: larger values give fewer, less convex rooms"),
      on_off("trivial", [](auto& s) -> auto& { return s.switches.trivial; },
             "no decomposition: one room per free-space component (baseline)"),
      on_off("parity", [](auto& s) -> auto& { return s.switches.parity; },
             "the reference behaviour: DuDe's pieces are the rooms (no cleaning, door cuts, merging or simplification); "
             "alone or with numbers and --trivial, not with a switch it already sets"),
      number("door-width", "M", OptionRange::kLength, [](auto& s) -> auto& { return s.options.doors.max_width; },
             "widest passage in metres taken for a door (cut before the decomposition)"),
      number("wall-line-wall", "M", OptionRange::kLength, [](auto& s) -> auto& { return s.options.doors.wall_line_wall; },
             "shortest straight wall (metres) whose continuation is a wall line"),
      number("max-wall-line", "M", OptionRange::kLength, [](auto& s) -> auto& { return s.options.doors.max_wall_line; },
             "longest stretch of free space (metres) a wall line crosses"),
      number("wall-line-spacing", "M", OptionRange::kLengthOrZero, [](auto& s) -> auto& { return s.options.doors.wall_line_spacing; },
             "of two wall lines closer than this (metres) along their whole length only the shorter is kept"),
      number("wall-line-side", "M", OptionRange::kLengthOrZero, [](auto& s) -> auto& { return s.options.doors.wall_line_side; },
             "a wall line is at least this long (metres) and leaves both sides this wide"),
      number("fold-area", "M2", OptionRange::kArea, [](auto& s) -> auto& { return s.options.merge.min_room_area; },
             "rooms smaller than this (m²) are folded into the neighbour they share the longest cut with"),
      on_off("cover-obstacles", [](auto& s) -> auto& { return s.options.labels.cover_absorbed_obstacles; },
             "label the obstacles a room absorbed (furniture) with the room, not with 0"),
      number("robot-radius", "M", OptionRange::kLengthOrZero, [](auto& s) -> auto& { return s.options.binarize.robot_radius; },
             "inflate obstacles by this radius in metres before decomposing (0: raw free space)"),
      number("opening", "M", OptionRange::kLengthOrZero, [](auto& s) -> auto& { return s.options.binarize.opening_size; },
             "open the free space with a square of this side in metres (drops single-ray spurs; 0: off)"),
      given(number("min-room-area", "M2", OptionRange::kArea,
                   [](auto& s) -> auto& { return s.options.contours.min_component_area; },
                   "free-space components smaller than this (m²) are not rooms; their cells join the nearest room")),
      number("min-hole-area", "M2", OptionRange::kArea, [](auto& s) -> auto& { return s.options.contours.min_hole_area; },
             "obstacles inside free space smaller than this (m²) are ignored by the decomposition"),
      number("oversegment", "F", OptionRange::kFraction, [](auto& s) -> auto& { return s.options.oversegment; },
             "with merging, DuDe cuts at F x tau, 0 < F <= 1 (merging then removes the cuts that are not door-like)"),
  });
  return rows;
}

SegmentOptions to_segment_options(const SegmentSettings& settings) {
  SegmentOptions options = settings.options;
  apply(settings.switches, options);
  validate(options);
  return options;
}

}  // namespace topocut
