#pragma once
// A growing map replayed into the incremental segmenter: whatever produces the grids (the simulated
// robot of run_exploration(), a laser log turned into grids scan by scan by the walls module), every
// grid that changed goes to the IncrementalSegmenter, timed update by update, with the stability of
// the room ids and, when asked, batch segment() on the same grids for comparison.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"
#include "topocut/core/segmentation.h"
#include "topocut/exploration/room_stability.h"
#include "topocut/scan/scan.h"
#include "topocut/segmentation/incremental_segmenter.h"

namespace topocut {

// One scan of the source: the grid after it and the cells it changed.
struct GridStep {
  const OccupancyGrid* grid = nullptr;  // must stay valid (and at the same address) until the replay ends
  cv::Rect changed;                     // empty: the scan changed nothing and the segmenter is not asked
  Pose2 pose;                           // the sensor's pose at this scan
};

// Pulls the next step into its argument; returns false when there is none left.
using GridSource = std::function<bool(GridStep&)>;

// The steps of a source shaped like Explorer: bool next() takes the next scan, known_map() is the
// grid after it, changed() the cells it changed, pose() the sensor's pose (Explorer; the walls
// module's WallMapReplay). source must outlive the returned function.
template <class Source>
GridSource steps_of(Source& source) {
  return [&source](GridStep& step) {
    if (!source.next()) return false;
    step = {&source.known_map(), source.changed(), source.pose()};
    return true;
  };
}

// What the callback of replay_grids sees after each update.
struct ReplayFrame {
  int update = 0;                       // 1-based
  int scan = 0;                         // 1-based scan that caused it
  const OccupancyGrid& grid;            // the grid the segmenter was given
  const Segmentation& segmentation;     // the incremental result for it
  const std::vector<Point2>& path;      // sensor positions so far
  Pose2 pose;                           // the sensor's pose at this scan
};

struct GridReplayOptions {
  IncrementalOptions incremental;
  // Also time segment(grid, incremental.segment) on every batch_every-th update and the last.
  bool compare_batch = false;
  int batch_every = 1;
  bool use_hint = true;    // hand the step's changed rectangle to the segmenter (it also works without)
  // At the end the map is at rest: the last grid is segmented again as a whole
  // (IncrementalSegmenter::resegment()), so the run ends on batch's rooms with the ids carried; the
  // stability counts that step as one more update. false: the run ends on the last windowed update.
  bool resegment_at_rest = true;
  int progress_every = 100;  // updates between two progress lines
  std::function<void(const ReplayFrame&)> on_update;  // may be empty
  std::function<void(const std::string&)> progress;   // occasional one-line status; may be empty
};

// The batch comparison's rows (--compare-batch, --batch-every), for an options struct that holds
// compare_batch and batch_every (GridReplayOptions, ExplorationRunOptions): one spelling, help and
// range for every command that replays.
template <typename Options>
std::vector<OptionRow<Options>> batch_comparison_rows() {
  return {switch_row("compare-batch", &Options::compare_batch,
                     "also run the batch segmenter on every update, timed, with its own churn (ids carried by overlap)"),
          field_row("batch-every", "N", OptionRange::kCount, &Options::batch_every,
                    "with --compare-batch: only every N-th update (and the last)")};
}

// One update: a scan that changed the grid. Times are process CPU time (immune to other programs on
// a shared machine), with the wall-clock time beside them.
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

struct GridReplay {
  std::vector<UpdateRecord> updates;  // one per scan that changed the grid
  int scans = 0;
  std::vector<Point2> path;           // every scan's sensor position, in order
  OccupancyGrid final_map;            // the grid after the last scan (its own copy)
  Segmentation incremental;           // after the last update (and the resegmentation at rest)
  int windowed_rooms = 0;             // rooms after the last update, before the resegmentation
  Segmentation batch;                 // segment() on final_map
  double batch_final_ms = 0.0;        // CPU time of that call
  StabilityReport stability;          // of the incremental labels, update by update
  // Batch's own stability on the same updates (the compared ones, with compare_batch; empty
  // otherwise): segment()'s labels with each room's id carried by overlap from the previous compared
  // update (IdCarrier), the reference the incremental churn is read against.
  StabilityReport batch_stability;
  std::size_t peak_state_bytes = 0;   // largest IncrementalSegmenter::state_bytes()
};

// Replays the steps of source in order until it has none left. Throws Error on invalid options, a
// source without any step, or when the segmenter throws (see IncrementalSegmenter::update).
GridReplay replay_grids(const GridSource& source, const GridReplayOptions& options);

}  // namespace topocut
