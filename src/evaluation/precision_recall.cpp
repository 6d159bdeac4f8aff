#include "topocut/evaluation/precision_recall.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/io/image_input.h"

namespace topocut {

namespace {

// Brings any integer label image to CV_32SC1 so that one loop handles them all.
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

std::uint64_t pair_key(int segment, int room) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(segment)) << 32) |
         static_cast<std::uint32_t>(room);
}

}  // namespace

cv::Mat load_ground_truth(const std::string& path, const ImageLimits& limits) {
  cv::Mat image = read_image(path, "ground truth", limits);
  if (image.depth() == CV_16U) {
    image.convertTo(image, CV_8U, 1.0 / 257.0);
  } else if (image.depth() != CV_8U) {
    throw Error("cannot read ground truth '" + path + "': only 8- and 16-bit images are supported");
  }
  cv::Mat grey;
  cv::Mat alpha;
  switch (image.channels()) {
    case 1:
      grey = image;
      break;
    case 2: {  // grey + alpha, should a decoder deliver it that way
      std::vector<cv::Mat> planes;
      cv::split(image, planes);
      grey = planes[0];
      alpha = planes[1];
      break;
    }
    case 3:
      cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
      break;
    case 4:
      cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
      cv::extractChannel(image, alpha, 3);
      break;
    default:
      throw Error("cannot read ground truth '" + path + "': unsupported channel count " +
                  std::to_string(image.channels()));
  }
  // A transparent pixel carries no drawing, so it cannot be a room pixel (alpha < 128 counts as
  // transparent, as for maps in io/map_loader).
  if (!alpha.empty()) grey.setTo(0, alpha < 128);
  return grey;
}

cv::Mat ground_truth_rooms(const cv::Mat& ground_truth, const EvaluationOptions& options) {
  if (ground_truth.empty()) throw Error("the ground-truth image is empty");
  if (ground_truth.type() != CV_8UC1) {
    throw Error("the ground-truth image must be one 8-bit grey channel (use load_ground_truth)");
  }
  const cv::Mat free = ground_truth > options.free_above;
  cv::Mat rooms;
  cv::connectedComponents(free, rooms, 8, CV_32S);
  return rooms;
}

PrecisionRecall precision_recall(const cv::Mat& segment_labels, const cv::Mat& room_labels,
                                 const EvaluationOptions& options) {
  const cv::Mat segments = to_int_labels(segment_labels, "segmentation label");
  const cv::Mat rooms = to_int_labels(room_labels, "ground-truth room label");
  if (segments.size() != rooms.size()) {
    throw Error("the segmentation is " + std::to_string(segments.cols) + "x" + std::to_string(segments.rows) +
                " pixels but the ground truth is " + std::to_string(rooms.cols) + "x" +
                std::to_string(rooms.rows));
  }

  // Contingency table n(s, r) = |S ∩ R| over all label pairs, label 0 included, so that the
  // marginals give |S| and |R|. It is sparse (a segment meets few rooms), so it is a hash map
  // filled in one pass; runs of equal pairs along a row are counted before touching the map.
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

  // Sorted copies keep every later sum in label order, so results are bit-for-bit reproducible.
  std::vector<std::pair<std::uint64_t, std::int64_t>> cells(table.begin(), table.end());
  std::sort(cells.begin(), cells.end());
  std::map<int, std::int64_t> segment_size;
  std::map<int, std::int64_t> room_size;
  for (const auto& [key, count] : cells) {
    segment_size[static_cast<int>(key >> 32)] += count;
    room_size[static_cast<int>(key & 0xffffffffu)] += count;
  }

  const auto counted = [&](const std::map<int, std::int64_t>& sizes, int label) {
    return label != 0 && sizes.at(label) > options.max_ignored_pixels;
  };
  std::map<int, std::int64_t> best_room_overlap;     // per counted segment: max |S ∩ R| over counted R
  std::map<int, std::int64_t> best_segment_overlap;  // per counted room: max |S ∩ R| over counted S
  for (const auto& [label, size] : segment_size) {
    if (counted(segment_size, label)) best_room_overlap[label] = 0;
  }
  for (const auto& [label, size] : room_size) {
    if (counted(room_size, label)) best_segment_overlap[label] = 0;
  }
  if (best_segment_overlap.empty()) {
    throw Error("the ground truth has no room larger than " + std::to_string(options.max_ignored_pixels) +
                " pixels");
  }
  for (const auto& [key, count] : cells) {
    const int s = static_cast<int>(key >> 32);
    const int r = static_cast<int>(key & 0xffffffffu);
    if (!counted(segment_size, s) || !counted(room_size, r)) continue;
    best_room_overlap[s] = std::max(best_room_overlap[s], count);
    best_segment_overlap[r] = std::max(best_segment_overlap[r], count);
  }

  PrecisionRecall result;
  result.segments = static_cast<int>(best_room_overlap.size());
  result.rooms = static_cast<int>(best_segment_overlap.size());
  for (const auto& [label, overlap] : best_room_overlap) {
    result.segment_precision.push_back(static_cast<double>(overlap) / static_cast<double>(segment_size.at(label)));
  }
  for (const auto& [label, overlap] : best_segment_overlap) {
    result.room_recall.push_back(static_cast<double>(overlap) / static_cast<double>(room_size.at(label)));
  }
  double precision_sum = 0.0;
  for (const double p : result.segment_precision) precision_sum += p;
  double recall_sum = 0.0;
  for (const double r : result.room_recall) recall_sum += r;
  // With no segment at all, nothing found is precise: 0 rather than an undefined mean that would
  // poison the means over maps.
  result.precision = result.segments > 0 ? precision_sum / result.segments : 0.0;
  result.recall = recall_sum / result.rooms;
  return result;
}

PrecisionRecall evaluate_against_ground_truth(const cv::Mat& segment_labels, const cv::Mat& ground_truth,
                                              const EvaluationOptions& options) {
  return precision_recall(segment_labels, ground_truth_rooms(ground_truth, options), options);
}

}  // namespace topocut
