#include "topocut/io/map_saver.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "io/temp_dir.h"
#include "topocut/core/error.h"
#include "topocut/io/map_loader.h"

namespace topocut {
namespace {

using testing::TempDir;

OccupancyGrid small_grid() {
  OccupancyGrid grid;
  grid.cells = (cv::Mat_<unsigned char>(3, 4) << kOccupied, kOccupied, kOccupied, kOccupied,  //
                kOccupied, kFree, kUnknown, kOccupied,                                          //
                kFree, kFree, kFree, kUnknown);
  grid.resolution = 0.025;
  grid.origin = {-12.5, 3.0625};
  return grid;
}

TEST(SaveMap, YamlAndPgmRoundTrip) {
  TempDir dir;
  const OccupancyGrid grid = small_grid();
  save_map(dir.file("m.yaml"), grid);
  ASSERT_TRUE(std::filesystem::exists(dir.file("m.pgm")));
  const cv::Mat image = cv::imread(dir.file("m.pgm"), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(image.type(), CV_8UC1);
  EXPECT_EQ(image.at<unsigned char>(1, 1), 254);  // map_saver's free value
  EXPECT_EQ(image.at<unsigned char>(1, 2), 205);  // and its unknown value
  const OccupancyGrid back = load_map(dir.file("m.yaml"));
  EXPECT_EQ(cv::countNonZero(back.cells != grid.cells), 0);
  EXPECT_DOUBLE_EQ(back.resolution, grid.resolution);
  EXPECT_DOUBLE_EQ(back.origin.x, grid.origin.x);
  EXPECT_DOUBLE_EQ(back.origin.y, grid.origin.y);
  // No temporary files left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 2);
}

TEST(SaveMap, PngImageOption) {
  TempDir dir;
  MapSaveOptions options;
  options.image_extension = ".png";
  save_map(dir.file("m.yaml"), small_grid(), options);
  EXPECT_TRUE(std::filesystem::exists(dir.file("m.png")));
  EXPECT_EQ(cv::countNonZero(load_map(dir.file("m.yaml")).cells != small_grid().cells), 0);
}

TEST(SaveMap, RejectsBadPathsBeforeWriting) {
  TempDir dir;
  EXPECT_THROW(save_map(dir.file("m.txt"), small_grid()), Error);
  EXPECT_THROW(save_map(dir.file("nodir/m.yaml"), small_grid()), Error);
  OccupancyGrid bad = small_grid();
  bad.resolution = -1.0;
  EXPECT_THROW(save_map(dir.file("m.yaml"), bad), Error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.yaml")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.pgm")));
}

}  // namespace
}  // namespace topocut
