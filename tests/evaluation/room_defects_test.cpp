// Defects of segmentations without ground truth, on hand-made label images with hand-computed counts.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/evaluation/room_defects.h"
#include "io/test_images.h"

namespace topocut {
namespace {

// Room 1: 40 x 40 cells; room 2: a 4 x 100 strip; room 3: 10 x 10; room 4: 3 x 3.
cv::Mat hand_made_labels() {
  cv::Mat labels = cv::Mat::zeros(120, 200, CV_32SC1);
  labels(cv::Rect(10, 10, 40, 40)).setTo(1);
  labels(cv::Rect(60, 10, 4, 100)).setTo(2);
  labels(cv::Rect(80, 10, 10, 10)).setTo(3);
  labels(cv::Rect(100, 10, 3, 3)).setTo(4);
  return labels;
}

TEST(RoomDefects, HandMadeLabelsAtTwoResolutions) {
  // 0.05 m: 4 m² square; 0.2 m x 5 m = 1 m² strip (a 13-cell disc fits nowhere: thin); 0.25 m²
  // (a speck); 0.0225 m² (neither).
  RoomDefects d = count_room_defects(hand_made_labels(), 0.05);
  EXPECT_EQ(d.rooms, 4);
  EXPECT_EQ(d.thin, 1);
  EXPECT_EQ(d.specks, 1);
  // 0.1 m: the square 16 m², the strip 0.4 m x 10 m (a 7-cell disc fits nowhere: thin), room 3
  // 1 m² (no speck; a 7-cell disc opens most of its 10 x 10 cells), room 4 0.09 m² (neither).
  d = count_room_defects(hand_made_labels(), 0.1);
  EXPECT_EQ(d.rooms, 4);
  EXPECT_EQ(d.thin, 1);
  EXPECT_EQ(d.specks, 0);
  // 16-bit labels read the same.
  cv::Mat narrow;
  hand_made_labels().convertTo(narrow, CV_16U);
  EXPECT_EQ(count_room_defects(narrow, 0.05).thin, 1);
}

TEST(RoomDefects, BadInputIsAnError) {
  EXPECT_THROW(count_room_defects(cv::Mat(), 0.05), Error);
  EXPECT_THROW(count_room_defects(hand_made_labels(), 0.0), Error);
  EXPECT_THROW(count_room_defects(cv::Mat(3, 3, CV_8UC3), 0.05), Error);
}

TEST(RoomDefects, MapFolderListsYamlsAndUnnamedImages) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("topocut_defects_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  cv::Mat map(60, 80, CV_8UC1, cv::Scalar(0));
  map(cv::Rect(5, 5, 70, 50)).setTo(255);
  ASSERT_TRUE(topocut::testing::write_test_image((dir / "a.pgm").string(), map));
  ASSERT_TRUE(topocut::testing::write_test_image((dir / "b.png").string(), map));
  ASSERT_TRUE(topocut::testing::write_test_image((dir / "b_gt_segmentation.png").string(), map));
  std::ofstream(dir / "a.yaml") << "image: a.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n";
  std::ofstream(dir / "notes.txt") << "not a map\n";
  const std::vector<MapFile> maps = discover_map_files(dir.string());
  ASSERT_EQ(maps.size(), 2u);  // a.yaml (its a.pgm is not listed again) and b.png
  EXPECT_EQ(maps[0].name, "a.yaml");
  EXPECT_EQ(maps[1].name, "b.png");
  MapFolderOptions options;
  options.floor_repetitions = 1;
  const std::vector<MapDefectResult> results = run_map_files(maps, options);
  ASSERT_EQ(results.size(), 2u);
  for (const MapDefectResult& r : results) {
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.defects.rooms, 1);  // one 3.5 m x 2.5 m room
    EXPECT_EQ(r.width, 80);
    EXPECT_GT(r.floor_ms, 0.0);
  }
  const std::string csv = defects_csv(results);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "map,width,height,rooms,thin,specks,time_ms,floor_ms");
  EXPECT_NE(format_defects_table(results).find("2 maps, 2 rooms: 0 thin, 0 specks"), std::string::npos);
  fs::remove_all(dir);
  EXPECT_THROW(discover_map_files(dir.string()), Error);
}

}  // namespace
}  // namespace topocut
