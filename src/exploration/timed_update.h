#pragma once
// One timed step of an incremental run (simulated exploration or log replay): the incremental
// update and, when asked, batch segment() on the same grid, both in process CPU time (immune to
// other programs on a shared machine) with the wall clock beside.
#include <vector>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/exploration/grid_replay.h"
#include "topocut/segmentation/incremental_segmenter.h"

namespace topocut::detail {

// Updates segmenter with grid (with the changed-rectangle hint when hint is non-null) and, when
// batch is true, also times segment(grid, segmenter.options().segment), whose result goes to
// *batch_result when that is non-null. Fills every field of the record but scan.
UpdateRecord timed_update(IncrementalSegmenter& segmenter, const OccupancyGrid& grid, const cv::Rect* hint, bool batch,
                          Segmentation* batch_result = nullptr);

// segment(grid, options) with its CPU and wall-clock times in milliseconds.
Segmentation timed_segment(const OccupancyGrid& grid, const SegmentOptions& options, double* cpu_ms, double* wall_ms);

// The end of a run: batch segment() of the final map, timed (returned with its CPU time in
// *cpu_ms); with compare_batch it also fills the last update's batch fields if they are empty, so
// that the last update is always compared.
Segmentation final_batch(const OccupancyGrid& final_map, const SegmentOptions& options, bool compare_batch,
                         std::vector<UpdateRecord>& updates, double* cpu_ms);

}  // namespace topocut::detail
