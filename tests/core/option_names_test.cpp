#include "topocut/core/option_names.h"

#include <gtest/gtest.h>

namespace topocut {
namespace {

TEST(OptionNames, UnderscoresAndDashesAreAlike) {
  EXPECT_EQ(dashed_option_name("robot_radius"), "robot-radius");
  EXPECT_EQ(dashed_option_name("no_wall_lines"), "no-wall-lines");
  EXPECT_EQ(dashed_option_name("concavity"), "concavity");
  EXPECT_EQ(underscored_option_name("robot-radius"), "robot_radius");
  EXPECT_EQ(underscored_option_name("no-wall-lines"), "no_wall_lines");
}

TEST(OptionNames, ATypoGetsTheNameMeantAndAnythingElseNone) {
  const std::vector<std::string> known{"robot-radius", "concavity", "door-width", "no-doors"};
  EXPECT_EQ(closest_option_name("robot-radios", known), "robot-radius");  // one substitution
  EXPECT_EQ(closest_option_name("robot_radis", known), "robot-radius");   // a deletion, '_' as '-'
  EXPECT_EQ(closest_option_name("concavty", known), "concavity");
  EXPECT_EQ(closest_option_name("no-door", known), "no-doors");
  EXPECT_EQ(closest_option_name("wall-lines", known), "");  // three or more edits from every name
  EXPECT_EQ(closest_option_name("x", {}), "");
  // The closest of two candidates wins.
  EXPECT_EQ(closest_option_name("door-widt", {"door-width", "door-widths-x"}), "door-width");
}

}  // namespace
}  // namespace topocut
