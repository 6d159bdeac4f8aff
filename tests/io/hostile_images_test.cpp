// Images that try to talk the decoders past their limits (issue 28): a size field given twice, a
// decoder asked for a size the header check did not accept, tiles far larger than their image, more
// strips than the limit, a progressive JPEG with more scans than the limit. Each is built here and
// must end in one Error line naming the cause, before the decoder allocates or loops.
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "io/codecs/codecs.h"
#include "io/error_text.h"
#include "io/image_variants.h"
#include "topocut/core/error.h"
#include "topocut/io/image_codec.h"
#include "topocut/io/image_input.h"

namespace topocut {
namespace {

using namespace topocut::testing;

constexpr std::uint16_t kShort = 3, kLong = 4;

// A grey 8-bit TIFF directory whose pixels are one strip of zeros after the directory.
std::vector<TiffEntry> grey_entries(std::uint32_t width, std::uint32_t height, std::uint32_t data_offset) {
  return {{256, kLong, 1, width},       {257, kLong, 1, height},   {258, kShort, 1, 8},
          {259, kShort, 1, 1},          {262, kShort, 1, 1},       {273, kLong, 1, data_offset},
          {277, kShort, 1, 1},          {278, kLong, 1, height},   {279, kLong, 1, width * height}};
}

TEST(HostileImages, TiffSizeGivenTwiceIsRefused) {
  // The file: the header check read one copy of ImageWidth, libtiff the other.
  std::vector<TiffEntry> entries = grey_entries(20, 20, 0);
  entries.insert(entries.begin(), {256, kLong, 1, 400000});
  entries.back().value = 400;
  for (TiffEntry& e : entries)
    if (e.tag == 273) e.value = tiff_data_offset(entries.size());
  const std::string twice = tiff_with_entries(entries, std::string(400, '\0'));
  const std::string message = error_of([&] { decode_image(twice, "twice.tif", {}); });
  EXPECT_NE(message.find("'twice.tif'"), std::string::npos) << message;
  EXPECT_NE(message.find("tag 256 twice"), std::string::npos) << message;
  // The same value twice is refused as well: the format allows each tag once.
  entries.front().value = 20;
  EXPECT_NE(error_of([&] { decode_image(tiff_with_entries(entries, std::string(400, '\0')), "same.tif", {}); }).find("twice"),
            std::string::npos);
  // Without the copy the file is a valid 20 x 20 image (so the refusal is the copy's).
  entries.erase(entries.begin());
  for (TiffEntry& e : entries)
    if (e.tag == 273) e.value = tiff_data_offset(entries.size());
  EXPECT_EQ(decode_image(tiff_with_entries(entries, std::string(400, '\0')), "once.tif", {}).size(), cv::Size(20, 20));
}

TEST(HostileImages, EveryDecoderRefusesASizeTheHeaderCheckDidNotAccept) {
  const cv::Mat image(6, 9, CV_8UC1, cv::Scalar(77));
  const std::vector<std::pair<std::string, std::function<cv::Mat(std::string_view, const codecs::DecodeBounds&)>>> decoders = {
      {".png", codecs::decode_png},   {".jpg", codecs::decode_jpeg}, {".pgm", codecs::decode_netpbm},
      {".bmp", codecs::decode_bmp},   {".tif", codecs::decode_tiff}};
  for (const auto& [extension, decode] : decoders) {
    SCOPED_TRACE(extension);
    const std::string bytes = encode_image(image, extension);
    EXPECT_EQ(decode(bytes, {9, 6}).size(), image.size());
    for (const codecs::DecodeBounds other : {codecs::DecodeBounds{8, 6}, codecs::DecodeBounds{9, 7}}) {
      try {
        decode(bytes, other);
        ADD_FAILURE() << "decoded a size it was not given";
      } catch (const codecs::CodecRefusal& e) {
        EXPECT_NE(std::string(e.what()).find("two sizes"), std::string::npos) << e.what();
      }
    }
  }
}

TEST(HostileImages, TiffTilesFarLargerThanTheImageAreRefused) {
  // A 1 x 1 image in one 65520 x 65520 tile: libtiff would allocate 4 GB for it.
  std::vector<TiffEntry> entries = {{256, kLong, 1, 1},      {257, kLong, 1, 1},      {258, kShort, 1, 8},
                                    {259, kShort, 1, 1},     {262, kShort, 1, 1},     {277, kShort, 1, 1},
                                    {322, kLong, 1, 65520},  {323, kLong, 1, 65520},  {324, kLong, 1, 0},
                                    {325, kLong, 1, 1}};
  entries[8].value = tiff_data_offset(entries.size());
  const std::string message = error_of([&] { decode_image(tiff_with_entries(entries, "x"), "tile.tif", {}); });
  EXPECT_NE(message.find("far larger than its image"), std::string::npos) << message;
}

TEST(HostileImages, TiffWithMoreStripsThanTheLimitIsRefused) {
  // 1 x 1,100,000 pixels, a strip per row: every strip is a seek and a decoder set-up.
  const std::uint32_t rows = 1'100'000;
  std::vector<TiffEntry> entries = grey_entries(1, rows, 0);
  std::string arrays;
  const std::uint32_t base = tiff_data_offset(entries.size());
  const std::uint32_t pixels = base + 8 * rows;  // after both arrays
  const auto put = [&arrays](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) arrays += static_cast<char>((v >> (8 * i)) & 255);
  };
  for (std::uint32_t r = 0; r < rows; ++r) put(pixels + r);
  for (std::uint32_t r = 0; r < rows; ++r) put(1);
  arrays += std::string(rows, '\x80');
  for (TiffEntry& e : entries) {
    if (e.tag == 273) e = {273, kLong, rows, base};
    if (e.tag == 278) e.value = 1;
    if (e.tag == 279) e = {279, kLong, rows, base + 4 * rows};
  }
  const std::string message = error_of([&] { decode_image(tiff_with_entries(entries, arrays), "strips.tif", {}); });
  EXPECT_NE(message.find("1100000 strips or tiles, more than the limit of 1048576"), std::string::npos) << message;
}

TEST(HostileImages, ProgressiveJpegWithMoreScansThanTheLimitIsRefused) {
  for (const int components : {1, 3}) {
    JpegLayout l;
    l.components = components;
    l.progressive = true;
    l.extra_scans = codecs::kMaxJpegScans;  // beyond the limit whatever the image's own scans
    const std::string message = error_of([&] { decode_image(jpeg_bytes(l), "scans.jpg", {}); });
    EXPECT_NE(message.find("'scans.jpg'"), std::string::npos) << message;
    EXPECT_NE(message.find("more than 100 scans"), std::string::npos) << message;
  }
  // The case: thousands of empty scans in a file of about a megabyte, within the pixel limit.
  JpegLayout large;
  large.width = 2000;
  large.height = 2000;
  large.progressive = true;
  large.extra_scans = 20000;
  const std::string bytes = jpeg_bytes(large);
  EXPECT_NE(error_of([&] { decode_image(bytes, "many.jpg", {}); }).find("scans"), std::string::npos);
}

}  // namespace
}  // namespace topocut
