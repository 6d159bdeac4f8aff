#pragma once
// A real robot's exploration replayed from its laser log: the occupancy grid of pipeline C is built
// scan by scan (IncrementalWallMap), and every scan that changes it goes to the incremental
// segmenter, timed update by update, as run_exploration() does for the simulated robot.
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/exploration/exploration_run.h"
#include "topocut/exploration/room_stability.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/walls/posed_scan.h"
#include "topocut/walls/walls_pipeline.h"

namespace topocut {

// What the callback of replay_log sees after each update.
struct ReplayFrame {
  int update = 0;                       // 1-based
  int scan = 0;                         // 1-based scan that caused it
  const OccupancyGrid& grid;            // the grid the segmenter was given
  const Segmentation& segmentation;     // the incremental result for it
  const std::vector<Point2>& path;      // laser positions so far
  Pose2 pose;                           // the laser's pose at this scan
};

struct LogReplayOptions {
  WallsOptions walls;              // line extraction and grid (walls are not merged: see IncrementalWallMap)
  // The segmenter's options: by default those `walls --segment` uses (wall_map_segment_options()),
  // without the cleaning, which is not incremental.
  IncrementalOptions incremental = [] {
    IncrementalOptions o;
    o.segment = wall_map_segment_options();
    o.segment.clean = false;
    return o;
  }();
  // Also time segment(grid, incremental.segment) on every batch_every-th update and the last.
  bool compare_batch = false;
  int batch_every = 1;
  std::function<void(const ReplayFrame&)> on_update;       // may be empty
  std::function<void(const std::string&)> progress;        // occasional one-line status; may be empty
};

struct LogReplay {
  std::vector<UpdateRecord> updates;  // one per scan that changed the grid
  int scans = 0;
  std::vector<Point2> path;           // every scan's laser position, in order
  OccupancyGrid final_map;            // the grid after the last scan (its own copy)
  Segmentation incremental;           // after the last update
  Segmentation batch;                 // segment() on final_map
  double batch_final_ms = 0.0;        // CPU time of that call
  StabilityReport stability;          // of the incremental labels, update by update
  std::size_t peak_state_bytes = 0;   // largest IncrementalSegmenter::state_bytes()
};

// Replays the scans in order. Throws Error if there are no scans, on invalid options, or when the
// segmenter throws (see IncrementalSegmenter::update).
LogReplay replay_log(std::span<const PosedScan> scans, const LogReplayOptions& options = {});

}  // namespace topocut
