#include "topocut/exploration/log_replay.h"

#include <algorithm>

#include "exploration/timed_update.h"
#include "topocut/core/error.h"
#include "topocut/walls/wall_extraction.h"
#include "topocut/walls/wall_map.h"

namespace topocut {

namespace {

// Every scan's wall segments, extracted before the replay: the grid's frame must cover them all.
std::vector<std::vector<WallSegment>> segments_per_scan(std::span<const PosedScan> scans, const WallsOptions& options) {
  std::vector<std::vector<WallSegment>> out;
  out.reserve(scans.size());
  for (std::size_t i = 0; i < scans.size(); ++i)
    out.push_back(extract_wall_segments(scans[i].scan, scans[i].pose, options.extraction, static_cast<int>(i)));
  return out;
}

void finish(LogReplay& run, const IncrementalSegmenter& segmenter, const OccupancyGrid& grid, const LogReplayOptions& options) {
  run.final_map = grid;
  run.final_map.cells = grid.cells.clone();
  run.incremental = segmenter.result();
  run.incremental.labels = segmenter.result().labels.clone();
  run.batch = detail::final_batch(run.final_map, options.incremental.segment, options.compare_batch, run.updates,
                                  &run.batch_final_ms);
}

}  // namespace

LogReplay replay_log(std::span<const PosedScan> scans, const LogReplayOptions& options) {
  if (scans.empty()) throw Error("there are no laser scans to replay");
  if (options.batch_every < 1) throw Error("batch comparison needs an interval of at least one update");
  const std::vector<std::vector<WallSegment>> segments = segments_per_scan(scans, options.walls);
  std::vector<WallSegment> all;
  for (const auto& s : segments) all.insert(all.end(), s.begin(), s.end());
  IncrementalWallMap map(scans, all, options.walls.map);
  IncrementalSegmenter segmenter(options.incremental);
  StabilityTracker stability;
  LogReplay run;
  int update = 0;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    run.path.push_back({scans[i].pose.x, scans[i].pose.y});
    const cv::Rect changed = map.add(scans[i], segments[i]);
    if (changed.empty()) continue;  // nothing new: the segmenter is not asked
    ++update;
    const OccupancyGrid& grid = map.grid();
    UpdateRecord record = detail::timed_update(segmenter, grid, &changed,
                                               options.compare_batch && update % options.batch_every == 0);
    record.scan = static_cast<int>(i) + 1;
    stability.add(segmenter.result().labels, grid.origin, grid.resolution);
    run.updates.push_back(record);
    run.peak_state_bytes = std::max(run.peak_state_bytes, segmenter.state_bytes());
    if (options.on_update)
      options.on_update(ReplayFrame{update, record.scan, grid, segmenter.result(), run.path, scans[i].pose});
    if (options.progress && update % 100 == 0)
      options.progress("update " + std::to_string(update) + " (scan " + std::to_string(record.scan) + "): " +
                       std::to_string(record.rooms) + " rooms");
  }
  run.scans = static_cast<int>(scans.size());
  finish(run, segmenter, map.grid(), options);
  run.stability = stability.report();
  return run;
}

}  // namespace topocut
