#pragma once
// What the merge model (segmentation/merge_model.h) is fitted on: every candidate merge the segmenter
// weighs on a map, labelled by people's rooms. scripts/train_merge_model.py reads these rows through
// the Python module.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

struct MergeTrainingRow {
  std::vector<double> features;  // merge_feature_names() order
  bool same_room = false;        // most of both rooms' cells lie in one room of people's
  double weight = 0.0;           // the purer side's share of its most common room times the other's
  double probability = 0.0;      // what the model that drove the merging gave
};

// Runs merging on grid as trace_merges() does and labels each candidate by the ground-truth room labels
// (CV_32SC1 of the grid's size, as from ground_truth_rooms(); 0 = no room): a side's room is the
// room most of its cells lie in, and a candidate whose side has no cell in any room is left out.
// Throws Error on a size mismatch or as segment() does.
std::vector<MergeTrainingRow> merge_training_rows(const OccupancyGrid& grid, const cv::Mat& room_labels,
                                                  const SegmentOptions& options);

}  // namespace topocut
