// topocut::load_segment_options (topocut.h): a robot's YAML as `topocut segment --config` reads it.
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "io/temp_dir.h"
#include "topocut/topocut.h"

namespace {

using topocut::testing::TempDir;

double row_value(const std::string& name, const topocut::SegmentSettings& settings) {
  return topocut::find_option(topocut::segment_option_rows(), name)->get(settings);
}

TEST(SegmentOptionsFile, TheExamplesRobotFile) {
  const topocut::SegmentOptions loaded = topocut::load_segment_options(std::string(TOPOCUT_SOURCE_DIR "/examples/robot.yaml"));
  // What the command line --robot-radius 0.1 --concavity 3 --door-width 1.2 --min-room-area 1.5 sets.
  topocut::SegmentSettings given;
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
           {"robot-radius", 0.1}, {"concavity", 3.0}, {"door-width", 1.2}, {"min-room-area", 1.5}})
    topocut::set_option(*topocut::find_option(topocut::segment_option_rows(), name), given, value, name);
  topocut::SegmentSettings expected, got;
  expected.options = topocut::to_segment_options(given);
  got.options = loaded;
  int compared = 0;
  for (const auto& row : topocut::segment_option_rows()) {
    if (row.is_switch()) continue;  // the switches live beside the options (all off in the file)
    EXPECT_DOUBLE_EQ(row.get(got), row.get(expected)) << row.name;
    ++compared;
  }
  EXPECT_GT(compared, 4);
  EXPECT_NE(row_value("concavity", got), row_value("concavity", topocut::SegmentSettings{}));
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
  // The reader's checks, as --config makes them: a key twice, an empty key, a hexadecimal number, a
  // switch given a number.
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {"robot_radius: 0.1\nrobot-radius: 0.2\n", "'robot-radius' in config file '" + dir.file("r.yaml") + "' is given twice (line 2)"},
           {"no_merge: false\n'': 1\n", "config file '" + dir.file("r.yaml") + "', line 2: an empty key is no option name"},
           {"concavity: 0x10\n", "'concavity' in config file '" + dir.file("r.yaml") + "' needs a number, not '0x10'"},
           {"no_merge: 1\n", "'no_merge' in config file '" + dir.file("r.yaml") + "' is a switch: give true or false, not '1'"}}) {
    try {
      topocut::load_segment_options(dir.write("r.yaml", text));
      ADD_FAILURE() << text << " was taken";
    } catch (const topocut::OptionFileError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  }
  const topocut::SegmentOptions defaults = topocut::load_segment_options(dir.write("e.yaml", ""));
  EXPECT_DOUBLE_EQ(defaults.concavity, topocut::SegmentOptions{}.concavity);
}

}  // namespace
