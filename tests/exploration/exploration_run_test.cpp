#include "topocut/exploration/exploration_run.h"

#include <gtest/gtest.h>

#include "exploration/offices_map.h"
#include "topocut/core/error.h"

namespace topocut {
namespace {

using test::expect_every_free_cell_labelled;
using test::offices;

TEST(ExplorationRun, BatchEverySamplesUpdatesAndAlwaysTheLast) {
  ExplorationRunOptions options;
  options.compare_batch = true;
  options.batch_every = 3;
  const ExplorationRun run = run_exploration(offices(), options);
  ASSERT_GT(run.updates.size(), 6u);
  for (std::size_t i = 0; i < run.updates.size(); ++i) {
    const bool compared = run.updates[i].batch_ms >= 0.0;
    EXPECT_EQ(compared, (i + 1) % 3 == 0 || i + 1 == run.updates.size()) << "update " << i + 1;
  }
  ExplorationRunOptions bad;
  bad.batch_every = 0;
  EXPECT_THROW(run_exploration(offices(), bad), Error);
}
TEST(ExplorationRun, HintAndNoHintGiveTheSameRooms) {
  ExplorationRunOptions with_hint, without_hint;
  without_hint.use_hint = false;
  const ExplorationRun a = run_exploration(offices(), with_hint);
  const ExplorationRun b = run_exploration(offices(), without_hint);
  ASSERT_EQ(a.updates.size(), b.updates.size());
  EXPECT_EQ(cv::countNonZero(a.incremental.labels != b.incremental.labels), 0);
  for (std::size_t i = 0; i < a.updates.size(); ++i) EXPECT_EQ(a.updates[i].rooms, b.updates[i].rooms);
}
TEST(ExplorationRun, GrowingMapIsSegmentedInItsWindow) {
  const OccupancyGrid world = offices();
  ExplorationRunOptions options;
  options.exploration.growing_map = true;
  const ExplorationRun run = run_exploration(world, options);
  ASSERT_EQ(run.final_map.cells.size(), run.window.size());
  expect_every_free_cell_labelled(run.final_map, run.incremental);
  const cv::Mat placed = labels_in_frame(run.incremental.labels, run.window, world.cells.size());
  EXPECT_EQ(cv::countNonZero(placed != 0), cv::countNonZero(run.incremental.labels != 0));
  // Same exploration as in the full frame: the same cells end up known.
  const ExplorationRun full = run_exploration(world, ExplorationRunOptions{});
  EXPECT_EQ(run.known_free_cells, full.known_free_cells);
  EXPECT_EQ(run.incremental.rooms.size(), run.batch.rooms.size());
}
TEST(ExplorationRun, LabelsInFrame) {
  cv::Mat labels = (cv::Mat_<int>(2, 3) << 1, 2, 0, 0, 3, 3);
  const cv::Mat out = labels_in_frame(labels, cv::Rect(1, 2, 3, 2), cv::Size(5, 5));
  EXPECT_EQ(out.at<int>(2, 1), 1);
  EXPECT_EQ(out.at<int>(2, 2), 2);
  EXPECT_EQ(out.at<int>(3, 3), 3);
  EXPECT_EQ(cv::countNonZero(out), 4);
  EXPECT_THROW(labels_in_frame(labels, cv::Rect(3, 2, 3, 2), cv::Size(5, 5)), Error);
  EXPECT_THROW(labels_in_frame(labels, cv::Rect(0, 0, 2, 2), cv::Size(5, 5)), Error);
}

}  // namespace
}  // namespace topocut
