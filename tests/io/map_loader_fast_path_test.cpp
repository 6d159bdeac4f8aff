// load_map() reads a plain image's levels in one pass (the grey image itself when it has one 8-bit
// channel); it must agree cell for cell with the rounded channel mean of decode_map_image() put
// through the same palette, for every channel layout.
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "io/temp_dir.h"
#include "topocut/core/input_file.h"
#include "topocut/io/map_loader.h"

namespace topocut {
namespace {

using testing::TempDir;

// Every channel value near the thresholds, in every combination, plus random pixels.
cv::Mat test_image(int channels) {
  std::vector<int> near;
  for (int v = 45; v <= 55; ++v) near.push_back(v);
  for (int v = 246; v <= 255; ++v) near.push_back(v);
  std::mt19937 rng(7);
  const int colour = channels == 2 || channels == 4 ? channels - 1 : channels;
  std::vector<cv::Vec4b> pixels;
  if (colour == 1) {
    for (int v = 0; v < 256; ++v) pixels.push_back({static_cast<unsigned char>(v), 0, 0, 0});
  } else {
    for (int a : near)
      for (int b : near)
        for (int c : near) pixels.push_back({static_cast<unsigned char>(a), static_cast<unsigned char>(b), static_cast<unsigned char>(c), 0});
  }
  for (int k = 0; k < 2000; ++k)
    pixels.push_back({static_cast<unsigned char>(rng()), static_cast<unsigned char>(rng()), static_cast<unsigned char>(rng()), 0});
  cv::Mat image(1, static_cast<int>(pixels.size()), CV_8UC(channels));
  for (int i = 0; i < image.cols; ++i) {
    unsigned char* px = image.ptr<unsigned char>(0) + static_cast<std::size_t>(i) * channels;
    for (int k = 0; k < colour; ++k) px[k] = pixels[static_cast<std::size_t>(i)][k];
    if (colour < channels) px[channels - 1] = static_cast<unsigned char>(i % 3 == 0 ? 127 : (i % 3 == 1 ? 128 : 255));
  }
  return image;
}

TEST(LoadMapFastPath, AgreesWithTheGeneralPathForEveryChannelLayout) {
  const TempDir dir;
  for (const int channels : {1, 3, 4}) {  // OpenCV writes no grey+alpha PNG; GreyPlusAlphaPng covers it
    SCOPED_TRACE(channels);
    const std::string path = dir.file("map" + std::to_string(channels) + ".png");
    ASSERT_TRUE(cv::imwrite(path, test_image(channels)));
    for (const int free_min : {250, 200}) {
      MapLoadOptions options;
      options.free_min = free_min;
      options.detect_palette = false;
      const OccupancyGrid grid = load_map(path, options);
      cv::Mat grey, transparent, levels;
      decode_map_image(read_input_file(path, "map image", 1ull << 26), path, grey, transparent);
      grey.convertTo(levels, CV_8U);  // rounds to the nearest level, as load_map does
      const cv::Mat expected = plain_image_cells(levels, transparent, threshold_palette(free_min, options.occupied_max));
      ASSERT_EQ(grid.cells.size(), expected.size());
      EXPECT_EQ(cv::countNonZero(grid.cells != expected), 0);
    }
  }
}

}  // namespace
}  // namespace topocut
