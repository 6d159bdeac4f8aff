#pragma once
// Label images: 16-bit PNGs where 0 is "not a room" and rooms are 1..N (DESIGN.md). They are for
// programs; the colour overlay (overlay.h) is for people.
#include <string>

#include <opencv2/core.hpp>

namespace topocut {

// Writes labels (CV_32SC1 or any single-channel integer type, values 0..65535) as a 16-bit PNG,
// atomically. Throws Error if a label does not fit in 16 bits or the file cannot be written.
void write_label_image(const std::string& path, const cv::Mat& labels);

// Reads a label image (8- or 16-bit, single channel) as CV_32SC1. Throws Error naming the file if
// it is missing, not an image, or has more than one channel.
cv::Mat read_label_image(const std::string& path);

}  // namespace topocut
