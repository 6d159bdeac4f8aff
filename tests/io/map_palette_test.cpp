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

}  // namespace
}  // namespace topocut
