#include "topocut/evaluation/matched_rooms.h"

#include <cstdint>
#include <map>
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

// The counted regions of both images, their matches (IoU above options.match_iou) and the table.
struct Matching {
  detail::Contingency table;
  std::vector<int> segments, rooms;  // counted labels, increasing
  struct Match {
    int segment = 0, room = 0;
    double iou = 0.0;
  };
  std::vector<Match> matches;
};

Matching match(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& free, const EvaluationOptions& options) {
  // Below 0.5 a segment could match two rooms, and the counts would stop meaning one-to-one.
  if (!(options.match_iou >= 0.5 && options.match_iou < 1.0)) throw Error("the match IoU must lie in [0.5, 1)");
  const cv::Mat segments = restricted(detail::to_int_labels(segment_labels, "segmentation label"), free, "segmentation");
  const cv::Mat rooms = restricted(detail::to_int_labels(room_labels, "ground-truth room label"), free, "ground truth");
  Matching m;
  m.table = detail::contingency(segments, rooms);
  m.segments = detail::counted_labels(m.table.segment_size, options.max_ignored_pixels);
  m.rooms = detail::counted_labels(m.table.room_size, options.max_ignored_pixels);
  if (m.rooms.empty()) {
    throw Error("the ground truth has no room larger than " + std::to_string(options.max_ignored_pixels) +
                " free pixels");
  }
  const std::set<int> segment_set(m.segments.begin(), m.segments.end());
  const std::set<int> room_set(m.rooms.begin(), m.rooms.end());
  for (const detail::LabelPair& pair : m.table.pairs) {
    if (!segment_set.count(pair.segment) || !room_set.count(pair.room)) continue;
    const std::int64_t united = m.table.segment_size.at(pair.segment) + m.table.room_size.at(pair.room) - pair.pixels;
    // Exact at 0.5: a ratio of pixel counts is either 0.5 exactly or at least 2^-33 away from it.
    const double iou = static_cast<double>(pair.pixels) / static_cast<double>(united);
    if (iou > options.match_iou) m.matches.push_back({pair.segment, pair.room, iou});
  }
  return m;
}

}  // namespace

MatchedRooms matched_rooms(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& free,
                           const EvaluationOptions& options) {
  const Matching m = match(segment_labels, room_labels, free, options);
  MatchedRooms result;
  result.segments = static_cast<int>(m.segments.size());
  result.rooms = static_cast<int>(m.rooms.size());
  result.matches = static_cast<int>(m.matches.size());
  for (const Matching::Match& pair : m.matches) result.iou_sum += pair.iou;
  result.false_positives = result.segments - result.matches;
  result.false_negatives = result.rooms - result.matches;
  const double denominator = result.matches + 0.5 * (result.false_positives + result.false_negatives);
  result.f1 = result.matches / denominator;
  result.pq = result.iou_sum / denominator;
  result.segments_per_room = static_cast<double>(result.segments) / result.rooms;
  return result;
}

RoomOutcomes room_outcomes(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& free,
                           const EvaluationOptions& options) {
  const Matching m = match(segment_labels, room_labels, free, options);
  RoomOutcomes out;
  for (const int room : m.rooms) out.room_match[room] = 0;
  for (const int segment : m.segments) out.segment_match[segment] = 0;
  for (const Matching::Match& pair : m.matches) {
    out.room_match[pair.room] = pair.segment;
    out.segment_match[pair.segment] = pair.room;
  }
  // A segment holding more than half of a room: at most one per room, so a segment that holds
  // more than half of two rooms took them both.
  std::map<int, int> majorities;
  for (const detail::LabelPair& pair : m.table.pairs) {
    if (pair.segment == 0 || !out.room_match.count(pair.room) || !out.segment_match.count(pair.segment)) continue;
    if (2 * pair.pixels > m.table.room_size.at(pair.room)) ++majorities[pair.segment];
  }
  for (const auto& [segment, rooms] : majorities)
    if (rooms >= 2) out.merges.insert(segment);
  return out;
}

}  // namespace topocut
