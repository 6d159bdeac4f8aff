#pragma once
// Precision and recall of a room segmentation against a ground-truth image, with the definitions of
// Bormann et al. (ICRA 2016), which DESIGN.md fixes: for every segment S,
//   precision_S = max over rooms R of |S ∩ R| / |S|,
// for every ground-truth room R,
//   recall_R = max over segments S of |S ∩ R| / |R|,
// and the reported figures are the means over segments and over rooms. (The seed paper, Fermin-Leon
// et al., swaps the two names in its equations 4-5; these are the definitions used everywhere here.)
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/io/image_input.h"

namespace topocut {

struct EvaluationOptions {
  int free_above = 250;          // ground-truth pixels brighter than this are free (Bormann: > 250)
  int max_ignored_pixels = 100;  // rooms and segments of at most this many pixels are ignored
  double match_iou = 0.5;        // matched rooms: a segment and a room match when their IoU exceeds this (>= 0.5)
  double far_distance = 0.5;     // m: a labelled cell farther than this from every ground-truth room is 'far'
};

struct PrecisionRecall {
  double precision = 0.0;  // mean over the counted segments; 0 when there is none
  double recall = 0.0;     // mean over the counted ground-truth rooms
  int segments = 0;        // segments larger than max_ignored_pixels (the ones the means run over)
  int rooms = 0;           // ground-truth rooms larger than max_ignored_pixels
  std::vector<double> segment_precision;  // per counted segment, in increasing label order
  std::vector<double> room_recall;        // per counted room, in increasing room-label order
};

// Loads a ground-truth image as one grey channel (CV_8UC1): colour is converted to grey, 16-bit
// is scaled to 8 bits, and transparent pixels (alpha < 128) become 0 (never free). Throws Error naming the
// file if it is missing, not a regular file, not an image of an accepted format or beyond limits.
// With expected, the image must have that size (checked before it is decoded).
cv::Mat load_ground_truth(const std::string& path, const ImageLimits& limits = {}, const ExpectedSize* expected = nullptr);

// Splits the free pixels (> options.free_above) of a grey ground-truth image (CV_8UC1) into rooms by
// 8-connected flood fill (cv::connectedComponents): returns CV_32SC1 labels, 0 = not a room, rooms
// 1..N. Small rooms are kept here; precision_recall() ignores them.
cv::Mat ground_truth_rooms(const cv::Mat& ground_truth, const EvaluationOptions& options = {});

// Precision and recall of segment labels (single-channel 8/16/32-bit integers, 0 = not a room)
// against ground-truth room labels of the same size (as from ground_truth_rooms()). |S| and |R| count
// every pixel of the segment or room, also those in no counted room or segment (separator lines,
// ignored small ones, label 0), as Bormann et al.'s code does. Throws Error on size or type mismatch,
// negative labels, or a ground truth without any room larger than max_ignored_pixels.
PrecisionRecall precision_recall(const cv::Mat& segment_labels, const cv::Mat& room_labels,
                                 const EvaluationOptions& options = {});

// ground_truth_rooms() followed by precision_recall(): scores segment labels against a grey
// ground-truth image.
PrecisionRecall evaluate_against_ground_truth(const cv::Mat& segment_labels, const cv::Mat& ground_truth,
                                              const EvaluationOptions& options = {});

}  // namespace topocut
