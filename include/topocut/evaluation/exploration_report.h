#pragma once
// What an incremental run (a simulated exploration or a replayed log) amounts to, for people: its
// per-update times, the stability of its room ids, and, for an exploration of a map with a ground
// truth, the quality of the final rooms.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/evaluation/precision_recall.h"
#include "topocut/evaluation/segmentation_scores.h"
#include "topocut/exploration/exploration_run.h"
#include "topocut/exploration/grid_replay.h"
#include "topocut/exploration/room_stability.h"

namespace topocut {

// The final incremental labels and batch segment() of the same final map, scored.
struct ExplorationScore {
  SegmentationScores incremental;
  SegmentationScores batch;
};

// Scores run's final results against gt_rooms (ground_truth_rooms() of the explored map, in its
// frame: the run's window places the labels); matched rooms count the pixels where free (CV_8UC1,
// the explored map's free cells in that frame; empty: all) is non-zero. Throws Error if the window
// does not fit gt_rooms.
ExplorationScore score_exploration(const ExplorationRun& run, const cv::Mat& gt_rooms, const cv::Mat& free = {},
                                   const EvaluationOptions& options = {});

// Lines for people: incremental time per update (median, p95, max, total; CPU, then wall clock)
// and, when compared, batch on the same updates and the speed-up of the medians and totals.
std::string format_update_times(const std::vector<UpdateRecord>& updates);

// One line for people: "churn median 0.000 %, p95 0.000 %, max 1.234 % (12 of 900 updates);
// rooms changed 3 of 40 (5 changes); ids used 44, final rooms 40".
std::string format_stability(const StabilityReport& report);

// "final rooms: incremental N (M before the map at rest was segmented as a whole), batch K".
std::string final_rooms_line(const GridReplay& run);

// Lines for people, empty unless run compared batch: batch's own stability on the same updates
// ("batch stability (ids carried by overlap): " and format_stability()), then the incremental churn
// p95 and ids used per final room, each over batch's.
std::string format_batch_stability(const GridReplay& run);

// The summary `topocut explore` prints: scans, updates, path, explored share, the update times,
// stability, peak state, final rooms, and, when gt_rooms is not empty, the score against it (the
// ground truth named ground_truth). Throws Error like score_exploration().
std::string format_exploration_summary(const ExplorationRun& run, const cv::Mat& gt_rooms,
                                       const std::string& ground_truth);

}  // namespace topocut
