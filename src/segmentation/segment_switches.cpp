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

// A --no-NAME switch for every rule of the pipeline that has one, in the pipeline's order.
std::vector<Row> rule_switches() {
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
  return switches;
}

// The rows of the part of SegmentOptions that part() returns.
template <typename Inner, typename Part>
std::vector<Row> lifted(const std::vector<OptionRow<Inner>>& part_rows, Part part) {
  return rows_within<SegmentSettings>(part_rows, part);
}

// The row of SegmentOptions' own number named name (segment_number_option_rows()).
Row own_number(const std::string& name) {
  static const std::vector<Row> rows = lifted(segment_number_option_rows(), [](auto& s) -> auto& { return s.options; });
  return *find_option(rows, name);
}

// The table and its headings, built together so that they cannot disagree.
struct Table {
  std::vector<Row> rows;
  std::vector<OptionGroup> groups;

  void add(const char* heading, std::vector<Row> group) {
    groups.push_back({heading, group.size()});
    rows.insert(rows.end(), group.begin(), group.end());
  }
};

// Every options struct under SegmentOptions by its own table, in the pipeline's order, one heading
// per struct.
Table make_table() {
  Table t;
  t.add("Concavity and the baselines",
        {own_number("concavity"),
         on_off("trivial", [](auto& s) -> auto& { return s.switches.trivial; },
                "no decomposition: one room per free-space component (baseline)"),
         on_off("parity", [](auto& s) -> auto& { return s.switches.parity; },
                "the reference behaviour: DuDe's pieces are the rooms (no cleaning, door cuts, merging or simplification); "
                "alone or with numbers and --trivial, not with a switch it already sets")});
  t.add("Steps of the pipeline (each switch turns one off)", rule_switches());
  t.add("Obstacles", lifted(binarize_option_rows(), [](auto& s) -> auto& { return s.options.binarize; }));
  t.add("Cleaning the free space", lifted(cleaning_option_rows(), [](auto& s) -> auto& { return s.options.cleaning; }));
  std::vector<Row> outlines = lifted(contour_option_rows(), [](auto& s) -> auto& { return s.options.contours; });
  for (Row& row : outlines)
    if (row.name == "min-room-area") row = given(row);
  outlines.push_back(own_number("simplify"));
  t.add("Free space and its outlines", std::move(outlines));
  t.add("Door cuts", lifted(door_option_rows(), [](auto& s) -> auto& { return s.options.doors; }));
  std::vector<Row> decomposition = {own_number("oversegment")};
  for (Row& row : lifted(decomposition_option_rows(), [](auto& s) -> auto& { return s.options.decomposition; }))
    decomposition.push_back(std::move(row));
  t.add("Decomposition", std::move(decomposition));
  t.add(kMergingHeading, lifted(room_merge_option_rows(), [](auto& s) -> auto& { return s.options.merge; }));
  t.add("Open rooms", lifted(open_room_option_rows(), [](auto& s) -> auto& { return s.options.open_rooms; }));
  t.add("Room labels", lifted(room_label_option_rows(), [](auto& s) -> auto& { return s.options.labels; }));
  t.add("Room kinds", lifted(room_kind_option_rows(), [](auto& s) -> auto& { return s.options.kinds; }));
  return t;
}

const Table& table() {
  static const Table t = make_table();
  return t;
}

}  // namespace

const std::vector<OptionRow<SegmentSettings>>& segment_option_rows() { return table().rows; }

const std::vector<OptionGroup>& segment_option_groups() { return table().groups; }

SegmentOptions to_segment_options(const SegmentSettings& settings) {
  SegmentOptions options = settings.options;
  apply(settings.switches, options);
  validate(options);
  return options;
}

}  // namespace topocut
