#pragma once
// The incremental runner over a Bormann-format dataset: the simulated robot explores every image,
// and the final incremental labels and batch segment() of the same final map are scored against
// the map's ground truth, for `topocut evaluate --mode incremental` and the incremental benchmark.
#include <cstddef>
#include <string>
#include <vector>

#include "topocut/core/time_statistics.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/exploration/exploration_run.h"
#include "topocut/exploration/room_stability.h"

namespace topocut {

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
  TimeStatistics incremental_times;       // CPU time
  TimeStatistics incremental_wall_times;  // wall-clock time of the same updates
  TimeStatistics batch_times;             // over the compared updates (empty unless compare_batch), CPU
  TimeStatistics incremental_compared;    // the incremental times of exactly those updates
  std::vector<double> update_ms;       // every update, CPU
  std::vector<double> update_wall_ms;  // every update, wall clock
  std::vector<double> batch_update_ms; // compared updates only
  std::vector<double> paired_update_ms;// incremental time of each compared update, same order
  std::vector<unsigned char> whole_map_update;  // per update (update_ms' order): 1 if it decomposed everything again
  int batch_updates = 0;               // updates on which the segmenter itself fell back to batch
  std::size_t peak_state_bytes = 0;
  StabilityReport stability;
  StabilityReport batch_stability;  // batch's own on the compared updates, ids carried by overlap
  int windowed_rooms = 0;           // incremental rooms before the final map at rest was segmented as a whole
};

// Explores every selected image (maps in order, variants in options' order): the robot explores the
// image itself; the final incremental labels and segment() on the same final map are scored against
// the map's ground truth. A failure (unreadable file, error) becomes a failed result, never a throw.
std::vector<IncrementalImageResult> run_incremental_dataset(const std::vector<DatasetMap>& maps,
                                                            const IncrementalDatasetOptions& options);

// The incremental ImageResults (for format_results_table / format_summary) and the batch ones.
std::vector<ImageResult> incremental_image_results(const std::vector<IncrementalImageResult>& results);
std::vector<ImageResult> batch_image_results(const std::vector<IncrementalImageResult>& results);

}  // namespace topocut
