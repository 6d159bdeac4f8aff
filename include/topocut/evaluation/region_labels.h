#pragma once
// Segmentations made by other tools, as they publish them: a label image (one grey or 16-bit value a
// region, 0 none) or a colour image (one colour a region, black none), to be scored like topocut's own.
#include <string>

#include <opencv2/core.hpp>

#include "topocut/io/image_input.h"

namespace topocut {

// The regions of a decoded image as CV_32SC1 labels, 0 = none: one channel (8 or 16 bits, with or
// without alpha), the value itself; colour (BGR or BGRA, 8 or 16 bits), each colour other than black numbered 1..N in increasing
// order of its (red, green, blue) value. A pixel with alpha < 128 is none. Throws Error on other types.
cv::Mat region_labels(const cv::Mat& image);

// read_image() then region_labels(); errors name the file.
// With expected, the image must have that size (checked before it is decoded).
cv::Mat read_region_labels(const std::string& path, const ImageLimits& limits = {}, const ExpectedSize* expected = nullptr);

}  // namespace topocut
