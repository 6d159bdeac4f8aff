#pragma once
// The contingency table of two label images, which every overlap score (precision/recall, matched
// rooms) reads: how many pixels each pair of labels shares, and each label's size.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace topocut::detail {

struct LabelPair {
  int segment = 0;
  int room = 0;
  std::int64_t pixels = 0;  // |S ∩ R|
};

struct Contingency {
  std::vector<LabelPair> pairs;                // every pair present, label 0 included, sorted by (segment, room)
  std::map<int, std::int64_t> segment_size;    // |S| for every segment label present, 0 included
  std::map<int, std::int64_t> room_size;       // |R| for every room label present, 0 included
};

// Brings an integer label image to CV_32SC1 (what names the image in errors). Throws Error on an
// empty, multi-channel, floating-point or negative image.
cv::Mat to_int_labels(const cv::Mat& image, const std::string& what);

// The table of two CV_32SC1 label images; throws Error naming both sizes when they differ.
Contingency contingency(const cv::Mat& segments, const cv::Mat& rooms);

// Labels > 0 whose size is above max_ignored_pixels: the regions a score counts.
std::vector<int> counted_labels(const std::map<int, std::int64_t>& sizes, int max_ignored_pixels);

}  // namespace topocut::detail
