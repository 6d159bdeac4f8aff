// Differential checking of the codecs (issue 28): valid images in the layouts real files come in
// (tests/io/image_variants.h: tiled, striped and planar TIFFs, 1- to 16-bit, palette, min-is-white,
// oriented; interlaced and palette PNGs; progressive, arithmetic and EXIF-oriented JPEGs; BMPs of
// every depth), generated here, decode with topocut to the pixels OpenCV's imdecode(IMREAD_UNCHANGED)
// gives, or to topocut's documented refusal.
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "io/codecs/codecs.h"
#include "io/image_variants.h"
#include "topocut/core/error.h"
#include "topocut/io/image_input.h"

namespace topocut {
namespace {

using namespace topocut::testing;

struct Tally {
  int cases = 0, same = 0, refused = 0, opencv_refused = 0, opencv_wrong = 0;
};

cv::Mat opencv_decoded(const std::string& bytes) {
  return cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data())), cv::IMREAD_UNCHANGED);
}

// The refusals docs/limits.md documents for valid files: layouts topocut does not read.
bool documented_refusal(const std::string& message) { return message.find("are not read") != std::string::npos || message.find("is not read") != std::string::npos; }

bool same_pixels(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

// Decodes bytes both ways; they must agree, or topocut refuse with a documented reason. With the
// pixels the file holds (expected, when the generator knows them), topocut must give them, and
// OpenCV may differ only where it is wrong or refuses.
void compare(const std::string& name, const std::string& bytes, Tally& tally, const cv::Mat& expected = {}) {
  SCOPED_TRACE(name);
  ASSERT_FALSE(bytes.empty()) << "the generator could not write " << name;
  ++tally.cases;
  const cv::Mat theirs = opencv_decoded(bytes);
  cv::Mat ours;
  std::string refusal;
  try {
    ours = decode_image(bytes, name, {});
  } catch (const Error& e) {
    refusal = e.what();
  }
  if (!refusal.empty()) {
    ++tally.refused;
    EXPECT_TRUE(documented_refusal(refusal)) << refusal << (theirs.empty() ? " (OpenCV refuses it too)" : " (OpenCV reads it)");
    return;
  }
  if (!expected.empty()) {
    EXPECT_TRUE(same_pixels(ours, expected)) << "topocut does not give the pixels the file holds";
    if (theirs.empty()) ++tally.opencv_refused;
    if (!theirs.empty() && !same_pixels(theirs, expected)) ++tally.opencv_wrong;
    if (theirs.empty() || !same_pixels(theirs, expected)) return;
  }
  if (theirs.empty()) {
    ++tally.opencv_refused;
    ADD_FAILURE() << "OpenCV refuses " << name << ", which topocut reads";
    return;
  }
  ASSERT_EQ(ours.type(), theirs.type());
  ASSERT_EQ(ours.size(), theirs.size());
  const double difference = cv::norm(ours, theirs, cv::NORM_INF);
  EXPECT_EQ(difference, 0.0);
  if (difference == 0.0) ++tally.same;
}

void report(const char* format, const Tally& t) {
  std::cout << format << ": " << t.cases << " valid files, " << t.same << " the same pixels as OpenCV, " << t.refused
            << " refused by topocut, " << t.opencv_refused << " refused by OpenCV, " << t.opencv_wrong
            << " decoded wrongly by OpenCV\n";
}

TEST(CodecDifferential, TiffLayouts) {
  struct Kind {
    int bits, samples, photometric;
  };
  const Kind kinds[] = {{1, 1, PHOTOMETRIC_MINISBLACK}, {1, 1, PHOTOMETRIC_MINISWHITE}, {2, 1, PHOTOMETRIC_MINISBLACK},
                        {4, 1, PHOTOMETRIC_MINISBLACK}, {4, 1, PHOTOMETRIC_PALETTE},    {8, 1, PHOTOMETRIC_MINISBLACK},
                        {8, 1, PHOTOMETRIC_MINISWHITE}, {8, 1, PHOTOMETRIC_PALETTE},    {8, 3, PHOTOMETRIC_RGB},
                        {8, 4, PHOTOMETRIC_RGB},        {16, 1, PHOTOMETRIC_MINISBLACK}, {16, 3, PHOTOMETRIC_RGB},
                        {16, 4, PHOTOMETRIC_RGB}};
  struct Blocks {
    bool tiled;
    int width, height;
  };
  const Blocks blocks[] = {{false, 0, 1}, {false, 0, 7}, {false, 0, 29}, {true, 16, 16}, {true, 32, 48}};
  const int compressions[] = {COMPRESSION_NONE, COMPRESSION_LZW, COMPRESSION_ADOBE_DEFLATE, COMPRESSION_PACKBITS};
  Tally tally;
  int n = 0;
  for (const Kind& kind : kinds)
    for (const Blocks& b : blocks)
      for (const bool separate : {false, true}) {
        if (separate && kind.samples == 1) continue;
        TiffLayout l;
        l.bits = kind.bits;
        l.samples = kind.samples;
        l.photometric = kind.photometric;
        l.tiled = b.tiled;
        l.block_width = b.width;
        l.block_height = b.height;
        l.separate = separate;
        l.compression = compressions[n % 4];
        l.seed = static_cast<std::uint64_t>(++n);
        const std::string name = "tiff bits " + std::to_string(l.bits) + " samples " + std::to_string(l.samples) +
                                 " photometric " + std::to_string(l.photometric) + (l.tiled ? " tiles " : " strips ") +
                                 std::to_string(b.width) + "x" + std::to_string(b.height) + (separate ? " planar" : "") +
                                 " compression " + std::to_string(l.compression);
        compare(name, tiff_bytes(l), tally, tiff_expected(l));
      }
  // Orientation tags: OpenCV turns 8-bit images read through libtiff's RGBA reader upright.
  for (const int orientation : {ORIENTATION_TOPRIGHT, ORIENTATION_BOTRIGHT, ORIENTATION_BOTLEFT, ORIENTATION_LEFTTOP,
                                ORIENTATION_RIGHTTOP, ORIENTATION_RIGHTBOT, ORIENTATION_LEFTBOT})
    for (const Kind& kind : {kinds[5], kinds[8], kinds[11]}) {
      TiffLayout l;
      l.bits = kind.bits;
      l.samples = kind.samples;
      l.photometric = kind.photometric;
      l.orientation = orientation;
      l.seed = static_cast<std::uint64_t>(++n);
      compare("tiff orientation " + std::to_string(orientation) + " bits " + std::to_string(l.bits), tiff_bytes(l), tally,
              tiff_expected(l));
    }
  report("TIFF", tally);
}

TEST(CodecDifferential, PngLayouts) {
  struct Kind {
    int colour_type, bits;
  };
  const Kind kinds[] = {{PNG_COLOR_TYPE_GRAY, 1},       {PNG_COLOR_TYPE_GRAY, 2},       {PNG_COLOR_TYPE_GRAY, 4},
                        {PNG_COLOR_TYPE_GRAY, 8},       {PNG_COLOR_TYPE_GRAY, 16},      {PNG_COLOR_TYPE_GRAY_ALPHA, 8},
                        {PNG_COLOR_TYPE_GRAY_ALPHA, 16}, {PNG_COLOR_TYPE_RGB, 8},        {PNG_COLOR_TYPE_RGB, 16},
                        {PNG_COLOR_TYPE_RGB_ALPHA, 8},  {PNG_COLOR_TYPE_RGB_ALPHA, 16}, {PNG_COLOR_TYPE_PALETTE, 1},
                        {PNG_COLOR_TYPE_PALETTE, 2},    {PNG_COLOR_TYPE_PALETTE, 4},    {PNG_COLOR_TYPE_PALETTE, 8}};
  Tally tally;
  int n = 0;
  for (const Kind& kind : kinds)
    for (const bool interlaced : {false, true})
      for (const bool transparency : {false, true}) {
        if (transparency && (kind.colour_type & PNG_COLOR_MASK_ALPHA)) continue;
        PngLayout l;
        l.colour_type = kind.colour_type;
        l.bits = kind.bits;
        l.interlaced = interlaced;
        l.transparency = transparency;
        l.seed = static_cast<std::uint64_t>(++n);
        compare("png colour type " + std::to_string(l.colour_type) + " bits " + std::to_string(l.bits) +
                    (interlaced ? " interlaced" : "") + (transparency ? " tRNS" : ""),
                png_bytes(l), tally);
      }
  report("PNG", tally);
}

TEST(CodecDifferential, JpegLayouts) {
  Tally tally;
  int n = 0;
  for (const int components : {1, 3, 4})
    for (const bool progressive : {false, true})
      for (const bool arithmetic : {false, true})
        for (const int restart_rows : {0, 1})
          for (const int orientation : {0, 6}) {
            JpegLayout l;
            l.components = components;
            l.progressive = progressive;
            l.arithmetic = arithmetic;
            l.restart_rows = restart_rows;
            l.subsampled = n % 2 == 0;
            l.exif_orientation = orientation;
            l.seed = static_cast<std::uint64_t>(++n);
            compare("jpeg components " + std::to_string(components) + (progressive ? " progressive" : "") +
                        (arithmetic ? " arithmetic" : "") + (restart_rows ? " restarts" : "") +
                        (l.subsampled ? " 4:2:0" : "") + (orientation ? " exif orientation 6" : ""),
                    jpeg_bytes(l), tally);
          }
  // Progressive files with empty scans appended, up to the scan limit: still OpenCV's pixels.
  for (const int components : {1, 3}) {
    JpegLayout l;
    l.components = components;
    l.progressive = true;
    const int own_scans = components == 1 ? 6 : 10;  // jpeg_simple_progression's script
    l.extra_scans = codecs::kMaxJpegScans - own_scans;
    compare("jpeg with " + std::to_string(codecs::kMaxJpegScans) + " scans, components " + std::to_string(components),
            jpeg_bytes(l), tally);
  }
  report("JPEG", tally);
}

TEST(CodecDifferential, BmpLayouts) {
  Tally tally;
  int n = 0;
  for (const int bits : {1, 4, 8, 16, 24, 32})
    for (const bool top_down : {false, true})
      for (const bool grey : {false, true}) {
        if (grey && bits > 8) continue;
        BmpLayout l;
        l.bits = bits;
        l.top_down = top_down;
        l.grey_palette = grey;
        l.seed = static_cast<std::uint64_t>(++n);
        compare("bmp bits " + std::to_string(bits) + (top_down ? " top-down" : "") + (grey ? " grey palette" : ""),
                bmp_bytes(l), tally);
      }
  report("BMP", tally);
}

}  // namespace
}  // namespace topocut
