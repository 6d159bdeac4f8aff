#pragma once
// Exploration runs: a simulated robot explores a map and every update of its known map goes to the
// incremental segmenter (and, when asked, to the batch segmenter on the same grid), timed update by
// update; and the same over a Bormann-format dataset, scored against the ground truth, for
// `topocut evaluate --mode incremental` and the incremental benchmark.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/exploration/explorer.h"
#include "topocut/exploration/room_stability.h"
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

// One update: a scan that changed the known map. Times are process CPU time (immune to other
// programs on a shared machine), with the wall-clock time beside them.
struct UpdateRecord {
  int scan = 0;                 // 1-based scan number
  double incremental_ms = 0.0;  // IncrementalSegmenter::update, CPU
  double incremental_wall_ms = 0.0;
  double batch_ms = -1.0;       // segment() on the same grid, CPU; -1 when not compared on this update
  double batch_wall_ms = -1.0;
  int rooms = 0;
  int batch_rooms = -1;
  int changed_cells = 0;        // cells whose free state changed, as the segmenter counted them
  bool batch_update = false;    // the segmenter decomposed everything again
};

struct ExplorationRun {
  std::vector<UpdateRecord> updates;
  int scans = 0;
  std::string stop_reason;
  double path_length = 0.0;      // metres
  std::vector<Point2> path;      // scan positions
  Pose2 final_pose;
  OccupancyGrid final_map;       // the last known map (its own copy)
  cv::Rect window;               // final_map's place in the ground truth's frame
  Segmentation incremental;      // after the last update
  Segmentation batch;            // segment() on final_map
  double batch_final_ms = 0.0;   // CPU time of that call
  int known_free_cells = 0;      // free cells of final_map
  int reachable_free_cells = 0;  // free cells of the ground truth the robot could ever see
  std::size_t peak_state_bytes = 0;  // largest IncrementalSegmenter::state_bytes() over the run
  StabilityReport stability;     // of the incremental labels, update by update
};

// Explores ground_truth until no frontier is left (or the scan cap), feeding every changed known
// map to an IncrementalSegmenter. Throws Error on invalid input (see Explorer, segment()).
ExplorationRun run_exploration(const OccupancyGrid& ground_truth, const ExplorationRunOptions& options);

// Labels of a segmentation placed into a larger frame (the ground truth's) at window; 0 elsewhere.
cv::Mat labels_in_frame(const cv::Mat& labels, const cv::Rect& window, const cv::Size& frame);

// Order statistics of per-update times. p95 is the nearest-rank percentile (the smallest value
// with at least 95 % of the values at or below it); everything is 0 for an empty list.
struct UpdateTimes {
  int count = 0;
  double median = 0.0, p95 = 0.0, max = 0.0, mean = 0.0, total = 0.0;
};
UpdateTimes update_times(std::vector<double> values_ms);

// The ground truth next to a Bormann-style map: X_gt_segmentation.png beside X.png or
// X_furnitures.png. Empty if there is no such file.
std::string find_ground_truth(const std::string& map_path);

// ---- datasets ------------------------------------------------------------------------------

struct IncrementalDatasetOptions {
  DatasetRunOptions run;               // variants, load, evaluation, progress; run.segment is used
  ExplorationRunOptions exploration;   // its incremental.segment is replaced by run.segment
};

struct IncrementalImageResult {
  ImageResult incremental;  // the final incremental labels scored; time_ms = all updates together (CPU)
  ImageResult batch;        // segment() on the same final map; time_ms = that one call (CPU)
  int scans = 0;
  int updates = 0;
  std::string stop_reason;
  double explored = 0.0;    // known free cells / reachable free cells of the ground truth
  UpdateTimes incremental_times;       // CPU time
  UpdateTimes incremental_wall_times;  // wall-clock time of the same updates
  UpdateTimes batch_times;             // over the compared updates (empty unless compare_batch), CPU
  UpdateTimes incremental_compared;    // the incremental times of exactly those updates
  std::vector<double> update_ms;       // every update, CPU
  std::vector<double> update_wall_ms;  // every update, wall clock
  std::vector<double> batch_update_ms; // compared updates only
  std::vector<double> paired_update_ms;// incremental time of each compared update, same order
  int batch_updates = 0;               // updates on which the segmenter itself fell back to batch
  std::size_t peak_state_bytes = 0;
  StabilityReport stability;
};

// Explores every selected image (maps in order, variants in options' order): the robot explores the
// image itself; the final incremental labels and segment() on the same final map are scored against
// the map's ground truth. A failure (unreadable file, error) becomes a failed result, never a throw.
std::vector<IncrementalImageResult> run_incremental_dataset(const std::vector<DatasetMap>& maps,
                                                            const IncrementalDatasetOptions& options);

// The incremental ImageResults (for format_results_table / format_summary) and the batch ones.
std::vector<ImageResult> incremental_image_results(const std::vector<IncrementalImageResult>& results);
std::vector<ImageResult> batch_image_results(const std::vector<IncrementalImageResult>& results);

// results_csv() of the incremental results plus the columns
// updates,update_median_ms,update_p95_ms,update_max_ms,batch_update_median_ms
// (the last one empty unless batch was compared on the same updates).
std::string incremental_results_csv(const std::vector<IncrementalImageResult>& results);

// Markdown table of per-update times per image: updates, incremental median / p95 / max, and when
// compared, batch median on the same updates and the ratio of the medians.
std::string format_update_times_table(const std::vector<IncrementalImageResult>& results);

// The whole report of an incremental dataset run, as `topocut evaluate --mode incremental` prints
// it: the per-image table and summary of the final incremental maps (the same tables as batch
// mode), the summary of batch on the same final maps, and the per-update time tables.
std::string format_incremental_report(const std::vector<IncrementalImageResult>& results, const std::string& method);

// Markdown summary over all images: all updates pooled (median, p95, max), batch on the same
// updates and the speed-up, quality of incremental and batch on the final maps, peak state.
std::string format_incremental_summary(const std::vector<IncrementalImageResult>& results);

}  // namespace topocut
