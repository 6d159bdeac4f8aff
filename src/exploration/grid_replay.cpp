#include "topocut/exploration/grid_replay.h"

#include <algorithm>

#include "exploration/timed_update.h"
#include "topocut/core/error.h"

namespace topocut {

namespace {

// The end of a replay: the final grid and labels as own copies, batch on the final grid.
void finish(GridReplay& run, const IncrementalSegmenter& segmenter, const OccupancyGrid& grid,
            const GridReplayOptions& options) {
  run.final_map = grid;
  run.final_map.cells = grid.cells.clone();
  run.incremental = segmenter.result();
  run.incremental.labels = segmenter.result().labels.clone();
  run.batch = detail::final_batch(run.final_map, options.incremental.segment, options.compare_batch, run.updates,
                                  &run.batch_final_ms);
}

}  // namespace

GridReplay replay_grids(const GridSource& source, const GridReplayOptions& options) {
  if (options.batch_every < 1) throw Error("batch comparison needs an interval of at least one update");
  IncrementalSegmenter segmenter(options.incremental);
  StabilityTracker stability;
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
    UpdateRecord record = detail::timed_update(segmenter, grid, options.use_hint ? &step.changed : nullptr,
                                               options.compare_batch && update % options.batch_every == 0);
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
  finish(run, segmenter, *last, options);
  run.stability = stability.report();
  return run;
}

}  // namespace topocut
