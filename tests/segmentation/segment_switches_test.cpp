#include "topocut/segmentation/segment_switches.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "topocut/core/error.h"
#include "topocut/segmentation/incremental_segmenter.h"

namespace topocut {
namespace {

const OptionRow<SegmentSettings>& row(const std::string& name) {
  const OptionRow<SegmentSettings>* found = find_option(segment_option_rows(), name);
  EXPECT_NE(found, nullptr) << name;
  return *found;
}

SegmentOptions given(std::initializer_list<std::pair<const char*, double>> values) {
  SegmentSettings settings;
  for (const auto& [name, value] : values) set_option(row(name), settings, value, name);
  return to_segment_options(settings);
}

// A valid value of row other than before: on for a switch, the next whole number for a count.
template <typename Target>
double changed_value(const OptionRow<Target>& r, double before) {
  if (r.is_switch()) return before != 0.0 ? 0.0 : 1.0;
  if (r.range == OptionRange::kFraction) return before == 0.75 ? 0.5 : 0.75;
  if (r.range == OptionRange::kShare || r.range == OptionRange::kShareBelowOne) return before == 0.25 ? 0.5 : 0.25;
  return is_whole_number(r.range) ? before + 1.0 : before + 0.25;
}

// Every row sets a field of its own: setting it leaves what every other row reads at its default
// (two rows on one field, or a row on the wrong struct, would show here).
template <typename Target>
void expect_one_field_per_row(const std::vector<OptionRow<Target>>& rows, const Target& defaults) {
  for (const OptionRow<Target>& r : rows) {
    Target target = defaults;
    r.set(target, changed_value(r, r.get(defaults)));
    for (const OptionRow<Target>& other : rows) {
      if (&other == &r) continue;
      EXPECT_EQ(other.get(target), other.get(defaults)) << r.name << " changed " << other.name;
    }
  }
}

TEST(SegmentOptionRows, EveryRowSetsAFieldOfItsOwn) {
  expect_one_field_per_row(segment_option_rows(), SegmentSettings{});
  expect_one_field_per_row(incremental_option_rows(), IncrementalOptions{});
}

// The tables of SegmentOptions' parts are all in the segment table, under the same names, reading the
// part's own defaults; the incremental table shares no name with it (one flag line, one keyword).
TEST(SegmentOptionRows, EveryPartsTableIsInTheSegmentTable) {
  const SegmentSettings defaults;
  auto expect_within = [&](const auto& part_rows, const auto& part) {
    for (const auto& r : part_rows) {
      const OptionRow<SegmentSettings>* lifted = find_option(segment_option_rows(), r.name);
      ASSERT_NE(lifted, nullptr) << r.name;
      EXPECT_EQ(lifted->get(defaults), r.get(part)) << r.name;
      EXPECT_EQ(lifted->range, r.range) << r.name;
      EXPECT_EQ(lifted->help, r.help) << r.name;
    }
  };
  expect_within(binarize_option_rows(), defaults.options.binarize);
  expect_within(cleaning_option_rows(), defaults.options.cleaning);
  expect_within(contour_option_rows(), defaults.options.contours);
  expect_within(door_option_rows(), defaults.options.doors);
  expect_within(decomposition_option_rows(), defaults.options.decomposition);
  expect_within(room_merge_option_rows(), defaults.options.merge);
  expect_within(open_room_option_rows(), defaults.options.open_rooms);
  expect_within(room_label_option_rows(), defaults.options.labels);
  expect_within(room_kind_option_rows(), defaults.options.kinds);
  std::set<std::string> names;
  for (const auto& r : segment_option_rows()) names.insert(r.name);
  for (const auto& r : incremental_option_rows()) EXPECT_TRUE(names.insert(r.name).second) << r.name;
  EXPECT_FALSE(names.count(kMergeModelOption.name));
}

TEST(SegmentOptionRows, NamesAreUniqueAndEveryRowReachesTheOptions) {
  std::set<std::string> names;
  for (const OptionRow<SegmentSettings>& r : segment_option_rows()) {
    EXPECT_TRUE(names.insert(r.name).second) << r.name;
    EXPECT_FALSE(r.help.empty()) << r.name;
    EXPECT_EQ(r.value_name.empty(), r.is_switch()) << r.name;
    // Setting a row changes what get reads back, from the default.
    SegmentSettings settings;
    const double before = r.get(settings);
    const double value = changed_value(r, before);
    r.set(settings, value);
    EXPECT_EQ(r.get(settings), value) << r.name;
    EXPECT_NE(r.get(settings), before) << r.name;
  }
  EXPECT_EQ(given({{"door-width", 1.25}}).doors.max_width, 1.25);
  EXPECT_EQ(given({{"opening", 0.2}}).binarize.opening_size, 0.2);
  EXPECT_EQ(given({{"oversegment", 1.0}}).oversegment, 1.0);
  EXPECT_FALSE(given({{"trivial", 1}}).decompose);
  EXPECT_FALSE(given({{"no-clean", 1}}).clean);
  const SegmentOptions lines = given({{"wall-line-wall", 0.3}, {"max-wall-line", 30.0}, {"wall-line-spacing", 0.1}, {"wall-line-side", 0.3}});
  EXPECT_EQ(lines.doors.wall_line_wall, 0.3);
  EXPECT_EQ(lines.doors.max_wall_line, 30.0);
  EXPECT_EQ(lines.doors.wall_line_spacing, 0.1);
  EXPECT_EQ(lines.doors.wall_line_side, 0.3);
  EXPECT_EQ(lines.doors.min_side_width, DoorOptions{}.min_side_width);  // wall openings keep theirs
  SegmentSettings settings;
  EXPECT_THROW(set_option(row("oversegment"), settings, 2.0, "--oversegment"), Error);
}

// validate(SegmentOptions) checks every number through its row: a value that no range holds (-1),
// set past the front ends, is refused in one line naming the option.
TEST(SegmentOptionRows, ValidateRefusesEveryRowsBadValueByName) {
  for (const OptionRow<SegmentSettings>& r : segment_option_rows()) {
    if (r.is_switch() || r.range == OptionRange::kAny) continue;
    SegmentSettings settings;
    r.set(settings, -1.0);
    try {
      validate(settings.options);
      ADD_FAILURE() << r.name << " = -1 passes";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("--" + r.name + " must ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

// The one --parity rule of every front end.
TEST(SegmentOptionRows, ParityIsTheReferenceAndRefusesTheSwitchesItSets) {
  const SegmentOptions parity = given({{"parity", 1}, {"concavity", 3.0}});
  const SegmentOptions reference = parity_segment_options(3.0);
  EXPECT_EQ(parity.concavity, 3.0);
  EXPECT_EQ(parity.doors.passages, reference.doors.passages);
  EXPECT_EQ(parity.merge.enabled, reference.merge.enabled);
  EXPECT_EQ(parity.clean, reference.clean);
  EXPECT_EQ(parity.simplify, reference.simplify);
  EXPECT_EQ(parity.contours.min_component_area, reference.contours.min_component_area);
  // A number it sets too: the value given wins.
  EXPECT_EQ(given({{"parity", 1}, {"min-room-area", 2.0}}).contours.min_component_area, 2.0);
  EXPECT_FALSE(given({{"parity", 1}, {"trivial", 1}}).decompose);
  EXPECT_FALSE(given({{"no-wall-lines", 1}}).doors.wall_lines);
  EXPECT_TRUE(given({}).doors.wall_lines);
  EXPECT_FALSE(given({{"no-island-cuts", 1}}).doors.island_cuts);
  EXPECT_TRUE(given({}).doors.island_cuts);
  EXPECT_FALSE(given({{"no-corridor-rule", 1}}).merge.corridor_rule);
  EXPECT_TRUE(given({}).merge.corridor_rule);
  EXPECT_EQ(given({{"no-bays", 1}}).merge.bay_share, 0.0);
  EXPECT_GT(given({}).merge.bay_share, 0.0);
  EXPECT_EQ(given({{"no-fragments", 1}}).merge.fragment_area, 0.0);
  EXPECT_GT(given({}).merge.fragment_area, 0.0);
  EXPECT_EQ(given({{"bay-share", 0.3}, {"hang-probability", 0.4}}).merge.bay_share, 0.3);
  EXPECT_EQ(given({{"hang-probability", 0.4}}).merge.hang_probability, 0.4);
  for (const char* sw : {"no-doors", "no-wall-openings", "no-merge", "no-simplify", "no-clean", "no-width-steps",
                         "no-furniture-rule", "cover-obstacles", "no-wall-lines", "no-island-cuts", "no-corridor-rule"}) {
    EXPECT_THROW(given({{"parity", 1}, {sw, 1}}), Error) << sw;
  }
}

}  // namespace
}  // namespace topocut
