#include "topocut/evaluation/matched_rooms.h"

#include <cstdint>
#include <set>
#include <string>

#include "evaluation/contingency.h"
#include "topocut/core/error.h"

namespace topocut {

namespace {

// The labels with every pixel outside free set to 0 (a copy; the input is left alone).
cv::Mat restricted(const cv::Mat& labels, const cv::Mat& free, const char* what) {
  if (free.empty()) return labels;
  if (free.type() != CV_8UC1) throw Error("the free-pixel mask must be one 8-bit channel");
  if (free.size() != labels.size()) {
    throw Error(std::string("the free-pixel mask is ") + std::to_string(free.cols) + "x" + std::to_string(free.rows) +
                " pixels but the " + what + " is " + std::to_string(labels.cols) + "x" + std::to_string(labels.rows));
  }
  cv::Mat out = labels.clone();
  out.setTo(0, free == 0);
  return out;
}

}  // namespace

MatchedRooms matched_rooms(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& free,
                           const EvaluationOptions& options) {
  // Below 0.5 a segment could match two rooms, and the counts would stop meaning one-to-one.
  if (!(options.match_iou >= 0.5 && options.match_iou < 1.0)) throw Error("the match IoU must lie in [0.5, 1)");
  const cv::Mat segments = restricted(detail::to_int_labels(segment_labels, "segmentation label"), free, "segmentation");
  const cv::Mat rooms = restricted(detail::to_int_labels(room_labels, "ground-truth room label"), free, "ground truth");
  const detail::Contingency table = detail::contingency(segments, rooms);
  const std::vector<int> counted_segments = detail::counted_labels(table.segment_size, options.max_ignored_pixels);
  const std::vector<int> counted_rooms = detail::counted_labels(table.room_size, options.max_ignored_pixels);
  if (counted_rooms.empty()) {
    throw Error("the ground truth has no room larger than " + std::to_string(options.max_ignored_pixels) +
                " free pixels");
  }
  const std::set<int> segment_set(counted_segments.begin(), counted_segments.end());
  const std::set<int> room_set(counted_rooms.begin(), counted_rooms.end());

  MatchedRooms result;
  result.segments = static_cast<int>(counted_segments.size());
  result.rooms = static_cast<int>(counted_rooms.size());
  for (const detail::LabelPair& pair : table.pairs) {
    if (!segment_set.count(pair.segment) || !room_set.count(pair.room)) continue;
    const std::int64_t united = table.segment_size.at(pair.segment) + table.room_size.at(pair.room) - pair.pixels;
    // Exact at 0.5: a ratio of pixel counts is either 0.5 exactly or at least 2^-33 away from it.
    const double iou = static_cast<double>(pair.pixels) / static_cast<double>(united);
    if (iou <= options.match_iou) continue;
    ++result.matches;
    result.iou_sum += iou;
  }
  result.false_positives = result.segments - result.matches;
  result.false_negatives = result.rooms - result.matches;
  const double denominator = result.matches + 0.5 * (result.false_positives + result.false_negatives);
  result.f1 = result.matches / denominator;
  result.pq = result.iou_sum / denominator;
  result.segments_per_room = static_cast<double>(result.segments) / result.rooms;
  return result;
}

}  // namespace topocut
