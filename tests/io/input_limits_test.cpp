// Bounded inputs (issue 12): regular files only, byte limits, image formats by magic bytes and
// pixel limits from the header, the streaming CARMEN reader's bounds, and the value ranges.
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <zlib.h>

#include "io/error_text.h"
#include "io/temp_dir.h"
#include "topocut/core/error.h"
#include "topocut/core/input_file.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/value_ranges.h"
#include "topocut/io/carmen_log.h"
#include "topocut/io/image_input.h"
#include "topocut/io/map_loader.h"

namespace topocut {
namespace {

using testing::TempDir;

using testing::error_of;

std::string encoded(const cv::Mat& image, const std::string& extension) {
  std::vector<unsigned char> bytes;
  EXPECT_TRUE(cv::imencode(extension, image, bytes)) << extension;
  return std::string(bytes.begin(), bytes.end());
}

TEST(InputFile, OnlyRegularFilesAreRead) {
  const TempDir dir;
  EXPECT_EQ(read_input_file(dir.write("a.txt", "hello"), "text", 100), "hello");
  ASSERT_EQ(::mkfifo(dir.file("fifo").c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NE(error_of([&] { read_input_file(dir.file("fifo"), "text", 100); }).find("not a regular file"), std::string::npos);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));  // refused, not waited on
  EXPECT_NE(error_of([&] { read_input_file("/dev/zero", "text", 100); }).find("not a regular file"), std::string::npos);
  EXPECT_NE(error_of([&] { read_input_file(dir.path().string(), "text", 100); }).find("directory"), std::string::npos);
  EXPECT_NE(error_of([&] { read_input_file(dir.file("gone"), "text", 100); }).find("no such file"), std::string::npos);
  EXPECT_NE(error_of([&] { require_regular_file("/dev/null", "log"); }).find("not a regular file"), std::string::npos);
}

TEST(InputFile, ByteLimitNamesTheLimit) {
  const TempDir dir;
  const std::string path = dir.write("big.txt", std::string(2048, 'x'));
  EXPECT_EQ(read_input_file(path, "text", 2048).size(), 2048u);
  EXPECT_NE(error_of([&] { read_input_file(path, "text", 1024); }).find("limit of 1 KiB"), std::string::npos);
  EXPECT_EQ(byte_size_text(16u << 20), "16 MiB");
  EXPECT_EQ(byte_size_text(1000), "1000 bytes");
}

TEST(ImageInput, HeadersGiveTheSizeOfEveryAcceptedFormat) {
  const cv::Mat image(37, 53, CV_8UC1, cv::Scalar(200));
  const std::pair<const char*, ImageFormat> formats[] = {{".png", ImageFormat::kPng},   {".pgm", ImageFormat::kNetpbm},
                                                         {".ppm", ImageFormat::kNetpbm}, {".jpg", ImageFormat::kJpeg},
                                                         {".bmp", ImageFormat::kBmp},   {".tif", ImageFormat::kTiff}};
  for (const auto& [extension, format] : formats) {
    cv::Mat input = image;
    if (std::string(extension) == ".ppm") cv::cvtColor(image, input, cv::COLOR_GRAY2BGR);
    const ImageHeader header = read_image_header(encoded(input, extension), extension);
    EXPECT_EQ(header.format, format) << extension;
    EXPECT_EQ(header.width, 53u) << extension;
    EXPECT_EQ(header.height, 37u) << extension;
    EXPECT_EQ(decode_image(encoded(input, extension), extension, {}).size(), image.size()) << extension;
  }
  EXPECT_EQ(read_image_header("P5\n# a comment\n 7 9\n255\n", "c.pgm").height, 9u);
}

TEST(ImageInput, OtherFormatsAndBrokenHeadersAreRefused) {
  std::string dicom(128, '\0');
  dicom += "DICM";
  EXPECT_NE(error_of([&] { read_image_header(dicom, "d"); }).find("not PNG, PGM/PPM, JPEG, BMP or TIFF"), std::string::npos);
  EXPECT_NE(error_of([&] { read_image_header("#?RADIANCE\n", "h"); }).find("not PNG"), std::string::npos);
  EXPECT_NE(error_of([&] { read_image_header("RIFF....WEBP", "w"); }).find("not PNG"), std::string::npos);
  EXPECT_NE(error_of([&] { read_image_header("", "e"); }).find("empty"), std::string::npos);
  EXPECT_NE(error_of([&] { read_image_header("\x89PNG\r\n\x1a\n", "p"); }).find("header is corrupt"), std::string::npos);
  EXPECT_NE(error_of([&] { read_image_header("P5 0 10 255\n", "z"); }).find("empty image"), std::string::npos);
  EXPECT_NE(error_of([&] { read_image_header("\xFF\xD8\xFF\xD9", "j"); }).find("JPEG header"), std::string::npos);
}

TEST(ImageInput, PixelLimitIsCheckedOnTheHeader) {
  std::string png = encoded(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)), ".png");
  for (int i = 0; i < 4; ++i) png[16 + i] = png[20 + i] = static_cast<char>(i == 2 ? 0x75 : i == 3 ? 0x30 : 0);  // 30000
  const ImageHeader header = read_image_header(png, "p");
  EXPECT_EQ(header.width, 30000u);
  const std::string message = error_of([&] { decode_image(png, "p.png", {}); });
  EXPECT_NE(message.find("900 megapixels"), std::string::npos) << message;
  EXPECT_NE(message.find("limit of 100 megapixels"), std::string::npos) << message;
  EXPECT_NE(message.find("--max-megapixels"), std::string::npos) << message;
  EXPECT_NE(error_of([] { validate(ImageLimits{0.0}); }).find("(0, 1000]"), std::string::npos);
  EXPECT_NE(error_of([] { validate(ImageLimits{1e9}); }).find("(0, 1000]"), std::string::npos);
}

TEST(ImageInput, AnExpectedSizeIsCheckedOnTheHeaderBeforeDecoding) {
  // A label image for a 40 x 30 map whose header declares 10000 x 10000 (100 megapixels, within the
  // pixel limit): refused by its header at once, not after 2 GB and seconds of decoding.
  const TempDir dir;
  std::string png = encoded(cv::Mat(30, 40, CV_16UC1, cv::Scalar(1)), ".png");
  for (int i = 0; i < 4; ++i) png[16 + i] = png[20 + i] = static_cast<char>(i == 2 ? 0x27 : i == 3 ? 0x10 : 0);  // 10000
  const std::string path = dir.write("labels.png", png);
  const ExpectedSize map{40, 30, "the map"};
  const auto start = std::chrono::steady_clock::now();
  const std::string message = error_of([&] { read_image(path, "label image", {}, &map); });
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  EXPECT_NE(message.find("is 10000 x 10000 pixels but the map is 40 x 30"), std::string::npos) << message;
  EXPECT_NE(message.find("labels.png"), std::string::npos) << message;
  // The size it must have passes; the header alone can be read without decoding.
  const std::string fine = dir.write("fine.png", encoded(cv::Mat(30, 40, CV_16UC1, cv::Scalar(1)), ".png"));
  EXPECT_EQ(read_image(fine, "label image", {}, &map).size(), cv::Size(40, 30));
  EXPECT_EQ(read_image_size(path, "label image", {}).width, 10000u);
}

TEST(MapLoaderLimits, DevicesAndRangesAreRefusedBeforeDecoding) {
  const TempDir dir;
  cv::imwrite(dir.file("m.png"), cv::Mat(20, 20, CV_8UC1, cv::Scalar(255)));
  const auto load = [&](const std::string& yaml) { return error_of([&] { load_map(dir.write("m.yaml", yaml)); }); };
  EXPECT_NE(load("image: /dev/zero\nresolution: 0.05\norigin: [0, 0, 0]\n").find("not a regular file"), std::string::npos);
  EXPECT_NE(load("image: m.png\nresolution: 1e-12\norigin: [0, 0, 0]\n").find("[0.0001, 1000]"), std::string::npos);
  EXPECT_NE(load("image: m.png\nresolution: 0.05\norigin: [0, -1e10, 0]\n").find("'origin' y"), std::string::npos);
  EXPECT_EQ(load("image: m.png\nresolution: 1000\norigin: [-1e9, 1e9, 0]\n"), "");
  MapLoadOptions options;
  options.resolution = 1e308;
  EXPECT_NE(error_of([&] { load_map(dir.file("m.png"), options); }).find("--resolution"), std::string::npos);
  options.resolution = 0.05;
  options.limits.max_megapixels = 0.0001;  // 100 pixels
  EXPECT_NE(error_of([&] { load_map(dir.file("m.png"), options); }).find("0.0004 megapixels"), std::string::npos);
}

TEST(ValueRanges, MessagesGiveTheRange) {
  EXPECT_EQ(error_of([] { check_resolution(0.05, "r"); }), "");
  EXPECT_EQ(error_of([] { check_resolution(1e308, "the resolution"); }),
            "the resolution must lie in [0.0001, 1000] metres per cell, got 1e+308");
  EXPECT_NE(error_of([] { check_resolution(std::nan(""), "r"); }), "");
  EXPECT_EQ(error_of([] { check_length(0.0, "tau", false); }), "tau must lie in (0, 100000] metres, got 0");
  EXPECT_EQ(error_of([] { check_length(0.0, "radius"); }), "");
  EXPECT_NE(error_of([] { check_area(1e11, "area"); }).find("[0, 1e+10] square metres"), std::string::npos);
  OccupancyGrid grid;
  grid.cells = cv::Mat(2, 2, CV_8UC1, cv::Scalar(kFree));
  grid.resolution = 1e-12;
  EXPECT_NE(error_of([&] { validate(grid); }).find("[0.0001, 1000]"), std::string::npos);
}

std::string gzip_file(const TempDir& dir, const std::string& name, const std::string& unit, std::size_t repeats) {
  gzFile file = gzopen(dir.file(name).c_str(), "wb1");
  for (std::size_t i = 0; i < repeats; ++i) gzwrite(file, unit.data(), static_cast<unsigned>(unit.size()));
  gzclose(file);
  return dir.file(name);
}

TEST(CarmenLimits, GzipIsInflatedAsAStreamWithinBounds) {
  const TempDir dir;
  const std::string line = "FLASER 2 1 2 0 0 0 0 0 0 1 h 1\n";
  // Lines split across the reader's 128 KiB chunks still parse: 20k lines of 31 bytes span five.
  EXPECT_EQ(read_carmen_log(gzip_file(dir, "ok.gz", line, 20000)).scans.size(), 20000u);
  const std::string zeros = gzip_file(dir, "zeros.gz", std::string(1 << 20, '\0'), 8);
  EXPECT_NE(error_of([&] { read_carmen_log(zeros); }).find("longer than 4 MiB"), std::string::npos);
  CarmenReadOptions options;
  options.max_total_beams = 1000;
  EXPECT_NE(error_of([&] { read_carmen_log(dir.file("ok.gz"), options); }).find("ok.gz:501: the log holds more than 1000"),
            std::string::npos);
  options = {};
  options.max_text_bytes = 1 << 20;
  const std::string odometry = gzip_file(dir, "odom.gz", "ODOM 0 0 0 0 0 0 1 h 1\n", 50000);
  EXPECT_NE(error_of([&] { read_carmen_log(odometry, options); }).find("more than 1 MiB of text"), std::string::npos);
  EXPECT_NE(error_of([] { read_carmen_log("/dev/zero"); }).find("not a regular file"), std::string::npos);
}

TEST(CarmenLimits, ValueCountMustMatchTheAnnouncedCount) {
  const std::string good = "FLASER 2 1 2 0 0 0 0 0 0 1 h 1\n";
  EXPECT_EQ(parse_carmen_log(good + "FLASER 2 1 2 0 0 0 0 0 0\n" + "FLASER 2 1 2 0 0 0 0 0 0 1\n").scans.size(), 3u);
  for (const char* bad : {"FLASER 2 1 2 3 0 0 0 0 0 0 1 h 1\n",   // a range more than announced
                          "FLASER 2 1 2 3 4 5 0 0 0 0 0 0\n",      // three more: the pose would be misread
                          "FLASER 2 1 2 0 0 0 0 0 0 1 h\n",        // trailing fields cut
                          "FLASER 2 1 2 0 0 0 0 0 0 1 h 1 9\n"}) {  // one value too many
    const std::string message = error_of([&] { parse_carmen_log(good + bad, "x.log"); });
    EXPECT_NE(message.find("x.log:2: FLASER announces 2 ranges but the line has"), std::string::npos) << bad << message;
  }
}

}  // namespace
}  // namespace topocut
