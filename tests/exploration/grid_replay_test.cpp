// replay_grids() on a hand-made sequence of grids: a map revealed room by room.
#include "topocut/exploration/grid_replay.h"

#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "exploration/offices_map.h"
#include "topocut/core/error.h"

namespace topocut {
namespace {

using test::expect_every_free_cell_labelled;
using test::offices;

// The offices revealed in four steps: the corridor, then the corridor again (nothing new), then the
// first two rooms, then everything.
struct Reveal {
  OccupancyGrid world = offices();
  OccupancyGrid grid;
  std::vector<cv::Rect> parts{cv::Rect(0, 136, 300, 44), cv::Rect(0, 136, 300, 44), cv::Rect(0, 0, 150, 180),
                              cv::Rect(0, 0, 300, 180)};
  std::size_t next_part = 0;

  Reveal() {
    grid = world;
    grid.cells = cv::Mat(world.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
  }
  bool next(GridStep& step) {
    if (next_part == parts.size()) return false;
    const cv::Mat before = grid.cells.clone();
    const cv::Rect part = parts[next_part++];
    world.cells(part).copyTo(grid.cells(part));
    step = {&grid, cv::boundingRect(before != grid.cells), Pose2{1.0 * next_part, 2.0, 0.0}};
    return true;
  }
};

TEST(GridReplay, EveryChangedGridIsAnUpdateAndTheEndMatchesBatch) {
  Reveal reveal;
  GridReplayOptions options;
  options.compare_batch = true;
  int seen = 0;
  options.on_update = [&](const ReplayFrame& frame) {
    ++seen;
    EXPECT_EQ(frame.update, seen);
    EXPECT_EQ(static_cast<int>(frame.path.size()), frame.scan);
    expect_every_free_cell_labelled(frame.grid, frame.segmentation);
  };
  const GridReplay run = replay_grids([&](GridStep& step) { return reveal.next(step); }, options);
  EXPECT_EQ(run.scans, 4);
  ASSERT_EQ(run.updates.size(), 3u);  // the repeated corridor changed nothing
  EXPECT_EQ(seen, 3);
  EXPECT_EQ(run.updates[0].scan, 1);
  EXPECT_EQ(run.updates[1].scan, 3);
  EXPECT_EQ(run.updates[2].scan, 4);
  for (const UpdateRecord& u : run.updates) EXPECT_GE(u.batch_ms, 0.0);
  ASSERT_EQ(run.path.size(), 4u);
  EXPECT_EQ(run.path[3].x, 4.0);
  EXPECT_EQ(cv::countNonZero(run.final_map.cells != reveal.world.cells), 0);
  expect_every_free_cell_labelled(run.final_map, run.incremental);
  EXPECT_EQ(run.incremental.rooms.size(), run.batch.rooms.size());
  EXPECT_EQ(run.stability.churn.size(), 2u);
  EXPECT_GT(run.peak_state_bytes, 0u);
}

TEST(GridReplay, BadInputIsRefused) {
  GridReplayOptions options;
  EXPECT_THROW(replay_grids([](GridStep&) { return false; }, options), Error);
  Reveal reveal;
  options.batch_every = 0;
  EXPECT_THROW(replay_grids([&](GridStep& step) { return reveal.next(step); }, options), Error);
}

}  // namespace
}  // namespace topocut
