#include "topocut/evaluation/segmentation_scores.h"

#include "topocut/evaluation/annotated_space.h"

namespace topocut {

SegmentationScores score_segmentation(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& free,
                                      double resolution, const EvaluationOptions& options) {
  SegmentationScores scores;
  scores.overlap = precision_recall(segment_labels, room_labels, options);
  scores.matched = matched_rooms(segment_labels, room_labels, free, options);
  scores.precision_inside = precision_inside_annotated(segment_labels, room_labels, options);
  scores.far_share = far_from_rooms_share(segment_labels, room_labels, resolution, options);
  return scores;
}

}  // namespace topocut
