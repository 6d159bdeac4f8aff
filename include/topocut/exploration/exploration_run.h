#pragma once
// Exploration runs: a simulated robot explores a map and every update of its known map goes to the
// incremental segmenter (and, when asked, to the batch segmenter on the same grid), timed update by
// update (replay_grids()). No files and no reports here: evaluation scores runs against a ground
// truth and prints them.
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/exploration/explorer.h"
#include "topocut/exploration/grid_replay.h"
#include "topocut/segmentation/incremental_segmenter.h"

namespace topocut {

// What the callback of run_exploration sees after each update.
struct ExplorationFrame {
  int update = 0;  // 1-based
  const Explorer& explorer;
  const OccupancyGrid& grid;          // the known map the segmenter was given
  const Segmentation& segmentation;   // the incremental result for it
};

struct ExplorationRunOptions {
  ExplorationOptions exploration;
  IncrementalOptions incremental;
  // Also run segment(grid, incremental.segment) on updates, timed, for comparison: every
  // batch_every-th update and the last one.
  bool compare_batch = false;
  int batch_every = 1;
  // Hand the explorer's changed rectangle to the segmenter (it also works without).
  bool use_hint = true;
  std::function<void(const ExplorationFrame&)> on_update;  // may be empty
  std::function<void(const std::string&)> progress;        // occasional one-line status; may be empty
};

// The run's own switch (--no-hint: use_hint off); the batch comparison's are batch_comparison_rows().
const std::vector<OptionRow<ExplorationRunOptions>>& exploration_run_option_rows();

// The replay of the robot's known maps (updates, scans, path, final map, incremental and batch
// results, stability, peak state) and what the robot did.
struct ExplorationRun : GridReplay {
  std::string stop_reason;
  double path_length = 0.0;      // metres
  Pose2 final_pose;
  cv::Rect window;               // final_map's place in the ground truth's frame
  int known_free_cells = 0;      // free cells of final_map
  int reachable_free_cells = 0;  // free cells of the ground truth the robot could ever see
};

// Explores ground_truth until no frontier is left (or the scan cap), feeding every changed known
// map to an IncrementalSegmenter. Throws Error on invalid input (see Explorer, segment()).
ExplorationRun run_exploration(const OccupancyGrid& ground_truth, const ExplorationRunOptions& options);

// Labels of a segmentation placed into a larger frame (the ground truth's) at window; 0 elsewhere.
cv::Mat labels_in_frame(const cv::Mat& labels, const cv::Rect& window, const cv::Size& frame);

}  // namespace topocut
