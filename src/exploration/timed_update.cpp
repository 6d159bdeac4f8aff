#include "exploration/timed_update.h"

#include <chrono>
#include <utility>

#include <time.h>

#include "topocut/segmentation/segmenter.h"

namespace topocut::detail {

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of the whole process (all threads), in milliseconds.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

}  // namespace

Segmentation timed_segment(const OccupancyGrid& grid, const SegmentOptions& options, double* cpu, double* wall) {
  const Clock::time_point start = Clock::now();
  const double cpu_start = cpu_ms();
  Segmentation result = segment(grid, options);
  *cpu = cpu_ms() - cpu_start;
  *wall = milliseconds_since(start);
  return result;
}

UpdateRecord timed_update(IncrementalSegmenter& segmenter, const OccupancyGrid& grid, const cv::Rect* hint, bool batch,
                          Segmentation* batch_result) {
  UpdateRecord record;
  const Clock::time_point start = Clock::now();
  const double cpu_start = cpu_ms();
  const Segmentation& result = hint ? segmenter.update(grid, *hint) : segmenter.update(grid);
  record.incremental_ms = cpu_ms() - cpu_start;
  record.incremental_wall_ms = milliseconds_since(start);
  record.rooms = static_cast<int>(result.rooms.size());
  record.changed_cells = segmenter.last_update().changed_cells;
  record.batch_update = segmenter.last_update().kind == IncrementalUpdateReport::Kind::kBatch;
  if (batch) {
    Segmentation rooms = timed_segment(grid, segmenter.options().segment, &record.batch_ms, &record.batch_wall_ms);
    record.batch_rooms = static_cast<int>(rooms.rooms.size());
    if (batch_result) *batch_result = std::move(rooms);
  }
  return record;
}

Segmentation final_batch(const OccupancyGrid& final_map, const SegmentOptions& options, bool compare_batch,
                         std::vector<UpdateRecord>& updates, double* cpu) {
  double wall = 0.0;
  Segmentation batch = timed_segment(final_map, options, cpu, &wall);
  if (compare_batch && !updates.empty() && updates.back().batch_ms < 0.0) {
    updates.back().batch_ms = *cpu;
    updates.back().batch_wall_ms = wall;
    updates.back().batch_rooms = static_cast<int>(batch.rooms.size());
  }
  return batch;
}

}  // namespace topocut::detail
