// libFuzzer target: image map decoding (load_map's path for plain images and a ROS YAML's image).
// Any input must give either three-state cells of the decoded size or a topocut::Error.
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

#include "fuzz_input.h"
#include "topocut/core/error.h"
#include "topocut/io/map_loader.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  cv::setNumThreads(1);
  return 0;
}

namespace {
// Why: a 30-byte header may claim a gigapixel image; the library's own limit, checked on the header
// before decoding, keeps the fuzzer within its memory limit (4 megapixels).
const topocut::ImageLimits kLimits{4.194304};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topocut;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  cv::Mat grey, transparent;
  try {
    decode_map_image(bytes, "fuzz", grey, transparent, kLimits);
  } catch (const Error&) {
    return 0;
  }
  if (grey.empty() || grey.type() != CV_32FC1) fuzz::fail("decode_map_image returned a non-CV_32FC1 or empty image");
  double lo = 0.0, hi = 0.0;
  cv::minMaxLoc(grey, &lo, &hi);
  if (!(lo >= 0.0 && hi <= 255.0 + 1e-3)) fuzz::fail("grey values outside 0..255");
  if (transparent.size() != grey.size() || transparent.type() != CV_8UC1) fuzz::fail("transparency mask of the wrong size or type");
  const auto check_cells = [&](const cv::Mat& cells) {
    if (cells.size() != grey.size() || cells.type() != CV_8UC1) fuzz::fail("cells of the wrong size or type");
    for (int r = 0; r < cells.rows; ++r) {
      const std::uint8_t* row = cells.ptr<std::uint8_t>(r);
      for (int c = 0; c < cells.cols; ++c) {
        if (row[c] != 0 && row[c] != 128 && row[c] != 255) fuzz::fail("a cell is not occupied, unknown or free");
      }
    }
  };
  cv::Mat levels, level_transparent;
  try {
    decode_map_levels(bytes, "fuzz", levels, level_transparent, kLimits);
  } catch (const Error&) {
    fuzz::fail("decode_map_levels refused an image decode_map_image read");
  }
  if (levels.size() != grey.size() || levels.type() != CV_8UC1) fuzz::fail("levels of the wrong size or type");
  check_cells(plain_image_cells(levels, level_transparent, plain_image_palette(levels, level_transparent, MapLoadOptions{})));
  RosMapMetadata metadata;
  metadata.resolution = 0.05;
  metadata.negate = size % 2 == 1;
  metadata.mode = static_cast<RosMapMode>(size % 3);
  check_cells(ros_cells(grey, transparent, metadata));
  return 0;
}
