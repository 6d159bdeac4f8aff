// The palette of a plain map image read from the image itself: the palettes of the map tools people
// use (drawings, SLAM images with grey walls, black or grey unknown, map_server PGMs) come out right.
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/temp_dir.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/io/map_loader.h"
#include "topocut/io/map_palette.h"

namespace topocut {
namespace {

using testing::TempDir;

// A 100 x 80 map: `outside` around a room of `free` with a wall ring of `wall`, partly observed greys.
cv::Mat slam_map(unsigned char outside, unsigned char wall, unsigned char free) {
  cv::Mat map(80, 100, CV_8UC1, cv::Scalar(outside));
  cv::rectangle(map, cv::Rect(10, 10, 80, 60), cv::Scalar(wall), cv::FILLED);
  cv::rectangle(map, cv::Rect(13, 13, 74, 54), cv::Scalar(free), cv::FILLED);
  // A few anti-aliased and partly observed levels, too rare to be modes.
  for (int i = 0; i < 20; ++i) map.at<unsigned char>(40, 20 + i) = static_cast<unsigned char>(free - 3 * i - 6);
  return map;
}

MapPalette detect(const cv::Mat& levels) { return detect_palette(levels, cv::Mat::zeros(levels.size(), CV_8UC1), 250, 50); }

TEST(MapPalette, GreyWallsLightGreyUnknown) {
  const MapPalette p = detect(slam_map(230, 127, 255));  // intel-style
  EXPECT_EQ(p.state[255], kFree);
  EXPECT_EQ(p.state[230], kUnknown);
  EXPECT_EQ(p.state[127], kOccupied);
  EXPECT_EQ(p.state[245], kUnknown);  // partly observed: never free
  EXPECT_EQ(p.state[251], kFree);
  EXPECT_NE(p.description.find("unknown 230"), std::string::npos);
}

TEST(MapPalette, BlackUnknownGreyWalls) {
  const MapPalette p = detect(slam_map(0, 127, 255));
  EXPECT_EQ(p.state[0], kUnknown);
  EXPECT_EQ(p.state[127], kOccupied);
  EXPECT_EQ(p.state[255], kFree);
}

TEST(MapPalette, MapServerPgm) {
  const MapPalette p = detect(slam_map(205, 0, 254));
  EXPECT_EQ(p.state[254], kFree);
  EXPECT_EQ(p.state[205], kUnknown);
  EXPECT_EQ(p.state[0], kOccupied);
}

TEST(MapPalette, ALargeUnexploredSurroundingChangesNothing) {
  // gmapping's default map is 4000 x 4000 cells, with the building in a small part of it: the walls
  // are far fewer than half a percent of all cells, but as many of the cells that are not unknown.
  // Before the share ignored the border's level, this map's walls read as unknown.
  const cv::Mat map = slam_map(205, 0, 254);
  cv::Mat wide;
  cv::copyMakeBorder(map, wide, 900, 1020, 1300, 1600, cv::BORDER_CONSTANT, cv::Scalar(205));
  ASSERT_LT(cv::countNonZero(wide == 0), wide.total() / 200);
  const MapPalette small = detect(map), large = detect(wide);
  EXPECT_EQ(large.state, small.state);
  EXPECT_EQ(large.state[0], kOccupied);
  EXPECT_EQ(large.description, small.description);
}

TEST(MapPalette, TwoModes) {
  // A drawing: black on white; the black is walls. A SLAM map with walls the colour of unknown.
  EXPECT_EQ(detect(slam_map(0, 0, 255)).state[0], kOccupied);
  const MapPalette grey = detect(slam_map(153, 153, 255));
  EXPECT_EQ(grey.state[153], kUnknown);
  EXPECT_EQ(grey.state[255], kFree);
  EXPECT_EQ(grey.state[250], kUnknown);  // Bormann's rule: > 250 is free
}

TEST(MapPalette, NoReadablePaletteFallsBackToTheThresholds) {
  const MapPalette one = detect(cv::Mat(20, 20, CV_8UC1, cv::Scalar(200)));
  const MapPalette fixed = threshold_palette(250, 50);
  EXPECT_EQ(one.state, fixed.state);
  EXPECT_NE(one.description.find("fixed"), std::string::npos);
  // Transparent pixels are not counted: an all-transparent image has no modes either.
  const cv::Mat levels = slam_map(230, 127, 255);
  EXPECT_EQ(detect_palette(levels, cv::Mat(levels.size(), CV_8UC1, cv::Scalar(255)), 250, 50).state, fixed.state);
}

TEST(LoadMap, PaletteFromTheImageFindsFreeSpaceTheThresholdsMiss) {
  TempDir dir;
  // Free space written as 240 (a lighter tool's palette): "> 250" sees no free cell at all.
  ASSERT_TRUE(cv::imwrite(dir.file("m.png"), slam_map(128, 40, 240)));
  std::string palette;
  const OccupancyGrid grid = load_map(dir.file("m.png"), {}, &palette);
  EXPECT_EQ(cv::countNonZero(grid.cells == kFree), 74 * 54 - 20);  // the partly observed greys are not free
  EXPECT_EQ(cv::countNonZero(grid.cells(cv::Rect(10, 10, 80, 3)) == kOccupied), 80 * 3);
  EXPECT_NE(palette.find("detected"), std::string::npos);
  MapLoadOptions fixed;
  fixed.detect_palette = false;
  EXPECT_EQ(cv::countNonZero(load_map(dir.file("m.png"), fixed).cells == kFree), 0);
}

// A map of long runs (what the blocks of 16 equal cells are counted and written at once for), some
// rows broken up and a few transparent patches.
cv::Mat runs_map(cv::RNG& rng, int rows, int cols) {
  cv::Mat map = slam_map(205, 0, 254);
  cv::resize(map, map, cv::Size(cols, rows), 0, 0, cv::INTER_NEAREST);
  for (int k = 0; k < rows; ++k) map.at<unsigned char>(rng.uniform(0, rows), rng.uniform(0, cols)) = static_cast<unsigned char>(rng.uniform(0, 256));
  return map;
}

TEST(MapPalette, CountingBlocksOfEqualLevelsChangesNoPalette) {
  cv::RNG rng(8);
  for (const cv::Size size : {cv::Size(100, 80), cv::Size(117, 33), cv::Size(15, 9), cv::Size(1, 40)}) {
    const cv::Mat levels = runs_map(rng, size.height, size.width);
    // The same levels with the inner cells shuffled: the same histogram and border, no runs left.
    cv::Mat shuffled = levels.clone();
    if (levels.rows > 2 && levels.cols > 2) {
      cv::Mat inner = shuffled(cv::Rect(1, 1, levels.cols - 2, levels.rows - 2)).clone().reshape(1, 1);
      cv::randShuffle(inner, 1.0, &rng);
      inner.reshape(1, levels.rows - 2).copyTo(shuffled(cv::Rect(1, 1, levels.cols - 2, levels.rows - 2)));
    }
    EXPECT_EQ(detect(levels).state, detect(shuffled).state) << size;
    cv::Mat transparent = cv::Mat::zeros(levels.size(), CV_8UC1);
    cv::rectangle(transparent, cv::Rect(0, 0, levels.cols / 3 + 1, levels.rows / 2 + 1), cv::Scalar(255), cv::FILLED);
    EXPECT_EQ(detect_palette(levels, transparent, 250, 50).state, detect_palette(shuffled, transparent, 250, 50).state);
  }
}

TEST(MapPalette, CellsAreTheirLevelsLookedUpAndTransparentCellsUnknown) {
  cv::RNG rng(9);
  for (const cv::Size size : {cv::Size(100, 80), cv::Size(117, 33), cv::Size(15, 9), cv::Size(1, 40)}) {
    const cv::Mat levels = runs_map(rng, size.height, size.width);
    cv::Mat transparent = cv::Mat::zeros(levels.size(), CV_8UC1);
    for (int k = 0; k < 30; ++k)
      cv::rectangle(transparent, cv::Rect(rng.uniform(0, size.width), rng.uniform(0, size.height), rng.uniform(1, 20), 1), cv::Scalar(1), cv::FILLED);
    const MapPalette palette = detect(levels);
    cv::Mat expected;
    cv::LUT(levels, cv::Mat(1, 256, CV_8UC1, const_cast<unsigned char*>(palette.state.data())), expected);
    expected.setTo(kUnknown, transparent);
    EXPECT_EQ(cv::countNonZero(plain_image_cells(levels, transparent, palette) != expected), 0) << size;
  }
}

}  // namespace
}  // namespace topocut
