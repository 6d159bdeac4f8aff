// `topocut simulate-map` as a user runs it: its outputs load with segment and score with evaluate,
// the same seed gives the same bytes, and bad input is one clear line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <opencv2/core.hpp>

#include "cli/cli_runner.h"
#include "io/test_images.h"
#include "topocut/exploration/simulated_map.h"

namespace {

namespace fs = std::filesystem;

using topocut::testing::CliResult;
using topocut::testing::expect_clean_error;
using topocut::testing::file_text;
using topocut::testing::memory_limit;
using topocut::testing::run_cli_line;

class SimulateMapCli : public ::testing::Test {
 protected:
  CliResult run(const std::string& command, const std::string& args) { return run_cli_line(dir_, command + " " + args, 120); }
  CliResult simulate(const std::string& args) { return run("simulate-map", args); }

  // A 12 m x 7 m plan (0.05 m/px), black outside like a Bormann map: a corridor below, three rooms
  // with doors; its ground truth in the dataset's naming, the doors cut off by a line.
  fs::path write_plan(const fs::path& folder, const std::string& name) {
    fs::create_directories(folder);
    cv::Mat plan(140, 240, CV_8UC1, cv::Scalar(0));
    plan(cv::Rect(4, 100, 232, 36)).setTo(255);
    cv::Mat truth;
    int x = 4;
    for (const int width : {70, 80, 74}) {
      plan(cv::Rect(x, 4, width, 92)).setTo(255);
      plan(cv::Rect(x + width / 2 - 9, 96, 18, 4)).setTo(255);
      x += width + 4;
    }
    truth = plan.clone();
    x = 4;
    for (const int width : {70, 80, 74}) {
      truth(cv::Rect(x + width / 2 - 9, 96, 18, 4)).setTo(0);
      x += width + 4;
    }
    const fs::path path = folder / (name + ".png");
    topocut::testing::write_test_image(path.string(), plan);
    topocut::testing::write_test_image((folder / (name + "_gt_segmentation.png")).string(), truth);
    return path;
  }

  std::string out(const std::string& name) const { return (dir_ / name).string(); }

  topocut::testing::TempDir temp_;
  const fs::path dir_ = temp_.path();
};

TEST_F(SimulateMapCli, HelpExplainsEveryOption) {
  const CliResult o = simulate("--help");
  ASSERT_EQ(o.code, 0) << o.err;
  for (const auto& row : topocut::simulated_map_option_rows()) EXPECT_NE(o.out.find("--" + row.name + " "), std::string::npos) << row.name;
  for (const char* option : {"--gt", "--seed", "--out-map", "--out-gt", "--dataset", "--seeds", "--limit", "--out "})
    EXPECT_NE(o.out.find(option), std::string::npos) << option;
  EXPECT_NE(run("--help", "").out.find("simulate-map"), std::string::npos);
}

TEST_F(SimulateMapCli, SameSeedSameBytesAndOutputsThatSegmentAndEvaluate) {
  const fs::path plan = write_plan(dir_ / "plans", "lab");
  const CliResult a = simulate(plan.string() + " --seed 4 --out-map " + out("a.png") + " --out-gt " + out("a_gt.png"));
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_NE(a.out.find("rooms seen"), std::string::npos) << a.out;
  const CliResult b = simulate(plan.string() + " --seed 4 --out-map " + out("b.png") + " --out-gt " + out("b_gt.png"));
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_EQ(file_text(out("a.png")), file_text(out("b.png")));
  EXPECT_EQ(file_text(out("a_gt.png")), file_text(out("b_gt.png")));
  ASSERT_EQ(simulate(plan.string() + " --seed 5 --out-map " + out("c.png") + " --out-gt " + out("c_gt.png")).code, 0);
  EXPECT_NE(file_text(out("a.png")), file_text(out("c.png")));

  // The map's palette: 0, 205 and 255 only; the ground truth 0 and 255, on the map's free cells.
  const cv::Mat map = topocut::testing::read_test_image(out("a.png"), topocut::testing::Pixels::kGrey);
  const cv::Mat truth = topocut::testing::read_test_image(out("a_gt.png"), topocut::testing::Pixels::kGrey);
  ASSERT_FALSE(map.empty());
  ASSERT_EQ(map.size(), truth.size());
  EXPECT_EQ(cv::countNonZero(map == 0) + cv::countNonZero(map == 205) + cv::countNonZero(map == 255), static_cast<int>(map.total()));
  EXPECT_GT(cv::countNonZero(map == 205), 0);
  EXPECT_GT(cv::countNonZero(truth == 255), 1000);
  EXPECT_EQ(cv::countNonZero((truth == 255) & (map != 255)), 0);

  const CliResult segmented = run("segment", out("a.png") + " --out-labels " + out("a_labels.png"));
  EXPECT_EQ(segmented.code, 0) << segmented.err;
  EXPECT_TRUE(fs::exists(out("a_labels.png")));

  // A ROS map for a .yaml name.
  const CliResult yaml = simulate(plan.string() + " --seed 4 --out-map " + out("ros.yaml") + " --out-gt " + out("ros_gt.png"));
  ASSERT_EQ(yaml.code, 0) << yaml.err;
  EXPECT_TRUE(fs::exists(out("ros.pgm")));
  EXPECT_NE(file_text(out("ros.yaml")).find("resolution: 0.05"), std::string::npos) << file_text(out("ros.yaml"));
}

TEST_F(SimulateMapCli, DatasetModeWritesTheBormannLayoutThatEvaluateScores) {
  write_plan(dir_ / "plans", "lab");
  write_plan(dir_ / "plans", "office");
  write_plan(dir_ / "plans", "zoo");
  const fs::path sims = dir_ / "sims";
  const CliResult o = simulate("--dataset " + (dir_ / "plans").string() + " --seeds 2 --seed 7 --limit 2 --out " + sims.string());
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.err.find("2/2 office"), std::string::npos) << o.err;  // progress
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(sims)) files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"lab_s7.png", "lab_s7_gt_segmentation.png", "lab_s8.png", "lab_s8_gt_segmentation.png",
                                             "office_s7.png", "office_s7_gt_segmentation.png", "office_s8.png",
                                             "office_s8_gt_segmentation.png"}));
  // The same seed, the same bytes as the single command; plans of the same seed differ from seed to seed.
  ASSERT_EQ(simulate((dir_ / "plans" / "lab.png").string() + " --seed 8 --out-map " + out("one.png") + " --out-gt " + out("one_gt.png")).code, 0);
  EXPECT_EQ(file_text(out("one.png")), file_text((sims / "lab_s8.png").string()));
  EXPECT_NE(file_text((sims / "lab_s7.png").string()), file_text((sims / "lab_s8.png").string()));

  const CliResult scored = run("evaluate", "--dataset " + sims.string() + " --variant plain --csv " + out("scores.csv"));
  ASSERT_EQ(scored.code, 0) << scored.err;
  const std::string csv = file_text(out("scores.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5) << csv;  // a header and the four maps, none failed
  EXPECT_NE(csv.find("office_s8,plain,"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("FAILED"), std::string::npos) << csv;
}

TEST_F(SimulateMapCli, AGroundTruthOfAnotherSizeIsRefusedByItsHeader) {
  // Its header declares 10000 x 10000 (100 megapixels, within the pixel limit): refused before a
  // decoder allocates for it, within a memory limit a decode would break.
  const fs::path plan = write_plan(dir_ / "plans", "lab");
  std::string bytes = file_text((dir_ / "plans" / "lab_gt_segmentation.png").string());
  for (int i = 0; i < 4; ++i) bytes[16 + i] = bytes[20 + i] = static_cast<char>(10000u >> (24 - 8 * i));
  std::ofstream(out("big_gt.png"), std::ios::binary) << bytes;
  const CliResult r = run_cli_line(dir_, "simulate-map " + plan.string() + " --gt " + out("big_gt.png") + " --out-map " +
                                             out("m.png") + " --out-gt " + out("g.png"), 10, memory_limit(600000));
  expect_clean_error(r, "simulate-map", "big_gt.png' is 10000 x 10000 pixels but the plan is 240 x 140");
  EXPECT_FALSE(fs::exists(out("m.png")));
}

TEST_F(SimulateMapCli, NamesAreEscapedOnTheTerminal) {
  const fs::path plan = write_plan(dir_ / "plans", "red\x1b[31mlab\rX");
  const CliResult one = simulate(topocut::testing::shell_quoted(plan.string()) + " --out-map " + out("m.png") + " --out-gt " + out("g.png"));
  ASSERT_EQ(one.code, 0) << one.err;
  const CliResult all = simulate("--dataset " + (dir_ / "plans").string() + " --out " + out("sims"));
  ASSERT_EQ(all.code, 0) << all.err;
  for (const std::string& text : {one.out, one.err, all.out, all.err}) {
    EXPECT_EQ(text.find('\x1b'), std::string::npos) << text;
    EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  }
  EXPECT_NE(one.out.find("simulated " + (dir_ / "plans").string() + "/red\\x1B[31mlab\\x0DX.png seed"), std::string::npos) << one.out;
  EXPECT_NE(all.err.find("red\\x1B[31mlab\\x0DX"), std::string::npos) << all.err;
}

TEST_F(SimulateMapCli, BadInputIsOneClearErrorAndWritesNothing) {
  const fs::path plan = write_plan(dir_ / "plans", "lab");
  const std::string outputs = " --out-map " + out("m.png") + " --out-gt " + out("g.png");
  expect_clean_error(simulate((dir_ / "nope.png").string() + outputs), "simulate-map", "nope.png");
  // A ground truth of another size.
  topocut::testing::write_test_image(out("small_gt.png"), cv::Mat(50, 60, CV_8UC1, cv::Scalar(255)));
  expect_clean_error(simulate(plan.string() + " --gt " + out("small_gt.png") + outputs), "simulate-map",
                     "small_gt.png' is 60 x 50 pixels but the plan is 240 x 140");
  // A plan without a ground truth beside it.
  topocut::testing::write_test_image(out("alone.png"), cv::Mat(50, 60, CV_8UC1, cv::Scalar(255)));
  expect_clean_error(simulate(out("alone.png") + outputs), "simulate-map", "--gt");
  // A ground truth without a room.
  topocut::testing::write_test_image(out("dark_gt.png"), cv::Mat(140, 240, CV_8UC1, cv::Scalar(0)));
  expect_clean_error(simulate(plan.string() + " --gt " + out("dark_gt.png") + outputs), "simulate-map", "room");
  // Bad seeds and options are usage errors (exit 2).
  for (const char* seed : {"-1", "abc", "4294967296", "1.5"})
    expect_clean_error(simulate(plan.string() + " --seed " + seed + outputs), "simulate-map", "--seed", 2);
  expect_clean_error(simulate(plan.string() + " --windows 2" + outputs), "simulate-map", "--windows", 2);
  expect_clean_error(simulate(plan.string() + " --range-from 20 --range-to 10" + outputs), "simulate-map", "--range-to", 2);
  expect_clean_error(simulate(plan.string() + " --wall-change 1.5" + outputs), "simulate-map", "--wall-change", 2);
  expect_clean_error(simulate(plan.string() + " --no-such-option 1" + outputs), "simulate-map", "no-such-option", 2);
  expect_clean_error(simulate(plan.string() + " --out-map " + out("m.png")), "simulate-map", "--out-gt", 2);
  expect_clean_error(simulate("--dataset " + (dir_ / "plans").string()), "simulate-map", "--out", 2);
  expect_clean_error(simulate(plan.string() + " --dataset " + (dir_ / "plans").string() + " --out " + out("d")), "simulate-map",
                     "--dataset", 2);
  expect_clean_error(simulate("--dataset " + (dir_ / "none").string() + " --out " + out("d")), "simulate-map", "none");
  // An output that is an input.
  expect_clean_error(simulate(plan.string() + " --out-map " + plan.string() + " --out-gt " + out("g.png")), "simulate-map", "lab.png");
  EXPECT_FALSE(fs::exists(out("m.png")));
  EXPECT_FALSE(fs::exists(out("g.png")));
}

}  // namespace
