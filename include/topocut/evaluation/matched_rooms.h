#pragma once
// Matched rooms (DESIGN.md, Evaluation): Bormann's precision and recall barely punish
// under-segmentation (docs/evaluating.md gives an example), so a segmentation is also counted
// one-to-one. A segment and a ground-truth room match when their IoU,
// over the map's free pixels, exceeds 0.5. Then the segment holds more than half of the room and the
// room more than half of the segment; segments do not overlap, nor do rooms, so every segment matches
// at most one room and every room at most one segment.
#include <map>
#include <set>

#include <opencv2/core.hpp>

#include "topocut/evaluation/precision_recall.h"

namespace topocut {

struct MatchedRooms {
  int segments = 0;  // segments of more than max_ignored_pixels free pixels
  int rooms = 0;     // ground-truth rooms of more than max_ignored_pixels free pixels
  int matches = 0;   // TP: matched pairs
  int false_positives = 0;   // counted segments matching no room
  int false_negatives = 0;   // counted rooms matching no segment
  double iou_sum = 0.0;      // sum of the matches' IoU
  double f1 = 0.0;           // TP / (TP + (FP + FN) / 2)
  double pq = 0.0;           // panoptic quality: iou_sum / (TP + (FP + FN) / 2)
  double segments_per_room = 0.0;  // segments / rooms (below 1: under-segmented, above: over-segmented)
};

// Matches segment labels against ground-truth room labels (single-channel integer images of one size,
// 0 = none; rooms as from ground_truth_rooms) over the pixels where free is non-zero (CV_8UC1 of the
// same size, the map's free cells; empty: every pixel). Both are restricted to free before sizes are
// taken, and regions of at most options.max_ignored_pixels pixels after that are ignored. Throws Error
// on size or type mismatch, negative labels, options.match_iou outside [0.5, 1), or a ground truth
// without any counted room.
MatchedRooms matched_rooms(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& free = {},
                           const EvaluationOptions& options = {});

// What became of every counted room and segment under the same matching, for pictures that show
// where a segmentation errs: a room without a match is missed; a segment that holds more than half
// of two or more counted rooms merged them (each room has at most one such segment).
struct RoomOutcomes {
  std::map<int, int> room_match;     // every counted room -> its matched segment, 0: missed
  std::map<int, int> segment_match;  // every counted segment -> its matched room, 0: unmatched
  std::set<int> merges;              // counted segments holding more than half of two or more counted rooms
};

// The matching behind matched_rooms(), region by region; same arguments and errors.
RoomOutcomes room_outcomes(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& free = {},
                           const EvaluationOptions& options = {});

}  // namespace topocut
