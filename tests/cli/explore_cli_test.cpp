// `topocut explore` as a user runs it: the built binary, its exit codes, its report and its frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <opencv2/core.hpp>

#include "cli/cli_runner.h"
#include "io/test_images.h"

namespace {

namespace fs = std::filesystem;

using topocut::testing::CliResult;
using topocut::testing::file_text;
using topocut::testing::run_cli_line;

class ExploreCli : public ::testing::Test {
 protected:

  CliResult run(const std::string& args, const std::string& command_name = "explore") { return run_cli_line(dir_, command_name + " " + args); }

  // A 12 m x 7 m map (0.05 m/px): corridor below, three rooms with doors; and its ground truth with
  // the doors closed by a line, in the dataset's naming (X.png, X_gt_segmentation.png).
  fs::path write_map(const std::string& name, bool with_truth) {
    cv::Mat map(140, 240, CV_8UC1, cv::Scalar(0));
    map(cv::Rect(4, 100, 232, 36)).setTo(255);
    cv::Mat truth;
    int x = 4;
    for (const int width : {70, 80, 74}) {
      map(cv::Rect(x, 4, width, 92)).setTo(255);
      map(cv::Rect(x + width / 2 - 9, 96, 18, 4)).setTo(255);
      x += width + 4;
    }
    truth = map.clone();
    x = 4;
    for (const int width : {70, 80, 74}) {
      truth(cv::Rect(x + width / 2 - 9, 98, 18, 1)).setTo(0);
      x += width + 4;
    }
    const fs::path path = dir_ / (name + ".png");
    topocut::testing::write_test_image(path.string(), map);
    if (with_truth) topocut::testing::write_test_image((dir_ / (name + "_gt_segmentation.png")).string(), truth);
    return path;
  }

  topocut::testing::TempDir temp_;
  const fs::path dir_ = temp_.path();
};

double number_after(const std::string& text, const std::string& label) {
  const std::size_t at = text.find(label);
  if (at == std::string::npos) return -1.0;
  return std::atof(text.c_str() + at + label.size());
}

TEST_F(ExploreCli, HelpListsTheOptions) {
  const CliResult o = run("--help");
  EXPECT_EQ(o.code, 0);
  for (const char* option : {"--range", "--step", "--seed", "--compare-batch", "--frames", "--gt", "--grow"})
    EXPECT_NE(o.out.find(option), std::string::npos) << option;
}

TEST_F(ExploreCli, BadInputIsOneClearError) {
  const CliResult missing = run((dir_ / "nope.png").string());
  EXPECT_NE(missing.code, 0);
  EXPECT_NE(missing.err.find("topocut explore: error:"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("nope.png"), std::string::npos);

  std::ofstream(dir_ / "garbage.png") << "not an image";
  EXPECT_NE(run((dir_ / "garbage.png").string()).code, 0);

  const fs::path map = write_map("lab", false);
  const CliResult bad_range = run(map.string() + " --range=-1");
  EXPECT_NE(bad_range.code, 0);
  EXPECT_NE(bad_range.err.find("range"), std::string::npos) << bad_range.err;
  const CliResult wall_start = run(map.string() + " --start 0.01,0.01");
  EXPECT_NE(wall_start.code, 0);
  EXPECT_NE(wall_start.err.find("not in the map's free space"), std::string::npos) << wall_start.err;
  EXPECT_NE(run(map.string() + " --start nonsense").code, 0);
  EXPECT_NE(run("").code, 0);
}

TEST_F(ExploreCli, ReportsUpdatesTimesAndGroundTruthQuality) {
  const fs::path map = write_map("lab", true);
  const CliResult o = run(map.string() + " --compare-batch");
  ASSERT_EQ(o.code, 0) << o.err;
  const double updates = number_after(o.out, "updates: ");
  EXPECT_GT(updates, 3.0) << o.out;
  EXPECT_NE(o.out.find("no reachable frontier left"), std::string::npos) << o.out;
  EXPECT_GE(number_after(o.out, "incremental per update: median "), 0.0) << o.out;
  EXPECT_GE(number_after(o.out, "batch per update:       median "), 0.0) << o.out;
  EXPECT_NE(o.out.find("lab_gt_segmentation.png"), std::string::npos) << o.out;
  const double recall = number_after(o.out, "incremental: recall ");
  EXPECT_GT(recall, 80.0) << o.out;
  EXPECT_LE(recall, 100.0);
  // The run ends on the explored map segmented as a whole: batch's rooms, so batch's scores.
  EXPECT_EQ(recall, number_after(o.out, "batch:       recall ")) << o.out;
  // Batch's own churn on the same updates, in the incremental line's format, and the ratios.
  EXPECT_GE(number_after(o.out, "batch stability (ids carried by overlap): churn median "), 0.0) << o.out;
  EXPECT_NE(o.out.find("against batch: churn p95 "), std::string::npos) << o.out;

  // Without a ground truth there is no quality section; --gt names one explicitly.
  const fs::path plain = write_map("plain", false);
  const CliResult none = run(plain.string());
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_EQ(none.out.find("ground truth"), std::string::npos);
  EXPECT_EQ(none.out.find("batch stability"), std::string::npos);  // batch was not run
  const CliResult named = run(plain.string() + " --gt " + (dir_ / "lab_gt_segmentation.png").string());
  ASSERT_EQ(named.code, 0) << named.err;
  EXPECT_NE(named.out.find("ground truth"), std::string::npos);
}

TEST_F(ExploreCli, FramesAreWrittenForEveryUpdate) {
  const fs::path map = write_map("lab", false);
  const fs::path frames = dir_ / "frames";
  const CliResult o = run(map.string() + " --frames " + frames.string());
  ASSERT_EQ(o.code, 0) << o.err;
  const int updates = static_cast<int>(number_after(o.out, "updates: "));
  ASSERT_GT(updates, 0);
  int count = 0;
  for (const auto& entry : fs::directory_iterator(frames)) {
    EXPECT_TRUE(std::regex_match(entry.path().filename().string(), std::regex("frame_[0-9]{5}\\.png")));
    ++count;
  }
  EXPECT_EQ(count, updates);
  EXPECT_NE(o.out.find("frames: " + std::to_string(updates) + " written"), std::string::npos) << o.out;
  const cv::Mat first = topocut::testing::read_test_image((frames / "frame_00001.png").string(), topocut::testing::Pixels::kColour);
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(first.cols % 240, 0);  // an integer scale of the map
  EXPECT_EQ(first.rows * 240, first.cols * 140);

  // Every third update, and always the last one.
  const fs::path sparse = dir_ / "sparse";
  const CliResult s = run(map.string() + " --frames " + sparse.string() + " --frame-every 3");
  ASSERT_EQ(s.code, 0) << s.err;
  int sparse_count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(sparse)) ++sparse_count;
  EXPECT_EQ(sparse_count, (updates - 1) / 3 + 1 + ((updates - 1) % 3 != 0 ? 1 : 0));
  char last[32];
  std::snprintf(last, sizeof last, "frame_%05d.png", updates);
  EXPECT_TRUE(fs::exists(sparse / last));

  // The frames folder must be creatable: a file in the way is an error before any work.
  std::ofstream(dir_ / "blocked") << "x";
  const CliResult blocked = run(map.string() + " --frames " + (dir_ / "blocked").string());
  EXPECT_NE(blocked.code, 0);
  EXPECT_NE(blocked.err.find("frames"), std::string::npos) << blocked.err;
}

TEST_F(ExploreCli, SameSeedSameRunGrowingMapWorks) {
  const fs::path map = write_map("lab", true);
  const CliResult a = run(map.string() + " --seed 3");
  const CliResult b = run(map.string() + " --seed 3");
  ASSERT_EQ(a.code, 0) << a.err;
  // Identical apart from the times.
  auto strip_times = [](const std::string& text) {
    return std::regex_replace(text, std::regex("[0-9.]+ ms|[0-9.]+x|[0-9.]+ MB"), "T");
  };
  EXPECT_EQ(strip_times(a.out), strip_times(b.out));
  const CliResult grow = run(map.string() + " --grow");
  ASSERT_EQ(grow.code, 0) << grow.err;
  EXPECT_GT(number_after(grow.out, "incremental: recall "), 80.0) << grow.out;
}

// `topocut evaluate --mode incremental` on a two-map dataset folder in the Bormann layout.
TEST_F(ExploreCli, EvaluateIncrementalModeReportsUpdatesAndCsv) {
  for (const std::string name : {"alpha", "beta"}) {
    const fs::path map = write_map(name, true);
    fs::copy_file(map, dir_ / (name + "_furnitures.png"));
  }
  const fs::path csv = dir_ / "out.csv";
  const CliResult o = run("--dataset " + dir_.string() + " --mode incremental --compare-batch --csv " + csv.string(), "evaluate");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("incremental"), std::string::npos);
  EXPECT_NE(o.out.find("batch segment() on the same final maps"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("inc median ms"), std::string::npos) << o.out;
  EXPECT_NE(o.err.find("[4/4]"), std::string::npos) << o.err;  // progress on stderr
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header,
            "map,variant,rooms,gt_rooms,recall,precision,time_ms,matches,free_segments,free_rooms,f1,pq,"
            "segments_per_room,precision_inside,far_share,status,updates,update_median_ms,update_p95_ms,"
            "update_max_ms,batch_update_median_ms");
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 20) << line;
    EXPECT_NE(line.back(), ',') << "batch median missing: " << line;
  }
  EXPECT_EQ(rows, 4);

  const CliResult bad = run("--dataset " + dir_.string() + " --mode sideways", "evaluate");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--mode"), std::string::npos) << bad.err;
}

}  // namespace
