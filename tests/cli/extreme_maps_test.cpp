// Extreme maps through `topocut segment` (issue "Hardening"): every one must give a clean result —
// labels of the map's size with no room on obstacles or unknown cells, a room on every free cell,
// JSON whose rooms match the labels, an SVG — or one clear error line, a non-zero exit and no output
// file at all. Never a crash, a hang or a half-written file.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "cli/cli_runner.h"
#include "io/temp_dir.h"
#include "io/test_images.h"

namespace {

using topocut::testing::TempDir;

using topocut::testing::file_text;

struct Outcome : topocut::testing::CliResult {
  bool signalled = false;
  std::string labels, color, json, svg;  // output paths
};

Outcome run_segment(const TempDir& dir, const std::string& map, std::vector<std::string> extra = {}) {
  Outcome o;
  o.labels = dir.file("labels.png");
  o.color = dir.file("color.png");
  o.json = dir.file("rooms.json");
  o.svg = dir.file("rooms.svg");
  std::vector<std::string> args{map, "--out-labels", o.labels, "--out-color", o.color, "--out-json", o.json, "--out-svg", o.svg};
  args.insert(args.end(), extra.begin(), extra.end());
  // The time limit turns a hang into a failure (exit 124) instead of a stuck suite.
  static_cast<topocut::testing::CliResult&>(o) = topocut::testing::run_cli(dir, "segment", args, 300);
  o.signalled = o.code == -1;
  return o;
}

// The one-clear-error contract: non-zero exit (not a crash or the timeout's 124), exactly one line on
// stderr in the CLI's format, and no output file left behind.
void expect_clear_error(const Outcome& o, const std::string& must_mention) {
  EXPECT_FALSE(o.signalled);
  EXPECT_NE(o.code, 0);
  EXPECT_NE(o.code, 124) << "timed out";
  EXPECT_EQ(o.err.rfind("topocut segment: error: ", 0), 0u) << o.err;
  EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
  EXPECT_NE(o.err.find(must_mention), std::string::npos) << o.err;
  for (const std::string& path : {o.labels, o.color, o.json, o.svg}) {
    EXPECT_FALSE(std::filesystem::exists(path)) << path << " was written despite the error";
  }
}

// A clean result for a plain image map whose cells are exactly 0 (occupied), 128 (unknown) or 255
// (free). Returns the labels.
cv::Mat expect_clean(const Outcome& o, const cv::Mat& map) {
  EXPECT_FALSE(o.signalled);
  EXPECT_EQ(o.code, 0) << o.err;
  EXPECT_TRUE(o.err.empty()) << o.err;
  cv::Mat labels = topocut::testing::read_test_image(o.labels);
  if (labels.empty()) {
    ADD_FAILURE() << "no label image";
    return labels;
  }
  EXPECT_EQ(labels.type(), CV_16UC1);
  EXPECT_EQ(labels.size(), map.size());
  if (labels.size() != map.size()) return labels;
  const nlohmann::json rooms = nlohmann::json::parse(file_text(o.json));
  std::set<int> ids;
  for (const auto& room : rooms.at("rooms")) ids.insert(room.at("id").get<int>());
  bool any_free = false;
  std::set<int> used;
  for (int r = 0; r < map.rows; ++r) {
    for (int c = 0; c < map.cols; ++c) {
      const int label = labels.at<std::uint16_t>(r, c);
      if (map.at<std::uint8_t>(r, c) != 255) {
        EXPECT_EQ(label, 0) << "a room on a non-free cell at row " << r << ", column " << c;
        if (label != 0) return labels;
      } else {
        any_free = true;
        if (label != 0) used.insert(label);
      }
    }
  }
  // Every label is a room in the JSON, and every room of the JSON has cells.
  EXPECT_EQ(used, ids);
  if (!any_free) {
    EXPECT_TRUE(ids.empty());
  }
  EXPECT_FALSE(topocut::testing::read_test_image(o.color).empty());
  const std::string svg = file_text(o.svg);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  return labels;
}

// Every free cell of a map gets a room (segment's promise) when the map has any room at all.
void expect_every_free_cell_labelled(const cv::Mat& labels, const cv::Mat& map) {
  if (labels.size() != map.size()) return;
  int unlabelled = 0;
  for (int r = 0; r < map.rows; ++r)
    for (int c = 0; c < map.cols; ++c)
      if (map.at<std::uint8_t>(r, c) == 255 && labels.at<std::uint16_t>(r, c) == 0) ++unlabelled;
  EXPECT_EQ(unlabelled, 0);
}

std::string write_map(const TempDir& dir, const std::string& name, const cv::Mat& map) {
  const std::string path = dir.file(name);
  EXPECT_TRUE(topocut::testing::write_test_image(path, map));
  return path;
}

TEST(ExtremeMaps, AllFreeMapIsOneRoomCoveringEveryCellUpToTheBorder) {
  TempDir dir;
  const cv::Mat map(40, 60, CV_8UC1, cv::Scalar(255));  // 3 m x 2 m: convex, one room
  const cv::Mat labels = expect_clean(run_segment(dir, write_map(dir, "free.png", map)), map);
  ASSERT_FALSE(labels.empty());
  double lo = 0, hi = 0;
  cv::minMaxLoc(labels, &lo, &hi);
  EXPECT_EQ(lo, 1);
  EXPECT_EQ(hi, 1);
}

// A map without free space has nothing to segment: segment() documents an Error for it.
TEST(ExtremeMaps, AllOccupiedMapIsAClearError) {
  TempDir dir;
  const cv::Mat map(30, 30, CV_8UC1, cv::Scalar(0));
  expect_clear_error(run_segment(dir, write_map(dir, "occupied.png", map)), "no free space");
}

TEST(ExtremeMaps, AllUnknownMapIsAClearError) {
  TempDir dir;
  const cv::Mat map(30, 30, CV_8UC1, cv::Scalar(128));
  expect_clear_error(run_segment(dir, write_map(dir, "unknown.png", map)), "no free space");
}

TEST(ExtremeMaps, SingleFreePixel) {
  TempDir dir;
  cv::Mat map(9, 9, CV_8UC1, cv::Scalar(0));
  map.at<std::uint8_t>(4, 4) = 255;
  expect_clean(run_segment(dir, write_map(dir, "one.png", map)), map);
  // Without a minimum area the single cell is a room of its own.
  TempDir dir2;
  const cv::Mat labels = expect_clean(run_segment(dir2, write_map(dir2, "one.png", map), {"--min-room-area", "0"}), map);
  expect_every_free_cell_labelled(labels, map);
}

TEST(ExtremeMaps, SingleFreePixelOnTheBorderOfAnUnknownMap) {
  TempDir dir;
  cv::Mat map(5, 7, CV_8UC1, cv::Scalar(128));
  map.at<std::uint8_t>(0, 6) = 255;
  const cv::Mat labels = expect_clean(run_segment(dir, write_map(dir, "corner.png", map), {"--min-room-area", "0"}), map);
  expect_every_free_cell_labelled(labels, map);
}

TEST(ExtremeMaps, CheckerboardOfSinglePixels) {
  // Free cells touch only diagonally: every free component is one pixel with 8-connected pinches.
  TempDir dir;
  cv::Mat map(40, 40, CV_8UC1);
  for (int r = 0; r < map.rows; ++r)
    for (int c = 0; c < map.cols; ++c) map.at<std::uint8_t>(r, c) = (r + c) % 2 ? 255 : 0;
  expect_clean(run_segment(dir, write_map(dir, "checker.png", map)), map);
  TempDir dir2;
  const cv::Mat labels = expect_clean(run_segment(dir2, write_map(dir2, "checker.png", map), {"--min-room-area", "0"}), map);
  expect_every_free_cell_labelled(labels, map);
}

TEST(ExtremeMaps, CheckerboardOfBlocks) {
  TempDir dir;
  cv::Mat map(64, 64, CV_8UC1);
  for (int r = 0; r < map.rows; ++r)
    for (int c = 0; c < map.cols; ++c) map.at<std::uint8_t>(r, c) = (r / 4 + c / 4) % 2 ? 255 : 0;
  const cv::Mat labels = expect_clean(run_segment(dir, write_map(dir, "blocks.png", map), {"--min-room-area", "0"}), map);
  expect_every_free_cell_labelled(labels, map);
}

TEST(ExtremeMaps, ThousandsOfTinyObstacles) {
  TempDir dir;
  cv::Mat map(300, 300, CV_8UC1, cv::Scalar(255));
  std::mt19937 random(7);
  std::uniform_int_distribution<int> cell(0, 299);
  for (int i = 0; i < 3000; ++i) map.at<std::uint8_t>(cell(random), cell(random)) = 0;
  // Tiny holes are below the default hole area and ignored; keeping them all must work as well.
  for (const std::string hole_area : {"0.05", "0"}) {
    TempDir run_dir;
    const cv::Mat labels = expect_clean(run_segment(run_dir, write_map(run_dir, "dots.png", map), {"--min-hole-area", hole_area}), map);
    expect_every_free_cell_labelled(labels, map);
  }
}

TEST(ExtremeMaps, FreeSpaceTouchingEveryBorder) {
  // A plus-shaped corridor system that leaves the image on all four sides.
  TempDir dir;
  cv::Mat map(120, 160, CV_8UC1, cv::Scalar(0));
  map(cv::Rect(70, 0, 20, 120)).setTo(255);
  map(cv::Rect(0, 50, 160, 20)).setTo(255);
  const cv::Mat labels = expect_clean(run_segment(dir, write_map(dir, "plus.png", map)), map);
  expect_every_free_cell_labelled(labels, map);
}

TEST(ExtremeMaps, OneRowAndOneColumnImages) {
  for (const cv::Size size : {cv::Size(200, 1), cv::Size(1, 200), cv::Size(1, 1)}) {
    TempDir dir;
    const cv::Mat map(size, CV_8UC1, cv::Scalar(255));
    const cv::Mat labels = expect_clean(run_segment(dir, write_map(dir, "thin.png", map), {"--min-room-area", "0"}), map);
    expect_every_free_cell_labelled(labels, map);
  }
}

TEST(ExtremeMaps, NonSquareResolutionIsAClearError) {
  for (const std::string resolution : {"[0.05, 0.1]", "0.05 0.1", "[0.05]", "{x: 0.05, y: 0.1}"}) {
    TempDir dir;
    topocut::testing::write_test_image(dir.file("map.png"), cv::Mat(10, 10, CV_8UC1, cv::Scalar(255)));
    const std::string yaml =
        dir.write("map.yaml", "image: map.png\nresolution: " + resolution + "\norigin: [0.0, 0.0, 0.0]\n");
    SCOPED_TRACE(resolution);
    expect_clear_error(run_segment(dir, yaml), "resolution");
  }
}

TEST(ExtremeMaps, NotAnImageIsAClearError) {
  TempDir dir;
  const std::string path = dir.write("garbage.png", std::string("\x89PNG\r\n\x1a\n garbage", 17));
  expect_clear_error(run_segment(dir, path), "garbage.png");
}

}  // namespace
