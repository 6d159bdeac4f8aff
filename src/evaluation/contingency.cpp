#include "evaluation/contingency.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "topocut/core/error.h"

namespace topocut::detail {

namespace {

std::uint64_t pair_key(int segment, int room) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(segment)) << 32) |
         static_cast<std::uint32_t>(room);
}

}  // namespace

cv::Mat to_int_labels(const cv::Mat& image, const std::string& what) {
  if (image.empty()) throw Error("the " + what + " image is empty");
  if (image.channels() != 1) {
    throw Error("the " + what + " image must have one channel, not " + std::to_string(image.channels()));
  }
  const int depth = image.depth();
  if (depth == CV_32F || depth == CV_64F || depth == CV_16F) {
    throw Error("the " + what + " image must hold integer labels, not floating-point values");
  }
  cv::Mat labels;
  if (depth == CV_32S) {
    labels = image;
  } else {
    image.convertTo(labels, CV_32S);
  }
  double min_value = 0.0;
  cv::minMaxLoc(labels, &min_value);
  if (min_value < 0) throw Error("the " + what + " image holds negative labels");
  return labels;
}

Contingency contingency(const cv::Mat& segments, const cv::Mat& rooms) {
  if (segments.size() != rooms.size()) {
    throw Error("the segmentation is " + std::to_string(segments.cols) + "x" + std::to_string(segments.rows) +
                " pixels but the ground truth is " + std::to_string(rooms.cols) + "x" + std::to_string(rooms.rows));
  }
  // Sparse (a segment meets few rooms), so a hash map filled in one pass; runs of equal pairs along
  // a row are counted before touching the map.
  std::unordered_map<std::uint64_t, std::int64_t> table;
  for (int row = 0; row < segments.rows; ++row) {
    const int* s = segments.ptr<int>(row);
    const int* r = rooms.ptr<int>(row);
    int run_segment = s[0];
    int run_room = r[0];
    std::int64_t run = 0;
    for (int column = 0; column < segments.cols; ++column) {
      if (s[column] == run_segment && r[column] == run_room) {
        ++run;
        continue;
      }
      table[pair_key(run_segment, run_room)] += run;
      run_segment = s[column];
      run_room = r[column];
      run = 1;
    }
    table[pair_key(run_segment, run_room)] += run;
  }
  // Sorted, so that every later sum runs in label order and results are bit-for-bit reproducible.
  std::vector<std::pair<std::uint64_t, std::int64_t>> cells(table.begin(), table.end());
  std::sort(cells.begin(), cells.end());
  Contingency result;
  for (const auto& [key, count] : cells) {
    const LabelPair pair{static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu), count};
    result.pairs.push_back(pair);
    result.segment_size[pair.segment] += count;
    result.room_size[pair.room] += count;
  }
  return result;
}

std::vector<int> counted_labels(const std::map<int, std::int64_t>& sizes, int max_ignored_pixels) {
  std::vector<int> labels;
  for (const auto& [label, size] : sizes) {
    if (label != 0 && size > max_ignored_pixels) labels.push_back(label);
  }
  return labels;
}

}  // namespace topocut::detail
