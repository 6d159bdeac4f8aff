#pragma once
// Image files in tests, read and written with io's own codecs (image_codec_test checks them against
// OpenCV's), so that test binaries need not link OpenCV's imgcodecs: with its GDAL dependencies it
// cost each test process a quarter of a second of start-up, and ctest runs every test as a process.
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/image_input.h"

namespace topocut::testing {

// What read_test_image() returns, as cv::imread's IMREAD_UNCHANGED, IMREAD_GRAYSCALE and IMREAD_COLOR.
enum class Pixels { kAsStored, kGrey, kColour };

// The image at path (empty if it cannot be read); kGrey and kColour give 8 bits, 1 or 3 channels (BGR).
inline cv::Mat read_test_image(const std::string& path, Pixels pixels = Pixels::kAsStored) {
  cv::Mat image;
  try {
    image = read_image(path, "test image", ImageLimits{});
  } catch (const Error&) {
    return {};
  }
  if (pixels == Pixels::kAsStored) return image;
  if (image.depth() == CV_16U) image.convertTo(image, CV_8U, 1.0 / 256.0);
  const int channels = image.channels();
  if (pixels == Pixels::kGrey && channels != 1)
    cv::cvtColor(image, image, channels == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  if (pixels == Pixels::kColour && channels != 3)
    cv::cvtColor(image, image, channels == 4 ? cv::COLOR_BGRA2BGR : cv::COLOR_GRAY2BGR);
  return image;
}

// Writes image encoded as path's extension says; false if it cannot be encoded or written.
inline bool write_test_image(const std::string& path, const cv::Mat& image) {
  try {
    write_image_atomically(path, image);
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace topocut::testing
