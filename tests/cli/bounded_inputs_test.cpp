// What the command does with inputs sized to hurt: merge models, --config aliases, openings wider
// than the map; and the one option parser: every bad value of the option table gives, on the
// command line and in --config, the message the library gives (the ROS node's and Python's tests
// walk the same table).
#include <chrono>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_maps.h"
#include "cli/cli_runner.h"
#include "io/test_images.h"
#include "topocut/core/error.h"
#include "topocut/core/option_table.h"
#include "topocut/segmentation/merge_model.h"
#include "topocut/segmentation/segment_switches.h"

namespace {

using topocut::testing::bundled;
using topocut::testing::small_map;
using topocut::testing::CliResult;
using topocut::testing::expect_clean_error;
using topocut::testing::file_text;
using topocut::testing::memory_limit;
using topocut::testing::run_cli;
using topocut::testing::TempDir;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(BoundedInputs, MergeModelsBeyondTheLimitsAreRefusedBeforeAnyMerging) {
  // Both under the 4 MiB file limit: 200,000 one-leaf trees (3 MB), and one chain of 5000 splits;
  // each was walked for every candidate (18-23 s on a 1 Mpx office instead of 0.3 s).
  const TempDir dir;
  std::string many = "topocut-merge-model 1\n";
  for (int i = 0; i < 200000; ++i) many += "tree\nleaf 0.001\nend\n";
  std::string deep = "topocut-merge-model 1\ntree\n";
  for (int d = 0; d < 5000; ++d) deep += "split furniture_end 0.5 " + std::to_string(2 * d + 1) + " " + std::to_string(2 * d + 2) + "\nleaf 0\n";
  deep += "leaf 1\nend\n";
  const auto start = std::chrono::steady_clock::now();
  expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.yaml"), "--merge-model", dir.write("many.txt", many)}),
                     "segment", "more than 1000 trees (the limit)");
  expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.yaml"), "--merge-model", dir.write("deep.txt", deep)}),
                     "segment", "deeper than 12 splits");
  EXPECT_LT(seconds_since(start), 10.0);
}

TEST(BoundedInputs, MergeModelOptionsAgree) {
  // A model given while learned merging is off was silently ignored by the command (Python used it).
  const TempDir dir;
  const std::string model = dir.write("model.txt", topocut::default_merge_model().text);
  for (const char* off : {"--no-learned-merge", "--no-merge", "--parity", "--trivial"})
    expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.yaml"), "--merge-model", model, off}), "segment",
                       "a merge model is given, but learned merging is off", 2);
  const CliResult ok = run_cli(dir, "segment", {bundled("floorplan.yaml"), "--merge-model", model});
  EXPECT_EQ(ok.code, 0) << ok.err;
}

TEST(BoundedInputs, TheSummaryNamesWhatIsSwitchedOff) {
  const TempDir dir;
  const CliResult all = run_cli(dir, "segment", {bundled("floorplan.yaml")});
  EXPECT_NE(all.out.find("(cleaning + doors + DuDe + merging, concavity 2.5 m)"), std::string::npos) << all.out;
  const CliResult some = run_cli(dir, "segment", {bundled("floorplan.yaml"), "--no-merge", "--no-wall-lines", "--no-doors"});
  EXPECT_NE(some.out.find("(cleaning + DuDe, without wall-lines, concavity 2.5 m)"), std::string::npos) << some.out;
  const CliResult hand = run_cli(dir, "segment", {bundled("floorplan.yaml"), "--no-learned-merge", "--no-clean"});
  EXPECT_NE(hand.out.find("(doors + DuDe + merging by hand rules, concavity 2.5 m)"), std::string::npos) << hand.out;
}

TEST(BoundedInputs, AnOpeningWiderThanTheMapIsOneClearErrorAtOnce) {
  // 5000 m at 0.05 m a cell: a 100,000-cell square ran out of memory; 1000 m took 415 MB.
  const TempDir dir;
  for (const char* metres : {"1000", "5000", "100000"}) {
    const auto start = std::chrono::steady_clock::now();
    const CliResult r = topocut::testing::run_cli_line(
        dir.path(), "segment " + topocut::testing::shell_quoted(bundled("floorplan.yaml")) + " --opening " + metres, 10,
        memory_limit(600000));
    expect_clean_error(r, "segment", "opening it with a square of " + std::string(metres) + " m a side, more than the map's 15 m");
    EXPECT_EQ(r.err.find("robot radius"), std::string::npos) << r.err;
    EXPECT_LT(seconds_since(start), 5.0);
  }
}

TEST(BoundedInputs, ConfigAliasesDuplicatesAndEmptyKeys) {
  const TempDir dir;
  const std::string map = small_map(dir);
  // One anchored 100 KiB value aliased 2000 times: 200 MB once copied, from a file of 110 KB.
  std::string aliases = "out-json: &big " + std::string(100 << 10, 'a') + "\nmin-room-area: [";
  for (int i = 0; i < 2000; ++i) aliases += std::string(i ? ", " : "") + "*big";
  const std::string config = dir.write("aliases.yaml", aliases + "]\n");
  const auto start = std::chrono::steady_clock::now();
  expect_clean_error(run_cli(dir, "segment", {map, "--config", config}), "segment", "its values add up to more than 1 MiB", 2);
  EXPECT_LT(seconds_since(start), 5.0);
  // A key given twice is refused whatever its kind (a switch's second value used to win).
  for (const char* twice : {"trivial: true\ntrivial: false\n", "trivial: false\ntrivial: true\n", "concavity: 1\nconcavity: 2\n",
                            "robot_radius: 0.1\nrobot-radius: 0.2\n"})
    expect_clean_error(run_cli(dir, "segment", {map, "--config", dir.write("twice.yaml", twice)}), "segment", "is given twice (line 2)", 2);
  // An empty key names the file and the line.
  for (const char* empty : {"\"\": 1\n", "trivial: true\n'': x\n"})
    expect_clean_error(run_cli(dir, "segment", {map, "--config", dir.write("empty.yaml", empty)}), "segment",
                       "empty.yaml', line " + std::string(empty[0] == 't' ? "2" : "1") + ": an empty key is no option name", 2);
}

TEST(BoundedInputs, NamesAreEscapedOnTheTerminal) {
  const TempDir dir;
  cv::Mat map(40, 60, CV_8UC1, cv::Scalar(0));
  map(cv::Rect(2, 2, 56, 36)).setTo(255);
  const std::string name = dir.file("room\x1b[2J\rX.png");
  ASSERT_TRUE(topocut::testing::write_test_image(name, map));
  const CliResult r = run_cli(dir, "segment", {name, "--trivial"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\r'), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("room\\x1B[2J\\x0DX.png: 60 x 40 cells"), std::string::npos) << r.out;
}

// The library's message for a value given to row under the name shown, or "" when it takes it.
template <typename Row, typename Target>
std::string library_message(const Row& row, Target target, const std::string& text, const std::string& shown) {
  try {
    topocut::set_option(row, target, topocut::parse_option_number(text, shown), shown);
  } catch (const topocut::Error& e) {
    return e.what();
  }
  return "";
}

TEST(OneOptionParser, EveryBadNumberOfTheTableGivesTheLibrarysMessageOnTheCommandLineAndInConfig) {
  // The values a careless or hostile user gives; each row refuses some of them by its range.
  const TempDir dir;
  const std::string map = small_map(dir);
  int walked = 0;
  for (const auto& row : topocut::segment_option_rows()) {
    if (row.is_switch()) continue;
    for (const std::string value : {"-1", "nan", "inf", "0x10", "1e999", "abc", "2,5", "1e6"}) {
      const std::string expected = library_message(row, topocut::SegmentSettings{}, value, "--" + row.name);
      if (expected.empty()) continue;
      SCOPED_TRACE(row.name + " = " + value);
      expect_clean_error(run_cli(dir, "segment", {map, "--" + row.name + "=" + value}), "segment", ": error: " + expected + " (", 2);
      const std::string config = dir.write("c.yaml", row.name + ": '" + value + "'\n");
      expect_clean_error(run_cli(dir, "segment", {map, "--config", config}), "segment", ": error: " + expected + " (", 2);
      ++walked;
    }
  }
  EXPECT_GT(walked, 60);
  // A switch in --config takes YAML's booleans only, with the message every front end gives.
  const std::string config = dir.write("s.yaml", "trivial: 1\n");
  const CliResult r = run_cli(dir, "segment", {map, "--config", config});
  expect_clean_error(r, "segment", "'trivial' in config file '", 2);
  EXPECT_NE(r.err.find(topocut::switch_value_error("s.yaml'", "1")), std::string::npos) << r.err;
}

}  // namespace
