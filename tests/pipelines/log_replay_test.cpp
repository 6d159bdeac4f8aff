// A laser log replayed scan by scan into the incremental segmenter: the walls module's grid of each
// scan (WallMapReplay) through exploration's replay_grids(), the join `topocut walls --incremental` makes.
#include "topocut/exploration/grid_replay.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "exploration/offices_map.h"
#include "topocut/core/error.h"
#include "topocut/scan/laser_simulator.h"
#include "topocut/segmentation/segmenter.h"
#include "topocut/segmentation/wall_map_segment_options.h"
#include "topocut/walls/wall_map_replay.h"

namespace topocut {
namespace {

// Three rooms in a row, 15 m by 6 m, joined by 1 m doors; the robot walks from the first to the
// last, looking ahead, and scans the middle twice from the same pose.
std::vector<PosedScan> walk() {
  const std::vector<Segment2> plan{{{0, 0}, {15, 0}},   {{15, 0}, {15, 6}},  {{15, 6}, {0, 6}},
                                   {{0, 6}, {0, 0}},    {{5, 0}, {5, 2.5}},  {{5, 3.5}, {5, 6}},
                                   {{10, 0}, {10, 2.5}}, {{10, 3.5}, {10, 6}}};
  LaserSpec spec;
  spec.field_of_view = M_PI;
  spec.angular_resolution = M_PI / 180.0;
  spec.range_max = 20.0;
  spec.noise_stddev = 0.0;
  std::mt19937 rng(1);
  std::vector<PosedScan> scans;
  for (double x = 1.0; x <= 14.0; x += 0.5) {
    for (const double heading : {0.0, M_PI}) {
      PosedScan s;
      s.pose = {x, 3.0, heading};
      s.scan = simulate_scan(plan, s.pose, spec, rng).scan;
      scans.push_back(s);
      if (x == 7.5) scans.push_back(s);
    }
  }
  return scans;
}

// What `walls --incremental` does by default.
GridReplayOptions log_options() {
  GridReplayOptions o;
  o.incremental = wall_map_incremental_options();
  return o;
}

GridReplay replay_log(const std::vector<PosedScan>& scans, const GridReplayOptions& options = log_options()) {
  WallMapReplay log_map(scans);
  return replay_grids(steps_of(log_map), options);
}

TEST(LogReplay, EveryChangeIsSegmentedAndTheEndMatchesBatch) {
  const std::vector<PosedScan> scans = walk();
  GridReplayOptions options = log_options();
  options.compare_batch = true;
  int seen = 0;
  options.on_update = [&](const ReplayFrame& frame) {
    ++seen;
    EXPECT_EQ(frame.update, seen);
    EXPECT_EQ(static_cast<int>(frame.path.size()), frame.scan);
    test::expect_every_free_cell_labelled(frame.grid, frame.segmentation, options.incremental.segment);
  };
  const GridReplay run = replay_log(scans, options);
  EXPECT_EQ(run.scans, static_cast<int>(scans.size()));
  EXPECT_EQ(static_cast<int>(run.updates.size()), seen);
  // The repeated scan changed nothing and was not handed to the segmenter.
  EXPECT_LT(static_cast<int>(run.updates.size()), run.scans);
  for (const UpdateRecord& u : run.updates) {
    EXPECT_GE(u.batch_ms, 0.0);
    EXPECT_GT(u.rooms, 0);
  }
  // One churn figure per update after the first, and one more when the map at rest segmented as a
  // whole changed a label; batch's own on the same updates.
  const std::size_t rest = run.windowed_rooms != static_cast<int>(run.incremental.rooms.size()) ? 1 : 0;
  EXPECT_GE(run.stability.churn.size() + 1, run.updates.size());
  EXPECT_LE(run.stability.churn.size(), run.updates.size());
  if (rest) {
    EXPECT_EQ(run.stability.churn.size(), run.updates.size());
  }
  EXPECT_EQ(run.batch_stability.churn.size(), run.updates.size() - 1);
  EXPECT_EQ(run.stability.final_rooms, static_cast<int>(run.incremental.rooms.size()));
  // The final grid is the scan-by-scan wall map, and batch on it finds the three rooms; the run
  // ends on them (the map at rest segmented as a whole), the windowed rooms within one of them.
  EXPECT_EQ(run.batch.rooms.size(), 3u);
  EXPECT_EQ(run.incremental.rooms.size(), 3u);
  EXPECT_LE(std::abs(run.windowed_rooms - 3), 1);
  EXPECT_EQ(cv::countNonZero((run.incremental.labels > 0) != (run.batch.labels > 0)), 0);
  test::expect_every_free_cell_labelled(run.final_map, run.incremental, options.incremental.segment);
}

TEST(LogReplay, BadInputIsRefused) {
  EXPECT_THROW(replay_log(std::vector<PosedScan>{}), Error);
  GridReplayOptions options = log_options();
  options.batch_every = 0;
  EXPECT_THROW(replay_log(walk(), options), Error);
}

}  // namespace
}  // namespace topocut
