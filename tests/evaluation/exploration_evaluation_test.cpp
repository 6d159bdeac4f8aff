// Exploration runs scored against ground truth, reported, drawn, and run over a dataset.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "exploration/offices_map.h"
#include "topocut/core/error.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/exploration_frame.h"
#include "topocut/evaluation/incremental_dataset.h"
#include "topocut/evaluation/incremental_dataset_report.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/exploration/exploration_run.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {
namespace {

namespace fs = std::filesystem;
using test::expect_every_free_cell_labelled;
using test::offices;

TEST(ExplorationRun, EveryUpdateIsSegmentedAndTheEndMatchesBatch) {
  const OccupancyGrid world = offices();
  ExplorationRunOptions options;
  options.compare_batch = true;
  int seen = 0;
  options.on_update = [&](const ExplorationFrame& frame) {
    ++seen;
    EXPECT_EQ(frame.update, seen);
    expect_every_free_cell_labelled(frame.grid, frame.segmentation);
  };
  const ExplorationRun run = run_exploration(world, options);
  ASSERT_FALSE(run.updates.empty());
  EXPECT_EQ(static_cast<int>(run.updates.size()), seen);
  EXPECT_LE(static_cast<int>(run.updates.size()), run.scans);
  // Stability is measured on every update after the first; the incremental segmenter hands out
  // fresh ids only, so the ids ever used are at least the final rooms.
  // The map at rest is segmented whole at the end, which counts as one more step when it changes a
  // label (a split or merge still held back: IncrementalOptions::split_after, merge_after).
  EXPECT_GE(run.stability.churn.size(), run.updates.size() - 1);
  EXPECT_LE(run.stability.churn.size(), run.updates.size());
  EXPECT_EQ(run.stability.final_rooms, static_cast<int>(run.incremental.rooms.size()));
  EXPECT_GE(run.stability.distinct_ids, run.stability.final_rooms);
  EXPECT_EQ(run.stop_reason, "no reachable frontier left");
  int free_changes = 0;
  for (const UpdateRecord& u : run.updates) {
    EXPECT_GE(u.incremental_ms, 0.0);
    EXPECT_GE(u.batch_ms, 0.0);  // compared on every update
    EXPECT_EQ(u.rooms, u.batch_rooms >= 0 ? u.rooms : -1);
    free_changes += u.changed_cells > 0;  // some scans only add obstacle cells
  }
  EXPECT_GT(free_changes, static_cast<int>(run.updates.size()) / 2);
  EXPECT_TRUE(run.updates.front().batch_update);  // the first update is a batch one
  expect_every_free_cell_labelled(run.final_map, run.incremental);
  expect_every_free_cell_labelled(run.final_map, run.batch);
  EXPECT_EQ(run.incremental.rooms.size(), run.batch.rooms.size());
  EXPECT_GT(run.known_free_cells, 0.97 * run.reachable_free_cells);
  // Score both against the world's own rooms (the four rooms and the corridor, split at the doors).
  cv::Mat truth = cv::Mat(world.cells == kFree).clone();
  for (int x = 4, k = 0; k < 4; ++k) {
    const int width = std::vector<int>{70, 60, 80, 70}[static_cast<std::size_t>(k)];
    truth(cv::Rect(x + width / 2 - 9, 138, 18, 1)).setTo(0);  // a separator line across each door
    x += width + 4;
  }
  const PrecisionRecall inc = evaluate_against_ground_truth(run.incremental.labels, truth);
  const PrecisionRecall bat = evaluate_against_ground_truth(run.batch.labels, truth);
  EXPECT_NEAR(inc.recall, bat.recall, 0.015);
  EXPECT_NEAR(inc.precision, bat.precision, 0.015);
  EXPECT_GT(run.peak_state_bytes, 6 * world.cells.total() - 1);
}
TEST(ExplorationRun, FindGroundTruth) {
  const fs::path dir = fs::temp_directory_path() / ("topocut_find_gt_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const char* name : {"lab.png", "lab_furnitures.png", "lab_gt_segmentation.png", "other.png"})
    std::ofstream(dir / name) << "x";
  EXPECT_EQ(find_ground_truth((dir / "lab.png").string()), (dir / "lab_gt_segmentation.png").string());
  EXPECT_EQ(find_ground_truth((dir / "lab_furnitures.png").string()), (dir / "lab_gt_segmentation.png").string());
  EXPECT_EQ(find_ground_truth((dir / "other.png").string()), "");
  EXPECT_EQ(find_ground_truth((dir / "lab_gt_segmentation.png").string()), "");
  fs::remove_all(dir);
}
TEST(ExplorationRun, IncrementalCsvAddsTheUpdateColumns) {
  IncrementalImageResult ok;
  ok.incremental.map = "lab";
  ok.incremental.ok = true;
  ok.incremental.rooms = 5;
  ok.incremental.gt_rooms = 6;
  ok.incremental.recall = 0.9;
  ok.incremental.precision = 0.8;
  ok.incremental.time_ms = 12.5;
  ok.updates = 40;
  ok.incremental_times = time_statistics({1.0, 2.0, 3.0});
  ok.batch_times = time_statistics({10.0, 30.0});
  IncrementalImageResult no_batch = ok;
  no_batch.incremental.variant = Variant::kFurnished;
  no_batch.batch_times = {};
  IncrementalImageResult failed;
  failed.incremental.map = "broken";
  failed.incremental.error = "cannot read";
  const std::string csv = incremental_results_csv({ok, no_batch, failed});
  std::istringstream in(csv);
  std::string header, a, b, c;
  std::getline(in, header);
  std::getline(in, a);
  std::getline(in, b);
  std::getline(in, c);
  EXPECT_EQ(header,
            "map,variant,rooms,gt_rooms,recall,precision,time_ms,matches,free_segments,free_rooms,f1,pq,"
            "segments_per_room,precision_inside,far_share,status,updates,update_median_ms,update_p95_ms,"
            "update_max_ms,batch_update_median_ms");
  EXPECT_NE(a.find(",40,2.0000,3.0000,3.0000,20.0000"), std::string::npos) << a;
  EXPECT_EQ(b.substr(b.size() - 1), ",");  // no batch comparison: last column empty
  EXPECT_EQ(std::count(c.begin(), c.end(), ','), 20);
  EXPECT_EQ(c.rfind("broken,", 0), 0u);
}
// The pooled table splits the updates into windowed and whole-map ones (which make the tail).
TEST(ExplorationRun, SummarySplitsWindowedAndWholeMapUpdates) {
  IncrementalImageResult r;
  r.incremental.ok = true;
  r.updates = 4;
  r.update_ms = {1.0, 3.0, 2.0, 40.0};
  r.update_wall_ms = r.update_ms;
  r.whole_map_update = {0, 0, 0, 1};
  const std::string out = format_incremental_summary({r});
  const auto row = [&out](const std::string& label) {
    const std::size_t at = out.find("| " + label + " ");
    return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
  };
  const std::string windowed = row("incremental, windowed updates"), whole = row("incremental, whole-map updates");
  ASSERT_FALSE(windowed.empty()) << out;
  ASSERT_FALSE(whole.empty()) << out;
  EXPECT_NE(windowed.find("| 2.000 "), std::string::npos) << windowed;  // the median of 1, 3 and 2
  EXPECT_NE(windowed.find("| 3  "), std::string::npos) << windowed;
  EXPECT_NE(whole.find("| 40.000 "), std::string::npos) << whole;
  EXPECT_NE(whole.find("| 1  "), std::string::npos) << whole;
  // Without whole-map updates, no such row.
  r.whole_map_update = {0, 0, 0, 0};
  EXPECT_EQ(format_incremental_summary({r}).find("whole-map updates"), std::string::npos);
}
TEST(ExplorationFrame, DrawsMapRoomsRobotAndPath) {
  const OccupancyGrid world = offices();
  OccupancyGrid known = world;
  known.cells = cv::Mat(world.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
  world.cells(cv::Rect(0, 136, 300, 44)).copyTo(known.cells(cv::Rect(0, 136, 300, 44)));
  const Segmentation s = segment(known);
  FrameOptions options;
  options.scale = 2;
  options.caption = "update 1";
  const Pose2 robot{5.0, 1.0, 0.0};
  const cv::Mat frame = render_exploration_frame(known, s, {{2.0, 1.0}, {5.0, 1.0}}, robot, options);
  ASSERT_EQ(frame.size(), cv::Size(600, 360));
  ASSERT_EQ(frame.type(), CV_8UC3);
  // Unknown space stays grey, far from the robot and the caption.
  const cv::Vec3b unknown = frame.at<cv::Vec3b>(100, 500);
  EXPECT_EQ(unknown[0], unknown[1]);
  EXPECT_EQ(unknown[1], unknown[2]);
  // The robot is a red disc (radius 0.25 m = 10 px) at its position: (5 m, 1 m) is cell
  // (99.5, 159.5) -> pixel (199, 319); 6 px below its centre is off its white heading line.
  const cv::Vec3b body = frame.at<cv::Vec3b>(325, 199);
  EXPECT_GT(body[2], 180);
  EXPECT_LT(body[0], 100);
  EXPECT_THROW(render_exploration_frame(world, Segmentation{}, {}, robot), Error);
}
// Integration on the real maps: exploration ends on every map tried, the known map never marks
// free what the map says is not, and incremental and batch agree at the end.
TEST(ExplorationDataset, TerminatesOnRealMaps) {
  const std::string folder = std::string(TOPOCUT_SHARED_DIR "/datasets/bormann");
  if (!fs::is_directory(folder)) GTEST_SKIP() << "dataset not found at " << folder;
  IncrementalDatasetOptions options;
  options.run.variants = {Variant::kPlain, Variant::kFurnished};
  const std::vector<DatasetMap> maps = select_maps(discover_dataset(folder), {"Freiburg52_scan", "lab_c_scan"});
  const std::vector<IncrementalImageResult> results = run_incremental_dataset(maps, options);
  ASSERT_EQ(results.size(), 4u);
  for (const IncrementalImageResult& r : results) {
    SCOPED_TRACE(r.incremental.map + " " + to_string(r.incremental.variant));
    ASSERT_TRUE(r.incremental.ok) << r.incremental.error;
    EXPECT_EQ(r.stop_reason, "no reachable frontier left");
    EXPECT_GT(r.updates, 50);
    EXPECT_GT(r.explored, 0.9);
    EXPECT_LE(r.explored, 1.0);
    EXPECT_NEAR(r.incremental.recall, r.batch.recall, 0.08);
    EXPECT_NEAR(r.incremental.precision, r.batch.precision, 0.08);
  }
  // The safety property, checked directly on one furnished map (grey furniture blocks the laser).
  const OccupancyGrid world = load_map(maps[0].furnished);
  Explorer explorer(world);
  while (explorer.next()) {
  }
  EXPECT_EQ(cv::countNonZero((explorer.known_cells() == kFree) & (world.cells != kFree)), 0);
}

}  // namespace
}  // namespace topocut
