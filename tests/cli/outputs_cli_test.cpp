// Every command's outputs as a user meets them: an output that is an input, two outputs on one
// file, a FIFO or a device as the output, and a run that fails after its first output.
#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "cli/cli_maps.h"
#include "cli/cli_runner.h"
#include "io/test_images.h"

namespace topocut::testing {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> names_in(const TempDir& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.path())) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(OutputsCli, AnOutputOnTheInputIsRefusedAndTheInputKept) {
  TempDir dir;
  fs::copy_file(bundled("floorplan.png"), dir.file("map.png"));
  const std::string before = file_text(dir.file("map.png"));
  expect_clean_error(run_cli(dir, "segment", {dir.file("map.png"), "--out-color", dir.file("map.png")}), "segment",
                        "both an input and an output");
  EXPECT_EQ(file_text(dir.file("map.png")), before);

  // The image a YAML names is an input too.
  fs::copy_file(bundled("floorplan.yaml"), dir.file("floorplan.yaml"));
  fs::copy_file(bundled("floorplan.png"), dir.file("floorplan.png"));
  expect_clean_error(run_cli(dir, "segment", {dir.file("floorplan.yaml"), "--out-labels", dir.file("floorplan.png")}), "segment",
                        "both an input and an output");
  EXPECT_EQ(file_text(dir.file("floorplan.png")), before);

  const std::string polygon = dir.write("p.json", R"({"outer": [[0,0],[10,0],[10,4],[4,4],[4,10],[0,10]]})");
  expect_clean_error(run_cli(dir, "decompose", {polygon, "--tau", "1", "-o", polygon}), "decompose", "both an input and an output");
  EXPECT_NE(file_text(polygon).find("outer"), std::string::npos);
}

// Every file a run reads is an input (core/input_file.h records them as they are opened): a
// --config file, the ground truth explore reads, a map that a later frame would overwrite.
TEST(OutputsCli, EveryFileTheRunReadsIsAnInput) {
  TempDir dir;
  // The issue's case: a config file that names itself as an output.
  const std::string config = dir.write("c.yaml", "out-json: " + dir.file("c.yaml") + "\ntrivial: true\n");
  expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.png"), "--config", config}), "segment",
                     "c.yaml' is both an input and an output");
  EXPECT_EQ(file_text(config), "out-json: " + dir.file("c.yaml") + "\ntrivial: true\n");
  // Under another name (a hard link), and as the output of another command.
  fs::create_hard_link(config, dir.file("linked.yaml"));
  expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.png"), "--config", config, "--out-svg", dir.file("linked.yaml")}),
                     "segment", "both an input and an output");
  const std::string polygon = dir.write("p.json", R"({"outer": [[0,0],[10,0],[10,4],[4,4],[4,10],[0,10]]})");
  const std::string decompose_config = dir.write("d.yaml", "tau: 1\n");
  expect_clean_error(run_cli(dir, "decompose", {polygon, "--config", decompose_config, "-o", decompose_config}), "decompose",
                     "both an input and an output");
  EXPECT_EQ(file_text(decompose_config), "tau: 1\n");

  // explore: the map lies in the frames folder under the name of a later frame; the run is refused
  // before that frame replaces it (when the outputs are put in place), and no frame is left.
  const std::string frames = dir.file("frames");
  fs::create_directories(frames);
  fs::copy_file(bundled("floorplan.png"), frames + "/frame_00002.png");
  const std::string map_before = file_text(frames + "/frame_00002.png");
  const CliResult r = run_cli(dir, "explore", {frames + "/frame_00002.png", "--frames", frames, "--no-clean"});
  expect_clean_error(r, "explore", "rame_00002.png' is both an input and an output");
  EXPECT_EQ(file_text(frames + "/frame_00002.png"), map_before);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(frames)) left.push_back(entry.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"frame_00002.png"});
}

TEST(OutputsCli, TwoOutputsOnOneFileAreRefusedBeforeAnyWork) {
  TempDir dir;
  // The log does not exist: the outputs are checked first, so that is not the error reported.
  expect_clean_error(run_cli(dir, "walls", {dir.file("no.log"), "--out-walls", dir.file("d.json"), "--out-rooms",
                                          dir.file("d.json")}), "walls",
                        "two outputs name the same file");
  expect_clean_error(run_cli(dir, "walls", {dir.file("no.log"), "--out-map", dir.file("m.yaml"), "--out-color",
                                          dir.file("m.pgm")}), "walls",
                        "two outputs name the same file");
  expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.png"), "--out-json", dir.file("a.json"),
                                          "--out-svg", (dir.path() / "." / "a.json").string()}), "segment",
                        "two outputs name the same file");
  EXPECT_TRUE(names_in(dir).empty());
}

TEST(OutputsCli, AFifoIsRefusedAndADeviceWrittenWithoutReplacingIt) {
  TempDir dir;
  ASSERT_EQ(::mkfifo(dir.file("pipe.json").c_str(), 0600), 0);
  expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.png"), "--out-json", dir.file("pipe.json")}), "segment",
                        "not a regular file");
  const CliResult ok = run_cli(dir, "segment", {bundled("floorplan.png"), "--out-json", "/dev/null", "--out-svg", "/dev/null"});
  EXPECT_EQ(ok.code, 0) << ok.err;
  struct stat info {};
  ASSERT_EQ(::stat("/dev/null", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
  if (fs::exists("/dev/full")) {
    expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.png"), "--out-json", "/dev/full"}), "segment",
                          "/dev/full");
  }
}

// The JPEG encoder cannot take a 100000-pixel-wide image: the labels written before it must not stay.
TEST(OutputsCli, AFailedOutputLeavesNoEarlierOutputBehind) {
  TempDir dir;
  topocut::testing::write_test_image(dir.file("long.png"), cv::Mat(1, 100000, CV_8UC1, cv::Scalar(255)));
  const CliResult r = run_cli(dir, "segment", {dir.file("long.png"), "--out-labels", dir.file("l.png"), "--out-color",
                                        dir.file("w.jpg")});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"long.png"}));
}

}  // namespace
}  // namespace topocut::testing
