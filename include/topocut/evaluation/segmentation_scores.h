#pragma once
// Every score of a segmentation against a ground truth, as the reports carry them: Bormann's
// precision and recall, matched rooms, precision inside annotated space and the far share. One
// function computes them all, so that the CLI, the benchmarks and the Python module agree.
#include <opencv2/core.hpp>

#include "topocut/evaluation/matched_rooms.h"
#include "topocut/evaluation/precision_recall.h"

namespace topocut {

struct SegmentationScores {
  PrecisionRecall overlap;        // Bormann's recall and precision (over the labels as given)
  MatchedRooms matched;           // over the map's free pixels
  double precision_inside = 0.0;  // precision with segments clipped to the annotated space
  double far_share = 0.0;         // labelled pixels farther than far_distance from every room
};

// Scores segment labels against ground-truth room labels (as from ground_truth_rooms) of a map whose
// free pixels are the non-zero pixels of free (CV_8UC1; empty: every pixel) at resolution metres per
// pixel. Throws Error on bad or mismatched input and on a ground truth without a counted room.
SegmentationScores score_segmentation(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& free,
                                      double resolution, const EvaluationOptions& options = {});

}  // namespace topocut
