// The runner on the real Bormann maps (read from TOPOCUT_SHARED_DIR, never copied into the project).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "topocut/evaluation/dataset.h"

namespace topocut {
namespace {

namespace fs = std::filesystem;

std::string bormann_folder() { return std::string(TOPOCUT_SHARED_DIR "/datasets/bormann"); }

TEST(BormannDataset, DiscoversTheTwentyMaps) {
  if (!fs::is_directory(bormann_folder())) GTEST_SKIP() << "Bormann dataset not found at " << bormann_folder();
  const std::vector<DatasetMap> maps = discover_dataset(bormann_folder());
  EXPECT_EQ(maps.size(), 20u);
  for (const DatasetMap& map : maps) {
    EXPECT_TRUE(fs::is_regular_file(map.plain)) << map.plain;
    EXPECT_TRUE(fs::is_regular_file(map.furnished)) << map.furnished;
  }
}

TEST(BormannDataset, TrivialBaselineOnThreeMapsIsSane) {
  if (!fs::is_directory(bormann_folder())) GTEST_SKIP() << "Bormann dataset not found at " << bormann_folder();
  DatasetRunOptions options;
  options.segment.decompose = false;
  options.maps = {"Freiburg52_scan", "lab_b_scan", "lab_ipa"};
  const std::vector<ImageResult> results = run_dataset(bormann_folder(), options);
  ASSERT_EQ(results.size(), 6u);
  for (const ImageResult& r : results) {
    SCOPED_TRACE(r.map + " " + to_string(r.variant));
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_GT(r.rooms, 0);
    // These buildings have many rooms; the ground truth must split into more than one.
    EXPECT_GT(r.gt_rooms, 5);
    EXPECT_GE(r.recall, 0.0);
    EXPECT_LE(r.recall, 1.0);
    EXPECT_GE(r.precision, 0.0);
    EXPECT_LE(r.precision, 1.0);
    EXPECT_GT(r.time_ms, 0.0);
    // A building is one or a few free-space components, so the baseline finds fewer rooms than
    // the ground truth and its segments span several rooms: precision below recall.
    EXPECT_LT(r.rooms, r.gt_rooms);
    EXPECT_LT(r.precision, r.recall);
    if (r.variant == Variant::kPlain) {
      // A plain map's free space is the ground truth's rooms plus the drawn separators, so every
      // room lies almost entirely in one component.
      EXPECT_GT(r.recall, 0.9);
    }
  }
}

TEST(BormannDataset, SegmenterOptionsFlowThroughTheRunner) {
  if (!fs::is_directory(bormann_folder())) GTEST_SKIP() << "Bormann dataset not found at " << bormann_folder();
  DatasetRunOptions options;
  options.maps = {"Freiburg52_scan"};
  options.variants = {Variant::kPlain};
  const std::vector<ImageResult> decomposed = run_dataset(bormann_folder(), options);
  options.segment.decompose = false;
  const std::vector<ImageResult> trivial = run_dataset(bormann_folder(), options);
  ASSERT_EQ(decomposed.size(), 1u);
  ASSERT_EQ(trivial.size(), 1u);
  ASSERT_TRUE(decomposed[0].ok) << decomposed[0].error;
  ASSERT_TRUE(trivial[0].ok) << trivial[0].error;
  // The map is one free-space component holding ten ground-truth rooms: the baseline keeps it
  // whole, a decomposition must split it and gain precision.
  EXPECT_EQ(trivial[0].rooms, 1);
  EXPECT_GT(decomposed[0].rooms, 1);
  EXPECT_GT(decomposed[0].precision, trivial[0].precision);
}

}  // namespace
}  // namespace topocut
