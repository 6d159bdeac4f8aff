// libFuzzer target: differential decoding (issue 28). The input's bytes pick a valid image layout
// (tests/io/image_variants.h: TIFF strips or tiles, planes, 1- to 16-bit, palette, min-is-white,
// orientation; PNG depths, palettes, interlacing, transparency; JPEG progressive, arithmetic,
// restarts, EXIF orientation, empty scans; BMP depths), the image is written by the format's own
// library, and topocut must decode it to the pixels OpenCV gives (for TIFF: to the pixels the file
// holds, which OpenCV gets wrong for 16-bit planar files and cannot read for 2- and 4-bit ones), or
// refuse it for a documented reason: a JPEG of more than kMaxJpegScans scans, and only such a JPEG.
#include <cstdint>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "fuzz_input.h"
#include "io/codecs/codecs.h"
#include "io/image_variants.h"
#include "topocut/core/error.h"
#include "topocut/io/image_input.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  cv::setNumThreads(1);
  return 0;
}

namespace {

using namespace topocut;
using namespace topocut::testing;

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

int count_scans(const std::string& jpeg) {
  int scans = 0;
  for (std::size_t i = 0; i + 1 < jpeg.size(); ++i) scans += jpeg[i] == '\xFF' && jpeg[i + 1] == '\xDA';
  return scans;
}

TiffLayout tiff_layout(fuzz::ByteReader& in) {
  struct Kind {
    int bits, samples, photometric;
  };
  static const Kind kinds[] = {{1, 1, PHOTOMETRIC_MINISBLACK}, {1, 1, PHOTOMETRIC_MINISWHITE}, {2, 1, PHOTOMETRIC_MINISBLACK},
                               {4, 1, PHOTOMETRIC_MINISWHITE}, {4, 1, PHOTOMETRIC_PALETTE},    {8, 1, PHOTOMETRIC_MINISBLACK},
                               {8, 1, PHOTOMETRIC_MINISWHITE}, {8, 1, PHOTOMETRIC_PALETTE},    {8, 3, PHOTOMETRIC_RGB},
                               {8, 4, PHOTOMETRIC_RGB},        {16, 1, PHOTOMETRIC_MINISBLACK}, {16, 3, PHOTOMETRIC_RGB},
                               {16, 4, PHOTOMETRIC_RGB}};
  static const int compressions[] = {COMPRESSION_NONE, COMPRESSION_LZW, COMPRESSION_ADOBE_DEFLATE, COMPRESSION_PACKBITS};
  TiffLayout l;
  const Kind& kind = kinds[in.next() % std::size(kinds)];
  l.bits = kind.bits;
  l.samples = kind.samples;
  l.photometric = kind.photometric;
  l.width = 1 + in.next() % 70;
  l.height = 1 + in.next() % 70;
  l.tiled = in.next() % 2 == 1;
  l.block_width = 16 * (1 + in.next() % 4);
  l.block_height = l.tiled ? 16 * (1 + in.next() % 4) : 1 + in.next() % l.height;
  l.separate = l.samples > 1 && in.next() % 2 == 1;
  l.compression = compressions[in.next() % 4];
  l.orientation = 1 + in.next() % 8;
  l.seed = in.next();
  return l;
}

PngLayout png_layout(fuzz::ByteReader& in) {
  static const std::pair<int, int> kinds[] = {{PNG_COLOR_TYPE_GRAY, 1},      {PNG_COLOR_TYPE_GRAY, 2},       {PNG_COLOR_TYPE_GRAY, 4},
                                              {PNG_COLOR_TYPE_GRAY, 8},      {PNG_COLOR_TYPE_GRAY, 16},      {PNG_COLOR_TYPE_GRAY_ALPHA, 8},
                                              {PNG_COLOR_TYPE_GRAY_ALPHA, 16}, {PNG_COLOR_TYPE_RGB, 8},       {PNG_COLOR_TYPE_RGB, 16},
                                              {PNG_COLOR_TYPE_RGB_ALPHA, 8}, {PNG_COLOR_TYPE_RGB_ALPHA, 16}, {PNG_COLOR_TYPE_PALETTE, 1},
                                              {PNG_COLOR_TYPE_PALETTE, 2},   {PNG_COLOR_TYPE_PALETTE, 4},    {PNG_COLOR_TYPE_PALETTE, 8}};
  PngLayout l;
  const auto& kind = kinds[in.next() % std::size(kinds)];
  l.colour_type = kind.first;
  l.bits = kind.second;
  l.width = 1 + in.next() % 70;
  l.height = 1 + in.next() % 70;
  l.interlaced = in.next() % 2 == 1;
  l.transparency = in.next() % 2 == 1;
  l.seed = in.next();
  return l;
}

JpegLayout jpeg_layout(fuzz::ByteReader& in) {
  static const int components[] = {1, 3, 4};
  JpegLayout l;
  l.components = components[in.next() % 3];
  l.width = 1 + in.next() % 70;
  l.height = 1 + in.next() % 70;
  l.progressive = in.next() % 2 == 1;
  l.arithmetic = in.next() % 2 == 1;
  l.restart_rows = in.next() % 3;
  l.subsampled = in.next() % 2 == 1;
  l.exif_orientation = in.next() % 9;
  l.extra_scans = l.progressive ? in.next() % 120 : 0;
  l.seed = in.next();
  return l;
}

BmpLayout bmp_layout(fuzz::ByteReader& in) {
  static const int bits[] = {1, 4, 8, 16, 24, 32};
  BmpLayout l;
  l.bits = bits[in.next() % 6];
  l.width = 1 + in.next() % 70;
  l.height = 1 + in.next() % 70;
  l.top_down = in.next() % 2 == 1;
  l.grey_palette = in.next() % 2 == 1;
  l.seed = in.next();
  return l;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader in(data, size);
  const int format = in.next() % 4;
  std::string bytes;
  cv::Mat expected;  // the pixels the file holds, where OpenCV is no oracle
  if (format == 0) {
    const TiffLayout l = tiff_layout(in);
    bytes = tiff_bytes(l);
    expected = tiff_expected(l);
  } else if (format == 1) {
    bytes = png_bytes(png_layout(in));
  } else if (format == 2) {
    bytes = jpeg_bytes(jpeg_layout(in));
  } else {
    bytes = bmp_bytes(bmp_layout(in));
  }
  if (bytes.empty()) return 0;  // a layout the writer refused
  cv::Mat ours;
  std::string refusal;
  try {
    ours = decode_image(bytes, "fuzz", {});
  } catch (const Error& e) {
    refusal = e.what();
  }
  const bool too_many_scans = format == 2 && count_scans(bytes) > codecs::kMaxJpegScans;
  if (too_many_scans != (refusal.find("scans") != std::string::npos))
    fuzz::fail("the scan limit is not the line between read and refused: " + refusal);
  if (!refusal.empty()) {
    if (!too_many_scans) fuzz::fail("a valid image is refused: " + refusal);
    return 0;
  }
  if (!expected.empty()) {
    if (!same(ours, expected)) fuzz::fail("topocut does not give the pixels the TIFF holds");
    return 0;
  }
  const cv::Mat theirs =
      cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data())), cv::IMREAD_UNCHANGED);
  if (theirs.empty()) fuzz::fail("OpenCV refuses an image topocut reads");
  if (!same(ours, theirs)) fuzz::fail("topocut and OpenCV give different pixels");
  return 0;
}
