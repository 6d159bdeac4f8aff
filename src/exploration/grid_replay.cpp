#include "topocut/exploration/grid_replay.h"

#include <algorithm>

#include "exploration/timed_update.h"
#include "topocut/core/error.h"
#include "topocut/segmentation/carried_ids.h"

namespace topocut {

namespace {

// Batch's labels of the compared updates, ids carried by overlap, as the incremental labels are.
struct BatchIds {
  IdCarrier carrier;
  StabilityTracker tracker;

  void add(const Segmentation& batch) {
    const Segmentation carried = carrier.carry(batch);
    tracker.add(carried.labels, carried.origin, carried.resolution);
  }
};

// The end of a replay: the final grid and labels as own copies, batch on the final grid (counted
// in batch's stability when the last update was not compared yet).
void finish(GridReplay& run, IncrementalSegmenter& segmenter, const OccupancyGrid& grid,
            const GridReplayOptions& options, BatchIds& batch_ids, StabilityTracker& stability) {
  run.final_map = grid;
  run.final_map.cells = grid.cells.clone();
  run.windowed_rooms = static_cast<int>(segmenter.result().rooms.size());
  if (options.resegment_at_rest && !run.updates.empty()) {
    const cv::Mat windowed = segmenter.result().labels.clone();
    segmenter.resegment();
    // Counted as an update only when it changed a label.
    if (cv::countNonZero(windowed != segmenter.result().labels) > 0)
      stability.add(segmenter.result().labels, grid.origin, grid.resolution);
  }
  run.incremental = segmenter.result();
  run.incremental.labels = segmenter.result().labels.clone();
  const bool last_compared = run.updates.empty() || run.updates.back().batch_ms >= 0.0;
  run.batch = detail::final_batch(run.final_map, options.incremental.segment, options.compare_batch, run.updates,
                                  &run.batch_final_ms);
  if (options.compare_batch && !last_compared) batch_ids.add(run.batch);
  if (options.compare_batch) run.batch_stability = batch_ids.tracker.report();
}

}  // namespace

GridReplay replay_grids(const GridSource& source, const GridReplayOptions& options) {
  if (options.batch_every < 1) throw Error("batch comparison needs an interval of at least one update");
  IncrementalSegmenter segmenter(options.incremental);
  StabilityTracker stability;
  BatchIds batch_ids;
  GridReplay run;
  const OccupancyGrid* last = nullptr;
  int update = 0;
  GridStep step;
  while (source(step)) {
    if (step.grid == nullptr) throw Error("internal: a replayed step has no grid");
    last = step.grid;
    ++run.scans;
    run.path.push_back({step.pose.x, step.pose.y});
    if (step.changed.empty()) continue;  // nothing new: the segmenter is not asked
    ++update;
    const OccupancyGrid& grid = *step.grid;
    const bool compared = options.compare_batch && update % options.batch_every == 0;
    Segmentation batch;
    UpdateRecord record =
        detail::timed_update(segmenter, grid, options.use_hint ? &step.changed : nullptr, compared, &batch);
    if (compared) batch_ids.add(batch);
    record.scan = run.scans;
    stability.add(segmenter.result().labels, grid.origin, grid.resolution);
    run.updates.push_back(record);
    run.peak_state_bytes = std::max(run.peak_state_bytes, segmenter.state_bytes());
    if (options.on_update)
      options.on_update(ReplayFrame{update, record.scan, grid, segmenter.result(), run.path, step.pose});
    if (options.progress && options.progress_every > 0 && update % options.progress_every == 0)
      options.progress("update " + std::to_string(update) + " (scan " + std::to_string(record.scan) + "): " +
                       std::to_string(record.rooms) + " rooms");
  }
  if (last == nullptr) throw Error("there is no grid to replay");
  finish(run, segmenter, *last, options, batch_ids, stability);
  run.stability = stability.report();
  return run;
}

}  // namespace topocut
