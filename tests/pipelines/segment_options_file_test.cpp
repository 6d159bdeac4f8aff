// topocut::load_segment_options (topocut.h): a robot's YAML as `topocut segment --config` reads it.
#include <gtest/gtest.h>

#include "io/temp_dir.h"
#include "topocut/topocut.h"

namespace {

using topocut::testing::TempDir;

TEST(SegmentOptionsFile, TheExamplesRobotFile) {
  const topocut::SegmentOptions options = topocut::load_segment_options(std::string(TOPOCUT_SOURCE_DIR) + "/examples/robot.yaml");
  topocut::SegmentSettings expected;
  expected.options.robot_radius = 0.1;
  expected.options.concavity = 3.0;
  // The rest as the rows set them: door-width and min-room-area through their own rows.
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{{"door-width", 1.2}, {"min-room-area", 1.5}})
    topocut::set_option(*topocut::find_option(topocut::segment_option_rows(), name), expected, value, name);
  const topocut::SegmentOptions want = topocut::to_segment_options(expected);
  EXPECT_DOUBLE_EQ(options.robot_radius, want.robot_radius);
  EXPECT_DOUBLE_EQ(options.concavity, want.concavity);
  for (const char* name : {"door-width", "min-room-area", "robot-radius", "concavity"}) {
    const auto* row = topocut::find_option(topocut::segment_option_rows(), std::string(name));
    topocut::SegmentSettings got;
    got.options = options;
    EXPECT_DOUBLE_EQ(row->get(got), row->get(expected)) << name;
  }
}

TEST(SegmentOptionsFile, RefusesWhatIsNoSegmentationOption) {
  TempDir dir;
  const std::string path = dir.write("robot.yaml", "concavity: 3\nout-json: rooms.json\n");
  try {
    topocut::load_segment_options(path);
    FAIL() << "out-json was taken";
  } catch (const topocut::OptionFileError& e) {
    EXPECT_EQ(std::string(e.what()), "'out-json' in config file '" + path + "' is not a segmentation option");
  }
  // A combination the command refuses: --parity with a rule switched off.
  EXPECT_THROW(topocut::load_segment_options(dir.write("p.yaml", "parity: true\nno-merge: true\n")), topocut::Error);
  const topocut::SegmentOptions defaults = topocut::load_segment_options(dir.write("e.yaml", ""));
  EXPECT_DOUBLE_EQ(defaults.concavity, topocut::SegmentOptions{}.concavity);
}

}  // namespace
