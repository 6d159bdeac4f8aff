#include "topocut/segmentation/segment_switches.h"

#include "topocut/core/error.h"

namespace topocut {

void apply(const SegmentSwitches& s, SegmentOptions& options) {
  if (s.parity && (s.no_doors || s.no_wall_openings || s.no_merge || s.no_simplify || options.labels.cover_absorbed_obstacles ||
                   s.no_wall_lines || s.no_island_cuts ||
                   s.no_clean || s.no_width_steps || s.no_furniture_rule))
    throw Error("--parity already switches every improvement off; give it alone");
  if (s.parity) {
    const SegmentOptions reference = parity_segment_options(options.concavity);
    options.doors = reference.doors;
    options.merge = reference.merge;
    options.simplify = reference.simplify;
    options.labels = reference.labels;
    options.clean = reference.clean;
    if (!s.min_room_area_given) options.contours.min_component_area = reference.contours.min_component_area;
  }
  if (s.no_doors) options.doors.enabled = false;
  if (s.no_wall_openings) options.doors.extend_walls = false;
  if (s.no_merge) options.merge.enabled = false;
  if (s.no_simplify) options.simplify = 0.0;
  if (s.no_clean) options.clean = false;
  options.decompose = !s.trivial;
  if (s.no_width_steps) options.merge.step_ratio = 0.0;
  if (s.no_furniture_rule) options.merge.furniture_size = 0.0;
  if (s.no_wall_lines) options.doors.wall_lines = false;
  if (s.no_island_cuts) options.doors.island_cuts = false;
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

}  // namespace

const std::vector<OptionRow<SegmentSettings>>& segment_option_rows() {
  static const std::vector<Row> rows = {
      number("concavity", "M", OptionRange::kLength, [](auto& s) -> auto& { return s.options.concavity; },
             "maximum concavity tau in metres: larger values give fewer, less convex rooms"),
      on_off("trivial", [](auto& s) -> auto& { return s.switches.trivial; },
             "no decomposition: one room per free-space component (baseline)"),
      on_off("parity", [](auto& s) -> auto& { return s.switches.parity; },
             "the reference behaviour: DuDe's pieces are the rooms (no cleaning, door cuts, merging or simplification); "
             "alone or with numbers and --trivial, not with a switch it already sets"),
      number("door-width", "M", OptionRange::kLength, [](auto& s) -> auto& { return s.options.doors.max_width; },
             "widest passage in metres taken for a door (cut before the decomposition)"),
      on_off("no-doors", [](auto& s) -> auto& { return s.switches.no_doors; }, "no door cuts before the decomposition"),
      on_off("no-wall-openings", [](auto& s) -> auto& { return s.switches.no_wall_openings; },
             "door cuts only at narrow passages, not where a thin wall stops short of the next obstacle"),
      on_off("no-wall-lines", [](auto& s) -> auto& { return s.switches.no_wall_lines; },
             "no cuts where a straight wall (2.5 m or more) continued across at most 5 m of free space meets the next "
             "wall (room boundaries across wide openings, candidates that merging may remove)"),
      number("wall-line-wall", "M", OptionRange::kLength, [](auto& s) -> auto& { return s.options.doors.wall_line_wall; },
             "shortest straight wall (metres) whose continuation is a wall line"),
      number("max-wall-line", "M", OptionRange::kLength, [](auto& s) -> auto& { return s.options.doors.max_wall_line; },
             "longest stretch of free space (metres) a wall line crosses"),
      number("wall-line-spacing", "M", OptionRange::kLengthOrZero, [](auto& s) -> auto& { return s.options.doors.wall_line_spacing; },
             "of two wall lines closer than this (metres) along their whole length only the shorter is kept"),
      number("wall-line-side", "M", OptionRange::kLengthOrZero, [](auto& s) -> auto& { return s.options.doors.wall_line_side; },
             "a wall line is at least this long (metres) and leaves both sides this wide"),
      on_off("no-island-cuts", [](auto& s) -> auto& { return s.switches.no_island_cuts; },
             "no door-like cuts from the outline to a free-standing piece of wall (longer than 2.5 m, at most 0.25 m "
             "thick: a partition whose joint the sensor missed), which separate rooms only together (candidates that "
             "merging may remove)"),
      on_off("no-merge", [](auto& s) -> auto& { return s.switches.no_merge; },
             "keep DuDe's pieces as rooms instead of merging them across wide cuts"),
      number("fold-area", "M2", OptionRange::kArea, [](auto& s) -> auto& { return s.options.merge.min_room_area; },
             "rooms smaller than this (m²) are folded into the neighbour they share the longest cut with"),
      on_off("no-simplify", [](auto& s) -> auto& { return s.switches.no_simplify; },
             "decompose the exact pixel-edge polygons (slower)"),
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
      on_off("no-clean", [](auto& s) -> auto& { return s.switches.no_clean; },
             "decompose the free space as it is: keep laser-ray fans, slivers, free and obstacle specks"),
      on_off("no-width-steps", [](auto& s) -> auto& { return s.switches.no_width_steps; },
             "merge a room into a much wider space it opens onto across its whole width (no width-step rule)"),
      on_off("no-furniture-rule", [](auto& s) -> auto& { return s.switches.no_furniture_rule; },
             "cuts that end on furniture-sized obstacles (at most 2.5 m a side) may separate rooms"),
      number("oversegment", "F", OptionRange::kFraction, [](auto& s) -> auto& { return s.options.oversegment; },
             "with merging, DuDe cuts at F x tau, 0 < F <= 1 (merging then removes the cuts that are not door-like)"),
  };
  return rows;
}

SegmentOptions to_segment_options(const SegmentSettings& settings) {
  SegmentOptions options = settings.options;
  apply(settings.switches, options);
  validate(options);
  return options;
}

}  // namespace topocut
