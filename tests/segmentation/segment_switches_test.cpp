#include "topocut/segmentation/segment_switches.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "topocut/core/error.h"

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

TEST(SegmentOptionRows, NamesAreUniqueAndEveryRowReachesTheOptions) {
  std::set<std::string> names;
  for (const OptionRow<SegmentSettings>& r : segment_option_rows()) {
    EXPECT_TRUE(names.insert(r.name).second) << r.name;
    EXPECT_FALSE(r.help.empty()) << r.name;
    EXPECT_EQ(r.value_name.empty(), r.is_switch()) << r.name;
    // Setting a row changes what get reads back, from the default.
    SegmentSettings settings;
    const double before = r.get(settings);
    const double value = r.is_switch() ? 1.0 : r.range == OptionRange::kFraction ? 0.75 : before + 0.25;
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
  for (const char* sw : {"no-doors", "no-wall-openings", "no-merge", "no-simplify", "no-clean", "no-width-steps",
                         "no-furniture-rule", "cover-obstacles", "no-wall-lines", "no-island-cuts", "no-corridor-rule"}) {
    EXPECT_THROW(given({{"parity", 1}, {sw, 1}}), Error) << sw;
  }
}

}  // namespace
}  // namespace topocut
