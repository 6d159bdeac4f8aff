#include "topocut/evaluation/precision_recall.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "evaluation/contingency.h"
#include "topocut/core/error.h"
#include "topocut/io/image_input.h"

namespace topocut {

using detail::contingency;
using detail::counted_labels;
using detail::to_int_labels;

cv::Mat load_ground_truth(const std::string& path, const ImageLimits& limits, const ExpectedSize* expected) {
  cv::Mat image = read_image(path, "ground truth", limits, expected);
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
  // The table holds label 0 too, so that its marginals give |S| and |R| whole.
  const detail::Contingency table =
      contingency(to_int_labels(segment_labels, "segmentation label"), to_int_labels(room_labels, "ground-truth room label"));
  std::map<int, std::int64_t> best_room_overlap;     // per counted segment: max |S ∩ R| over counted R
  std::map<int, std::int64_t> best_segment_overlap;  // per counted room: max |S ∩ R| over counted S
  for (const int label : counted_labels(table.segment_size, options.max_ignored_pixels)) best_room_overlap[label] = 0;
  for (const int label : counted_labels(table.room_size, options.max_ignored_pixels)) best_segment_overlap[label] = 0;
  if (best_segment_overlap.empty()) {
    throw Error("the ground truth has no room larger than " + std::to_string(options.max_ignored_pixels) +
                " pixels");
  }
  for (const detail::LabelPair& pair : table.pairs) {
    const auto s = best_room_overlap.find(pair.segment);
    const auto r = best_segment_overlap.find(pair.room);
    if (s == best_room_overlap.end() || r == best_segment_overlap.end()) continue;
    s->second = std::max(s->second, pair.pixels);
    r->second = std::max(r->second, pair.pixels);
  }

  PrecisionRecall result;
  result.segments = static_cast<int>(best_room_overlap.size());
  result.rooms = static_cast<int>(best_segment_overlap.size());
  for (const auto& [label, overlap] : best_room_overlap) {
    result.segment_precision.push_back(static_cast<double>(overlap) / static_cast<double>(table.segment_size.at(label)));
  }
  for (const auto& [label, overlap] : best_segment_overlap) {
    result.room_recall.push_back(static_cast<double>(overlap) / static_cast<double>(table.room_size.at(label)));
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
