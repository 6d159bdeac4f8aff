#pragma once
// Pictures of a segmentation against its ground truth, for people who judge segmenters by eye: the
// ground truth's rooms and the segments side by side, every matched pair (matched_rooms.h) in one
// colour in both, missed rooms hatched red, segments that merged rooms outlined and hatched orange.
#include <opencv2/core.hpp>

#include "topocut/evaluation/matched_rooms.h"
#include "topocut/evaluation/precision_recall.h"

namespace topocut {

struct ComparisonPictures {
  cv::Mat truth;         // CV_8UC3 (BGR): the ground truth's rooms over the map
  cv::Mat segments;      // CV_8UC3 (BGR): the segments over the map, the same size
  RoomOutcomes outcomes;  // what the pictures mark
};

// Draws segment_labels and room_labels (single-channel integer labels of the map's size, rows
// top-down; rooms as from ground_truth_rooms) over map_cells (an OccupancyGrid's cells: free, unknown,
// occupied), scaled by a whole factor (1 to 4) so that the longer side has at least min_side pixels.
// The matching is room_outcomes() over the map's free cells. Throws Error like room_outcomes() and
// when map_cells is not CV_8UC1 of the labels' size.
ComparisonPictures comparison_pictures(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& map_cells,
                                       const EvaluationOptions& options = {}, int min_side = 600);

}  // namespace topocut
