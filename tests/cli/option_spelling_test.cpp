// One spelling per option: every row of the library's segmentation and incremental tables is a flag of
// the commands that segment (and the labeling, walls, log-reading and line tables of label, walls and
// lines), with the table's value name and the default of the options struct the
// command starts from, and a --config key under the same name. Python's keywords and the ROS node's
// parameters are checked against the same tables in tests/python/test_option_spelling.py and
// ros/test/adapter_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli/cli_maps.h"
#include "cli/cli_runner.h"
#include "io/temp_dir.h"
#include "topocut/core/option_table.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/exploration/exploration_run.h"
#include "topocut/evaluation/robot_made_dataset.h"
#include "topocut/evaluation/room_defects.h"
#include "topocut/exploration/explorer.h"
#include "topocut/exploration/grid_replay.h"
#include "topocut/io/carmen_log.h"
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/lines/extract.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segment_switches.h"
#include "topocut/segmentation/wall_map_segment_options.h"
#include "topocut/walls/walls_pipeline.h"

namespace {

using topocut::IncrementalOptions;
using topocut::OptionRow;
using topocut::SegmentSettings;
using topocut::shortest_number;
using topocut::testing::bundled;
using topocut::testing::file_text;
using topocut::testing::run_cli;
using topocut::testing::TempDir;

// Whether row's switch is on in its struct: such a switch takes true or false.
template <typename Target>
bool on_by_default(const OptionRow<Target>& row) {
  return row.is_switch() && row.get(Target{}) != 0.0;
}

// The start of row's line in a command's --help, with the default it shows.
template <typename Target>
std::string help_line(const OptionRow<Target>& row, const Target& defaults) {
  const double value = row.get(defaults);
  if (on_by_default(row)) return "\n  --" + row.name + " true|false (=" + (value != 0.0 ? "true" : "false") + ")";
  if (row.is_switch()) return "\n  --" + row.name + " ";
  return "\n  --" + row.name + " " + row.value_name + " (=" + shortest_number(value) + ")";
}

// Every row of rows has its line in help, once.
template <typename Target>
void expect_rows_in_help(const std::string& command, const std::string& help, const std::vector<OptionRow<Target>>& rows,
                         const Target& defaults) {
  for (const OptionRow<Target>& row : rows) {
    const std::string line = help_line(row, defaults);
    const std::size_t at = help.find(line);
    EXPECT_NE(at, std::string::npos) << command << ": " << line;
    if (at != std::string::npos) {
      EXPECT_EQ(help.find(line, at + 1), std::string::npos) << command << " twice: " << line;
    }
  }
}

TEST(OptionSpelling, EveryRowIsAFlagWithItsStructsDefault) {
  const TempDir dir;
  const std::string segment = run_cli(dir, "segment", {"--help"}).out;
  expect_rows_in_help("segment", segment, topocut::segment_option_rows(), SegmentSettings{});
  EXPECT_NE(segment.find("\n  --" + std::string(topocut::kMergeModelOption.name) + " FILE"), std::string::npos);
  const std::string explore = run_cli(dir, "explore", {"--help"}).out;
  expect_rows_in_help("explore", explore, topocut::segment_option_rows(), SegmentSettings{IncrementalOptions{}.segment, {}});
  expect_rows_in_help("explore", explore, topocut::incremental_option_rows(), IncrementalOptions{});
  expect_rows_in_help("explore", explore, topocut::exploration_option_rows(), topocut::ExplorationOptions{});
  const std::string decompose = run_cli(dir, "decompose", {"--help"}).out;
  expect_rows_in_help("decompose", decompose, topocut::decomposition_option_rows(), topocut::DecompositionOptions{});
  // walls starts from the laser-built grid's options and the real-log preset.
  const std::string walls = run_cli(dir, "walls", {"--help"}).out;
  expect_rows_in_help("walls", walls, topocut::segment_option_rows(), SegmentSettings{topocut::wall_map_segment_options(), {}});
  expect_rows_in_help("walls", walls, topocut::incremental_option_rows(),
                      topocut::wall_map_incremental_options(topocut::wall_map_segment_options()));
  expect_rows_in_help("walls", walls, topocut::walls_option_rows(), topocut::WallsOptions{});
  expect_rows_in_help("walls", walls, topocut::carmen_read_option_rows(), topocut::CarmenReadOptions{});
  const std::string label = run_cli(dir, "label", {"--help"}).out;
  expect_rows_in_help("label", label, topocut::labeling_option_rows(), topocut::LabelingOptions{});
  // Each extractor has its own defaults: the lines command shows the value name only.
  const std::string lines = run_cli(dir, "lines", {"--help"}).out;
  for (const topocut::LineOptionRow& option : topocut::line_option_rows()) {
    const std::string line = "\n  --" + option.row.name + " " + option.row.value_name + " ";
    const std::size_t at = lines.find(line);
    EXPECT_NE(at, std::string::npos) << "lines: " << line;
    if (at != std::string::npos) {
      EXPECT_EQ(lines.find(line, at + 1), std::string::npos) << "lines twice: " << line;
    }
  }
}

// The commands that replay updates (explore, walls --incremental, evaluate --mode incremental) take the
// batch comparison's rows alike, and the two that write frames the same --frame-every (the CLI's
// FrameSequenceOptions, whose help line is written here as the row writes it): one spelling, one
// default, one check that refuses a zero with the range's line.
TEST(OptionSpelling, EveryReplayingCommandTakesTheSameReplayRows) {
  const TempDir dir;
  const auto rows = topocut::batch_comparison_rows<topocut::ExplorationRunOptions>();
  ASSERT_EQ(rows.size(), 2u);
  const std::string frame_every = "\n  --frame-every N (=1) ";
  for (const char* command : {"explore", "walls", "evaluate"}) {
    const std::string help = run_cli(dir, command, {"--help"}).out;
    expect_rows_in_help(command, help, rows, topocut::ExplorationRunOptions{});
    const bool writes_frames = std::string(command) != "evaluate";
    EXPECT_EQ(help.find(frame_every) != std::string::npos, writes_frames) << command;
  }
  // The same rows over GridReplayOptions (what walls hands the library) are spelt the same.
  const auto replay = topocut::batch_comparison_rows<topocut::GridReplayOptions>();
  for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(replay[i].name, rows[i].name);
  const std::string map = bundled("floorplan.yaml");
  for (const char* option : {"--batch-every", "--frame-every"}) {
    const auto r = run_cli(dir, "explore", {map, option, "0"});
    EXPECT_EQ(r.code, 2) << option;
    EXPECT_EQ(r.err.rfind("topocut explore: error: " + std::string(option) + " must be a whole number >= 1", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const auto evaluate = run_cli(dir, "evaluate", {"--dataset", dir.path().string(), "--batch-every", "0"});
  EXPECT_EQ(evaluate.code, 2);
  EXPECT_NE(evaluate.err.find("--batch-every must be a whole number >= 1"), std::string::npos) << evaluate.err;
}

// Every option chosen by name is a flag of its command listing the names, its struct's default shown,
// and a name not listed is refused with one line that lists them.
TEST(OptionSpelling, EveryChoiceIsAFlagListingItsNames) {
  const TempDir dir;
  const std::string help = run_cli(dir, "decompose", {"--help"}).out;
  const topocut::DecompositionOptions defaults;
  for (const topocut::ChoiceRow<topocut::DecompositionOptions>& row : topocut::decomposition_choice_rows()) {
    ASSERT_GE(row.names.size(), 2u) << row.name;
    const std::string line = "\n  --" + row.name + " " + row.value_name() + " (=" + row.get(defaults) + ")";
    const std::size_t at = help.find(line);
    EXPECT_NE(at, std::string::npos) << line;
    if (at != std::string::npos) {
      EXPECT_EQ(help.find(line, at + 1), std::string::npos) << line;
    }
    // Each name sets a value of its own, which reads back as the name.
    for (const std::string& name : row.names) {
      topocut::DecompositionOptions set;
      topocut::set_choice(row, set, name, row.name);
      EXPECT_EQ(row.get(set), name) << row.name;
    }
    const auto r = run_cli(dir, "decompose", {bundled("floorplan.yaml"), "--tau", "1", "--" + row.name, "nameless"});
    EXPECT_EQ(r.code, 2) << row.name;
    EXPECT_NE(r.err.find("--" + row.name + " must be one of '" + row.names.front() + "'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("got 'nameless'"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // The labeling's element, in both commands that label.
  for (const char* command : {"label", "walls"}) {
    const std::string shown = run_cli(dir, command, {"--help"}).out;
    for (const auto& row : topocut::labeling_choice_rows()) {
      const std::string line = "\n  --" + row.name + " " + row.value_name() + " (=" + row.get(topocut::LabelingOptions{}) + ")";
      EXPECT_NE(shown.find(line), std::string::npos) << command << ": " << line;
    }
  }
  const std::string scan = dir.write("scan.csv", "angle,range\n0,2\n0.01,2\n0.02,2\n");
  const auto r = run_cli(dir, "label", {scan, "--element", "disc"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--element must be one of 'cross', 'square', got 'disc'"), std::string::npos) << r.err;
}

// segment --help lists the rows under their struct's heading: each heading once, in the table's order,
// and every row of a group after its heading and before the next one.
TEST(OptionSpelling, SegmentHelpGroupsTheRowsUnderTheirHeadings) {
  const TempDir dir;
  const std::string help = run_cli(dir, "segment", {"--help"}).out;
  const auto& rows = topocut::segment_option_rows();
  const auto& groups = topocut::segment_option_groups();
  std::size_t counted = 0;
  for (const topocut::OptionGroup& group : groups) counted += group.rows;
  EXPECT_EQ(counted, rows.size());
  std::size_t row = 0, previous = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const std::string heading = "\n" + groups[g].heading + ":\n";
    const std::size_t at = help.find(heading);
    ASSERT_NE(at, std::string::npos) << heading;
    EXPECT_EQ(help.find(heading, at + 1), std::string::npos) << heading;
    EXPECT_GT(at, previous) << heading;
    const std::size_t next = g + 1 < groups.size() ? help.find("\n" + groups[g + 1].heading + ":\n") : help.size();
    for (std::size_t k = 0; k < groups[g].rows; ++k, ++row) {
      const std::size_t line = help.find("\n  --" + rows[row].name + " ");
      EXPECT_TRUE(line > at && line < next) << rows[row].name << " not under " << groups[g].heading;
    }
    previous = at;
  }
  const std::size_t merging = help.find(std::string("\n") + topocut::kMergingHeading + ":\n");
  EXPECT_GT(help.find("\n  --" + std::string(topocut::kMergeModelOption.name) + " FILE"), merging);
}

// A --config file naming every row with its default value: each name is a key, each default reads
// back as itself, and the rooms are those of no file at all.
TEST(OptionSpelling, EveryRowIsAConfigKeyTakingItsDefault) {
  const TempDir dir;
  std::string yaml;
  const SegmentSettings defaults;
  for (const OptionRow<SegmentSettings>& row : topocut::segment_option_rows()) {
    const double value = row.get(defaults);
    yaml += row.name + ": " + (row.is_switch() ? (value != 0.0 ? "true" : "false") : shortest_number(value)) + "\n";
  }
  const std::string config = dir.write("all.yaml", yaml);
  const std::string map = bundled("floorplan.yaml");
  const std::string plain = (dir.path() / "plain.json").string(), configured = (dir.path() / "configured.json").string();
  ASSERT_EQ(run_cli(dir, "segment", {map, "--out-json", plain}, 60).code, 0);
  const auto r = run_cli(dir, "segment", {map, "--config", config, "--out-json", configured}, 60);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(file_text(plain), file_text(configured));
}

// The same for the label command's table: its defaults as --config keys give the same segments.
TEST(OptionSpelling, EveryLabelingRowIsAConfigKeyTakingItsDefault) {
  const TempDir dir;
  std::string yaml;
  const topocut::LabelingOptions defaults;
  for (const OptionRow<topocut::LabelingOptions>& row : topocut::labeling_option_rows())
    yaml += row.name + ": " + shortest_number(row.get(defaults)) + "\n";
  const std::string config = dir.write("label.yaml", yaml);
  std::string csv = "angle,range\n";
  for (int i = 0; i < 30; ++i) csv += std::to_string(-0.3 + 0.02 * i) + "," + (i % 10 == 9 ? "nan" : "2") + "\n";
  const std::string scan = dir.write("scan.csv", csv);
  const auto plain = run_cli(dir, "label", {scan});
  const auto configured = run_cli(dir, "label", {scan, "--config", config});
  ASSERT_EQ(plain.code, 0) << plain.err;
  ASSERT_EQ(configured.code, 0) << configured.err;
  EXPECT_EQ(plain.out, configured.out);
}

// The commands' own numbers and names are library rows too, lifted as the segmentation's are: each is
// a flag with its struct's default (evaluate starts --floor-repetitions at 3, walls its extractor at
// IEPF: the struct each starts from), and a bad value is one line naming the flag, exit code 2.
TEST(OptionSpelling, EveryCommandsOwnNumbersAreRowsWithTheirChecks) {
  const TempDir dir;
  expect_rows_in_help("decompose", run_cli(dir, "decompose", {"--help"}).out, topocut::decomposition_tau_rows(),
                      topocut::DecompositionOptions{});
  expect_rows_in_help("explore", run_cli(dir, "explore", {"--help"}).out, topocut::exploration_run_option_rows(),
                      topocut::ExplorationRunOptions{});
  expect_rows_in_help("simulate-map", run_cli(dir, "simulate-map", {"--help"}).out, topocut::robot_made_seed_rows(),
                      topocut::RobotMadeDatasetOptions{});
  topocut::MapFolderOptions folder;
  folder.floor_repetitions = 3;
  expect_rows_in_help("evaluate", run_cli(dir, "evaluate", {"--help"}).out, topocut::map_folder_option_rows(), folder);
  const auto& method = topocut::line_choice_rows().front();
  for (const auto& [command, defaults] : {std::pair<const char*, std::string>{"lines", "smf"}, {"walls", "iepf"}}) {
    const std::string help = run_cli(dir, command, {"--help"}).out;
    EXPECT_NE(help.find("\n  --method " + method.value_name() + " (=" + defaults + ")"), std::string::npos) << command;
  }
  for (const auto& row : topocut::exploration_text_rows())
    EXPECT_NE(run_cli(dir, "explore", {"--help"}).out.find("\n  --" + row.name + " " + row.value_name + " "), std::string::npos);

  const std::string map = bundled("floorplan.yaml");
  const std::string scan = dir.write("scan.csv", "angle,range\n0,2\n0.01,2\n0.02,2\n");
  const struct {
    const char* command;
    std::vector<std::string> args;
    std::string message;
  } bad[] = {
      {"explore", {map, "--seed=-1"}, "--seed must be a whole number in 0..4294967295"},
      {"explore", {map, "--start", "3"}, "--start needs a point X,Y in metres, not '3'"},
      {"simulate-map", {"--dataset", dir.path().string(), "--out", dir.file("out"), "--seed", "4294967296"},
       "--seed must be a whole number in 0..4294967295"},
      {"simulate-map", {"--dataset", dir.path().string(), "--out", dir.file("out"), "--seeds", "0"}, "--seeds must be a whole number >= 1"},
      {"lines", {scan, "--method", "SMF"}, "--method must be one of 'sef', 'lt', 'iepf', 'smf', 'ale', got 'SMF'"},
      {"lines", {scan, "--format", "xml"}, "--format must be one of 'json', 'csv', got 'xml'"},
      {"label", {scan, "--fcm=-1"}, "--fcm must be a whole number >= 0"},
      {"evaluate", {"--dataset", dir.path().string(), "--mode", "live"}, "--mode must be one of 'batch', 'incremental', got 'live'"},
      {"evaluate", {"--maps", dir.path().string(), "--floor-repetitions", "1.5"}, "--floor-repetitions must be a whole number >= 0"},
      {"segment", {map, "--out-json", ""}, "--out-json was given an empty file name"},
      {"walls", {"log.gz", "--out-map", ""}, "--out-map was given an empty file name"},
      {"decompose", {scan, "--tau", "0"}, "--tau must be a positive number"},
  };
  for (const auto& b : bad) {
    const auto r = run_cli(dir, b.command, b.args);
    EXPECT_EQ(r.code, 2) << b.command << " " << b.message << ": " << r.err;
    EXPECT_EQ(r.err.rfind("topocut " + std::string(b.command) + ": error: " + b.message, 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
