#include "topocut/io/map_loader.h"

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <zlib.h>

#include "io/temp_dir.h"
#include "topocut/core/error.h"
#include "topocut/io/image_codec.h"

namespace topocut {
namespace {

using testing::TempDir;

// Cells of a one-row grey image of `values` under the given ROS metadata.
std::vector<int> ros_row(const std::vector<int>& values, const RosMapMetadata& m) {
  cv::Mat grey(1, static_cast<int>(values.size()), CV_32FC1);
  for (std::size_t i = 0; i < values.size(); ++i) grey.at<float>(0, static_cast<int>(i)) = static_cast<float>(values[i]);
  const cv::Mat cells = ros_cells(grey, cv::Mat::zeros(grey.size(), CV_8UC1), m);
  std::vector<int> out;
  for (int c = 0; c < cells.cols; ++c) out.push_back(cells.at<unsigned char>(0, c));
  return out;
}

constexpr int F = kFree, O = kOccupied, U = kUnknown;

TEST(RosSemantics, TrinaryThresholdsByHand) {
  RosMapMetadata m;  // occupied 0.65, free 0.196
  // p = (255 - v) / 255: v=0 -> 1 (occ); 89 -> 0.65098 (occ); 90 -> 0.6471 (unk); 205 -> 0.196078 (unk,
  // not below 0.196); 206 -> 0.19216 (free); 255 -> 0 (free).
  EXPECT_EQ(ros_row({0, 89, 90, 205, 206, 255}, m), (std::vector<int>{O, O, U, U, F, F}));
}

TEST(RosSemantics, NegateFlipsTheShade) {
  RosMapMetadata m;
  m.negate = true;
  // p = v / 255: 255 -> occ; 166 -> 0.651 (occ); 165 -> 0.647 (unk); 50 -> 0.196078 (unk); 49 -> free; 0 -> free.
  EXPECT_EQ(ros_row({255, 166, 165, 50, 49, 0}, m), (std::vector<int>{O, O, U, U, F, F}));
}

TEST(RosSemantics, ScaleModeKeepsTheMiddleBandUnknown) {
  RosMapMetadata m;
  m.mode = RosMapMode::kScale;
  m.occupied_thresh = 0.9;
  m.free_thresh = 0.1;
  // p: 0 -> 1 (occ); 25 -> 0.902 (occ); 26 -> 0.898 (unk); 128 -> 0.498 (unk); 230 -> 0.098 (free); 229 -> 0.102 (unk).
  EXPECT_EQ(ros_row({0, 25, 26, 128, 230, 229}, m), (std::vector<int>{O, O, U, U, F, U}));
}

TEST(RosSemantics, RawModeReadsPercentages) {
  RosMapMetadata m;
  m.mode = RosMapMode::kRaw;
  // p = v / 100: 0 free; 19 free; 20 unk; 65 unk (not above 0.65); 66 occ; 100 occ; 101 and 255 unknown.
  EXPECT_EQ(ros_row({0, 19, 20, 65, 66, 100, 101, 255}, m), (std::vector<int>{F, F, U, U, O, O, U, U}));
  m.negate = true;  // v' = 255 - v
  EXPECT_EQ(ros_row({255, 155, 0}, m), (std::vector<int>{F, O, U}));
}

// Whole levels are looked up, a colour image's channel means are worked out: both as map_server.
TEST(RosSemantics, ChannelMeansBetweenLevelsReadAsMapServerReadsThem) {
  // p = (255 - v) / 255: 205 -> 0.196078 (unk); 205.333 (205, 205, 206) -> 0.19477 (free); 89 -> 0.65098
  // (occ); 89.667 (89, 90, 90) -> 0.64837 (unk). Alone, the whole ones take the looked-up path.
  cv::Mat grey = (cv::Mat_<float>(1, 4) << 205.0f, 616.0f / 3.0f, 89.0f, 269.0f / 3.0f);
  cv::Mat cells = ros_cells(grey, cv::Mat::zeros(grey.size(), CV_8UC1), RosMapMetadata{});
  EXPECT_EQ(cv::countNonZero(cells != (cv::Mat_<unsigned char>(1, 4) << U, F, O, U)), 0);
  grey = (cv::Mat_<float>(1, 2) << 205.0f, 89.0f);
  cells = ros_cells(grey, (cv::Mat_<unsigned char>(1, 2) << 0, 255), RosMapMetadata{});
  EXPECT_EQ(cv::countNonZero(cells != (cv::Mat_<unsigned char>(1, 2) << U, U)), 0);
  EXPECT_EQ(ros_row({205, 89}, RosMapMetadata{}), (std::vector<int>{U, O}));
}

TEST(RosSemantics, TransparentPixelsAreUnknown) {
  cv::Mat grey(1, 2, CV_32FC1, cv::Scalar(255));
  cv::Mat transparent = (cv::Mat_<unsigned char>(1, 2) << 255, 0);
  const cv::Mat cells = ros_cells(grey, transparent, RosMapMetadata{});
  EXPECT_EQ(cells.at<unsigned char>(0, 0), kUnknown);
  EXPECT_EQ(cells.at<unsigned char>(0, 1), kFree);
}

TEST(ParseYaml, ReadsEveryField) {
  const RosMapMetadata m = parse_ros_map_yaml(
      "image: maps/a.pgm\nresolution: 0.1\norigin: [-3.5, 2.25, 0.5]\nnegate: 1\n"
      "occupied_thresh: 0.7\nfree_thresh: 0.2\nmode: raw\n",
      "a.yaml");
  EXPECT_EQ(m.image, "maps/a.pgm");
  EXPECT_DOUBLE_EQ(m.resolution, 0.1);
  EXPECT_DOUBLE_EQ(m.origin.x, -3.5);
  EXPECT_DOUBLE_EQ(m.origin.y, 2.25);
  EXPECT_DOUBLE_EQ(m.yaw, 0.5);
  EXPECT_TRUE(m.negate);
  EXPECT_DOUBLE_EQ(m.occupied_thresh, 0.7);
  EXPECT_DOUBLE_EQ(m.free_thresh, 0.2);
  EXPECT_EQ(m.mode, RosMapMode::kRaw);
}

TEST(ParseYaml, OptionalFieldsTakeMapSaverDefaults) {
  const RosMapMetadata m = parse_ros_map_yaml("image: a.png\nresolution: 0.05\norigin: [0, 0, 0]\n", "a.yaml");
  EXPECT_FALSE(m.negate);
  EXPECT_DOUBLE_EQ(m.occupied_thresh, 0.65);
  EXPECT_DOUBLE_EQ(m.free_thresh, 0.196);
  EXPECT_EQ(m.mode, RosMapMode::kTrinary);
}

// The message must name the field that is wrong.
void expect_yaml_error(const std::string& text, const std::string& fragment) {
  try {
    parse_ros_map_yaml(text, "bad.yaml");
    ADD_FAILURE() << "no error for: " << text;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.yaml"), std::string::npos) << e.what();
  }
}

TEST(ParseYaml, RejectsMissingAndWrongFields) {
  const std::string ok_rest = "resolution: 0.05\norigin: [0, 0, 0]\n";
  expect_yaml_error(ok_rest, "'image'");
  expect_yaml_error("image: a.png\norigin: [0, 0, 0]\n", "'resolution'");
  expect_yaml_error("image: a.png\nresolution: 0.05\n", "'origin'");
  expect_yaml_error("image: a.png\nresolution: 0\norigin: [0, 0, 0]\n", "'resolution'");
  expect_yaml_error("image: a.png\nresolution: -1\norigin: [0, 0, 0]\n", "'resolution'");
  expect_yaml_error("image: a.png\nresolution: .nan\norigin: [0, 0, 0]\n", "'resolution'");
  expect_yaml_error("image: a.png\nresolution: fine\norigin: [0, 0, 0]\n", "'resolution'");
  expect_yaml_error("image: a.png\nresolution: 0.05\norigin: [0, 0, 0, 0]\n", "'origin'");
  expect_yaml_error("image: a.png\nresolution: 0.05\norigin: [a, 0, 0]\n", "'origin'");
  expect_yaml_error("image: a.png\n" + ok_rest + "mode: fuzzy\n", "'mode'");
  expect_yaml_error("image: a.png\n" + ok_rest + "occupied_thresh: 1.5\n", "'occupied_thresh'");
  expect_yaml_error("image: a.png\n" + ok_rest + "free_thresh: -0.1\n", "'free_thresh'");
  expect_yaml_error("image: a.png\n" + ok_rest + "free_thresh: 0.8\noccupied_thresh: 0.6\n", "'free_thresh'");
  expect_yaml_error("image: a.png\n" + ok_rest + "negate: 7\n", "'negate'");
  expect_yaml_error("image: [a, b]\n" + ok_rest, "'image'");
  expect_yaml_error("just a string", "map_server");
  expect_yaml_error("image: [unclosed\n", "not valid YAML");
}

TEST(LoadMap, YamlImageIsRelativeToTheYamlFolder) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "sub");
  cv::Mat image = (cv::Mat_<unsigned char>(2, 3) << 0, 205, 254, 255, 100, 0);
  ASSERT_TRUE(cv::imwrite(dir.file("sub/m.pgm"), image));
  dir.write("sub/m.yaml", "image: m.pgm\nresolution: 0.1\norigin: [1.0, -2.0, 0.0]\nnegate: 0\n"
                          "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const OccupancyGrid grid = load_map(dir.file("sub/m.yaml"));
  EXPECT_DOUBLE_EQ(grid.resolution, 0.1);
  EXPECT_DOUBLE_EQ(grid.origin.x, 1.0);
  EXPECT_DOUBLE_EQ(grid.origin.y, -2.0);
  // 100 -> p = 0.608: unknown.
  const cv::Mat expected = (cv::Mat_<unsigned char>(2, 3) << O, U, F, F, U, O);
  EXPECT_EQ(cv::countNonZero(grid.cells != expected), 0);
}

TEST(LoadMap, PlainImagesUseTheImageThresholds) {
  TempDir dir;
  cv::Mat image = (cv::Mat_<unsigned char>(1, 6) << 0, 49, 50, 250, 251, 255);
  ASSERT_TRUE(cv::imwrite(dir.file("m.png"), image));
  MapLoadOptions options;
  options.resolution = 0.025;
  options.detect_palette = false;
  const OccupancyGrid grid = load_map(dir.file("m.png"), options);
  EXPECT_DOUBLE_EQ(grid.resolution, 0.025);
  const cv::Mat expected = (cv::Mat_<unsigned char>(1, 6) << O, O, U, U, F, F);
  EXPECT_EQ(cv::countNonZero(grid.cells != expected), 0);
}

TEST(LoadMap, ColourAndAlphaChannels) {
  TempDir dir;
  // BGRA: white opaque, white transparent, black opaque, (255,255,0) opaque -> mean 170 -> unknown.
  cv::Mat image(1, 4, CV_8UC4);
  image.at<cv::Vec4b>(0, 0) = {255, 255, 255, 255};
  image.at<cv::Vec4b>(0, 1) = {255, 255, 255, 0};
  image.at<cv::Vec4b>(0, 2) = {0, 0, 0, 255};
  image.at<cv::Vec4b>(0, 3) = {255, 255, 0, 255};
  ASSERT_TRUE(cv::imwrite(dir.file("rgba.png"), image));
  const OccupancyGrid grid = load_map(dir.file("rgba.png"));
  const cv::Mat expected = (cv::Mat_<unsigned char>(1, 4) << F, U, O, U);
  EXPECT_EQ(cv::countNonZero(grid.cells != expected), 0);
}

TEST(LoadMap, SixteenBitGreyIsScaled) {
  TempDir dir;
  cv::Mat image = (cv::Mat_<unsigned short>(1, 3) << 65535, 0, 30000);
  ASSERT_TRUE(cv::imwrite(dir.file("g16.png"), image));
  const OccupancyGrid grid = load_map(dir.file("g16.png"));
  const cv::Mat expected = (cv::Mat_<unsigned char>(1, 3) << F, O, U);
  EXPECT_EQ(cv::countNonZero(grid.cells != expected), 0);
}

// Rows of runs of equal pixels of every length around the eight the levels compare at once, in
// RGBA, RGB and 16-bit RGBA: every pixel's level is its rounded channel mean and its transparency
// alpha below half, as a pixel-by-pixel reading gives.
TEST(LoadMap, LevelsOfRunsOfEqualPixels) {
  std::mt19937 random(36);
  for (const int type : {CV_8UC4, CV_8UC3, CV_16UC4}) {
    cv::Mat image(5, 61, type);
    const int top = CV_MAT_DEPTH(type) == CV_8U ? 255 : 65535;
    for (int r = 0; r < image.rows; ++r) {
      std::vector<double> colour(4);
      for (int c = 0, left = 0; c < image.cols; ++c, --left) {
        if (left == 0) {  // a new run of 1 to 18 pixels
          left = 1 + static_cast<int>(random() % 18);
          for (double& v : colour) v = static_cast<double>(random() % 2 ? top : random() % (top + 1));
        }
        for (int k = 0; k < image.channels(); ++k) {
          if (CV_MAT_DEPTH(type) == CV_8U) image.ptr<unsigned char>(r)[c * image.channels() + k] = cv::saturate_cast<unsigned char>(colour[k]);
          else image.ptr<unsigned short>(r)[c * image.channels() + k] = cv::saturate_cast<unsigned short>(colour[k]);
        }
      }
    }
    cv::Mat levels, transparent;
    decode_map_levels(encode_image(image, ".png"), "runs.png", levels, transparent);
    ASSERT_EQ(levels.size(), image.size());
    const double scale = CV_MAT_DEPTH(type) == CV_8U ? 1.0 : 255.0 / 65535.0;
    for (int r = 0; r < image.rows; ++r)
      for (int c = 0; c < image.cols; ++c) {
        double sum = 0.0, alpha = top;
        for (int k = 0; k < 3; ++k) sum += CV_MAT_DEPTH(type) == CV_8U ? image.ptr<unsigned char>(r)[c * image.channels() + k]
                                                                       : image.ptr<unsigned short>(r)[c * image.channels() + k];
        if (image.channels() == 4)
          alpha = CV_MAT_DEPTH(type) == CV_8U ? image.ptr<unsigned char>(r)[c * 4 + 3] : image.ptr<unsigned short>(r)[c * 4 + 3];
        ASSERT_EQ(levels.at<unsigned char>(r, c), cv::saturate_cast<unsigned char>(sum * scale / 3)) << r << ", " << c;
        ASSERT_EQ(transparent.at<unsigned char>(r, c), alpha < (top + 1) / 2 ? 255 : 0) << r << ", " << c;
      }
  }
}

// OpenCV cannot write grey+alpha PNGs, so this builds one by hand (PNG colour type 4).
std::string grey_alpha_png(int width, int height, const std::vector<unsigned char>& grey_alpha) {
  auto u32 = [](std::string& s, unsigned v) {
    for (int shift = 24; shift >= 0; shift -= 8) s += static_cast<char>((v >> shift) & 0xff);
  };
  auto chunk = [&](std::string& png, const std::string& type, const std::string& data) {
    u32(png, static_cast<unsigned>(data.size()));
    const std::string body = type + data;
    png += body;
    u32(png, static_cast<unsigned>(crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
  };
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string ihdr;
  u32(ihdr, static_cast<unsigned>(width));
  u32(ihdr, static_cast<unsigned>(height));
  ihdr += std::string("\x08\x04\x00\x00\x00", 5);  // 8 bit, grey+alpha, deflate, no filter, no interlace
  chunk(png, "IHDR", ihdr);
  std::string raw;
  for (int r = 0; r < height; ++r) {
    raw += '\0';  // filter type none
    for (int i = 0; i < 2 * width; ++i) raw += static_cast<char>(grey_alpha[static_cast<std::size_t>(r * 2 * width + i)]);
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string compressed(size, '\0');
  compress(reinterpret_cast<Bytef*>(compressed.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
           static_cast<uLong>(raw.size()));
  compressed.resize(size);
  chunk(png, "IDAT", compressed);
  chunk(png, "IEND", "");
  return png;
}

TEST(LoadMap, GreyPlusAlphaPng) {
  TempDir dir;
  // (grey, alpha): white opaque, white transparent, black opaque, mid-grey opaque.
  const std::string path = dir.write("ga.png", grey_alpha_png(4, 1, {255, 255, 255, 0, 0, 255, 128, 255}));
  const OccupancyGrid grid = load_map(path);
  ASSERT_EQ(grid.width(), 4);
  const cv::Mat expected = (cv::Mat_<unsigned char>(1, 4) << F, U, O, U);
  EXPECT_EQ(cv::countNonZero(grid.cells != expected), 0);
}

TEST(LoadMap, BormannGreyAlphaMap) {
  const std::string path = std::string(TOPOCUT_SHARED_DIR "/datasets/bormann/Freiburg52_scan.png");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared Bormann dataset not found at " << path;
  MapLoadOptions fixed;
  fixed.detect_palette = false;
  const OccupancyGrid grid = load_map(path, fixed);
  EXPECT_EQ(grid.width(), 643);
  EXPECT_EQ(grid.height(), 354);
  // Counted independently from the PNG's grey channel: 142381 pixels > 250 and 167 pixels < 50.
  EXPECT_EQ(cv::countNonZero(grid.cells == kFree), 142381);
  EXPECT_EQ(cv::countNonZero(grid.cells == kOccupied), 167);
  EXPECT_EQ(cv::countNonZero(grid.cells == kUnknown), 643 * 354 - 142381 - 167);
  // The detected palette (free 255, the drawing's greys not free) frees exactly the same cells.
  const OccupancyGrid detected = load_map(path);
  EXPECT_EQ(cv::countNonZero((detected.cells == kFree) != (grid.cells == kFree)), 0);
}

void expect_load_error(const std::string& path, const std::string& fragment, const MapLoadOptions& options = {}) {
  try {
    load_map(path, options);
    ADD_FAILURE() << "no error for " << path;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(LoadMap, BadInputGivesOneClearError) {
  TempDir dir;
  expect_load_error(dir.file("missing.png"), "does not exist");
  expect_load_error(dir.write("text.png", "this is not an image"), "as an image");
  expect_load_error(dir.write("empty.png", ""), "empty");
  expect_load_error(dir.write("noimage.yaml", "image: gone.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"), "gone.pgm");
  expect_load_error(dir.write("bad.yaml", "image: x.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nmode: fancy\n"), "'mode'");
  expect_load_error(dir.path().string(), "directory");
  ASSERT_TRUE(cv::imwrite(dir.file("ok.png"), cv::Mat(2, 2, CV_8UC1, cv::Scalar(255))));
  MapLoadOptions bad;
  bad.resolution = 0.0;
  expect_load_error(dir.file("ok.png"), "resolution", bad);
  bad.resolution = std::nan("");
  expect_load_error(dir.file("ok.png"), "resolution", bad);
}

}  // namespace
}  // namespace topocut
