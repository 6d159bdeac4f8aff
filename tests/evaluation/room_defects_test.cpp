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

// A grid of labels' size, every cell in state (free unless told), at resolution.
OccupancyGrid grid_like(const cv::Mat& labels, double resolution, unsigned char state = kFree) {
  OccupancyGrid grid;
  grid.cells = cv::Mat(labels.size(), CV_8UC1, cv::Scalar(state));
  grid.resolution = resolution;
  return grid;
}

RoomDefects count_room_defects(const cv::Mat& labels, double resolution) {
  return topocut::count_room_defects(labels, grid_like(labels, resolution));
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
  EXPECT_THROW(topocut::count_room_defects(hand_made_labels(), grid_like(cv::Mat(3, 3, CV_8UC1), 0.05)), Error);
}

// A 40 x 40 room (4 m² at 0.05 m) in the middle of a 60 x 60 grid of unknown cells, with walls drawn
// one cell thick on the sides named.
struct OpenRoomCase {
  cv::Mat labels = cv::Mat::zeros(60, 60, CV_32SC1);
  OccupancyGrid grid = grid_like(labels, 0.05, kUnknown);
  const cv::Rect room{10, 10, 40, 40};
  OpenRoomCase() {
    labels(room).setTo(1);
    grid.cells(room).setTo(kFree);
  }
  void wall(const cv::Rect& cells) { grid.cells(cells).setTo(kOccupied); }
  void wall_top() { wall({10, 9, 40, 1}); }
  void wall_bottom() { wall({10, 50, 40, 1}); }
  void wall_left() { wall({9, 10, 1, 40}); }
  void wall_right() { wall({50, 10, 1, 40}); }
  // Laser rays ending at different lengths: every other cell of the side named sticks out one cell.
  void ragged(bool top, bool bottom, bool right) {
    for (int k = 0; k < 40; k += 2) {
      if (top) free_room_cell(10 + k, 9);
      if (bottom) free_room_cell(10 + k, 50);
      if (right) free_room_cell(50, 10 + k);
    }
  }
  void free_room_cell(int c, int r) {
    labels.at<int>(r, c) = 1;
    grid.cells.at<unsigned char>(r, c) = kFree;
  }
  RoomDefects count() const { return topocut::count_room_defects(labels, grid); }
  // The share rule alone: straight never-seen sides count too.
  RoomDefects count_any_outline() const {
    DefectOptions options;
    options.open.ragged_share = 0.0;
    return topocut::count_room_defects(labels, grid, options);
  }
};

TEST(RoomDefects, ARoomBoundedByRaggedUnknownOnThreeSidesIsOpen) {
  OpenRoomCase c;
  c.wall_left();  // 40 wall edges, 120 straight unknown ones: a wall drawn in the unknown grey
  EXPECT_EQ(c.count().open, 0);
  EXPECT_EQ(c.count().unseen, 1);  // not a defect (straight), but bounded mostly by never-seen cells
  EXPECT_EQ(c.count_any_outline().open, 1);
  c.ragged(true, true, true);  // 160 unknown edges, of which all but the straight ones turn
  const RoomDefects d = c.count();
  EXPECT_EQ(d.rooms, 1);
  EXPECT_EQ(d.open, 1);
  EXPECT_EQ(d.unseen, 1);
  EXPECT_EQ(d.thin, 0);
  EXPECT_EQ(d.flagged, 1);
}

TEST(RoomDefects, ABandOfUnknownBetweenTwoRoomsIsAWall) {
  // Two rooms side by side, 4 never-seen cells (0.2 m) apart, walled elsewhere: the band is a wall
  // drawn in grey; 12 cells (0.6 m, more than the 0.5 m band) apart it is never-seen space.
  for (const int gap : {4, 12}) {
    cv::Mat labels = cv::Mat::zeros(60, 100, CV_32SC1);
    OccupancyGrid grid = grid_like(labels, 0.05, kOccupied);
    const cv::Rect left(5, 5, 40, 50), right(45 + gap, 5, 40, 50);
    labels(left).setTo(1);
    labels(right).setTo(2);
    grid.cells(left).setTo(kFree);
    grid.cells(right).setTo(kFree);
    grid.cells(cv::Rect(45, 5, gap, 50)).setTo(kUnknown);
    DefectOptions straight;
    straight.open.ragged_share = 0.0;
    straight.open.share = 0.2;  // one side of four against never-seen space is open here
    EXPECT_EQ(topocut::count_room_defects(labels, grid, straight).open, gap == 4 ? 0 : 2) << gap;
  }
}

// A 2 m x 2 m walled room (floor) and, off its open right side, rays one every other row (free cells
// the cleaning removed, labelled with the room): with the floor given, a room that is mostly rays and
// touches no other room's floor is open, as the open-rooms rule leaves it out; as floor alone it is
// walled on three sides and not open.
TEST(RoomDefects, AnIslandOfFloorThatIsMostlyRaysIsOpen) {
  cv::Mat labels = cv::Mat::zeros(60, 200, CV_32SC1);
  OccupancyGrid grid = grid_like(labels, 0.05, kUnknown);
  const cv::Rect room(10, 10, 40, 40);
  grid.cells(cv::Rect(9, 9, 42, 42)).setTo(kOccupied);
  grid.cells(room).setTo(kFree);
  grid.cells(cv::Rect(50, 10, 1, 40)).setTo(kUnknown);  // the right side is never-seen
  cv::Mat floor = cv::Mat::zeros(labels.size(), CV_8UC1);
  floor(room).setTo(255);
  labels(room).setTo(1);
  for (int row = 10; row < 50; row += 2) {
    grid.cells(cv::Rect(50, row, 150, 1)).setTo(kFree);
    labels(cv::Rect(50, row, 150, 1)).setTo(1);
  }
  DefectOptions options;
  EXPECT_EQ(topocut::count_room_defects(labels, grid, options, floor).open, 1);  // 1600 floor of 4600 cells
  EXPECT_EQ(topocut::count_room_defects(labels, grid, options).open, 0);         // no floor: the outline alone
  options.open.floor_share = 0.0;                                                 // off
  EXPECT_EQ(topocut::count_room_defects(labels, grid, options, floor).open, 0);
  // With a room beside its floor it is not judged by its rays.
  options.open.floor_share = 0.5;
  grid.cells(cv::Rect(9, 50, 42, 1)).setTo(kFree);
  labels(cv::Rect(9, 50, 42, 10)).setTo(2);
  grid.cells(cv::Rect(9, 50, 42, 10)).setTo(kFree);
  floor(cv::Rect(9, 50, 42, 10)).setTo(255);
  EXPECT_EQ(topocut::count_room_defects(labels, grid, options, floor).open, 0);
}

TEST(RoomDefects, AWalledRoomWithOneDoorIsNotOpen) {
  OpenRoomCase c;
  c.wall_top();
  c.wall_bottom();
  c.wall_left();
  c.wall_right();
  c.grid.cells(cv::Rect(50, 20, 1, 6)).setTo(kFree);  // a door in the right wall ...
  c.labels(cv::Rect(50, 20, 10, 6)).setTo(2);          // ... into another room (which is open: unknown beyond)
  c.grid.cells(cv::Rect(50, 20, 10, 6)).setTo(kFree);
  c.grid.cells(cv::Rect(9, 30, 1, 4)).setTo(kFree);    // and a gap to free cells no room holds
  RoomDefects d = c.count();
  EXPECT_EQ(d.rooms, 2);
  EXPECT_EQ(d.open, 0);  // room 2 has 60 x 0.05² = 0.15 m²: a speck, too small to be called open
  EXPECT_EQ(d.unseen, 0);  // nor counted as bounded by never-seen cells; the walled room is not
  EXPECT_EQ(d.specks, 1);
  EXPECT_EQ(d.flagged, 1);
}

TEST(RoomDefects, OpenNeedsMoreThanHalfOfTheOutlineUnknown) {
  DefectOptions exact;
  exact.open.wall_reach = 0.0;  // only occupied cells are wall here
  OpenRoomCase c;
  c.wall_top();
  exact.open.ragged_share = 0.0;
  c.wall_left();  // 80 wall edges, 80 unknown: not more than half
  EXPECT_EQ(topocut::count_room_defects(c.labels, c.grid, exact).open, 0);
  c.grid.cells(cv::Rect(9, 10, 1, 1)).setTo(kUnknown);  // 79 wall edges, 81 unknown
  EXPECT_EQ(topocut::count_room_defects(c.labels, c.grid, exact).open, 1);
}

TEST(RoomDefects, NeverSeenCellsAlongAWallCountAsWall) {
  // Walls on three sides behind two never-seen cells: 3 cells (0.15 m) from the cells beside the room.
  OpenRoomCase c;
  c.wall({10, 6, 40, 1});
  c.wall({6, 10, 1, 40});
  c.wall({10, 53, 40, 1});
  EXPECT_EQ(c.count_any_outline().open, 0);
  // Behind 9 never-seen cells (0.45 m) they are beyond the rim: with walls drawn at most 0.25 m thick
  // (the look-ahead then meets the rim 0.4 m on), that is never-seen space.
  OpenRoomCase far;
  far.wall({10, 0, 40, 1});
  far.wall({0, 10, 1, 40});
  far.wall({10, 59, 40, 1});
  DefectOptions thin_walls;
  thin_walls.open.ragged_share = 0.0;
  thin_walls.open.wall_band = 0.25;
  EXPECT_EQ(topocut::count_room_defects(far.labels, far.grid, thin_walls).open, 1);
  thin_walls.open.wall_band = 0.5;  // the default: 9 cells of grey can be a drawn wall
  EXPECT_EQ(topocut::count_room_defects(far.labels, far.grid, thin_walls).open, 0);
}

TEST(RoomDefects, HolesInsideARoomAreNotItsOutline) {
  // A walled room with 100 never-seen cells inside it (a table the laser never saw over): closed.
  OpenRoomCase c;
  c.wall_top();
  c.wall_bottom();
  c.wall_left();
  c.wall_right();
  for (int k = 0; k < 25; ++k) {
    const cv::Rect hole(13 + 7 * (k % 5), 13 + 7 * (k / 5), 2, 2);  // 25 holes of 4 cells: 200 edges
    c.labels(hole).setTo(0);
    c.grid.cells(hole).setTo(kUnknown);
  }
  EXPECT_EQ(c.count().open, 0);
}

TEST(RoomDefects, TheGridEdgeIsNeverSeenSpaceAndSmallRoomsAreNotOpen) {
  cv::Mat labels = cv::Mat::zeros(60, 40, CV_32SC1);
  labels(cv::Rect(0, 0, 40, 40)).setTo(1);  // touches the grid's edge on three sides ...
  OccupancyGrid grid = grid_like(labels, 0.05);
  grid.cells(cv::Rect(0, 40, 40, 1)).setTo(kOccupied);  // ... and a wall on the fourth
  DefectOptions straight;
  straight.open.ragged_share = 0.0;
  EXPECT_EQ(topocut::count_room_defects(labels, grid, straight).open, 1);
  // Below open_min_area (19 x 19 cells = 0.9 m²) a room is not called open.
  labels.setTo(0);
  labels(cv::Rect(0, 0, 19, 19)).setTo(1);
  EXPECT_EQ(topocut::count_room_defects(labels, grid, straight).open, 0);
}

TEST(RoomDefects, WithoutAnyOccupiedCellOpenRoomsAreNotJudged) {
  OpenRoomCase c;  // unknown all around, not a single wall cell: walls drawn in the unknown grey
  const RoomDefects d = c.count();
  EXPECT_FALSE(d.open_judged);
  EXPECT_EQ(d.open, 0);
  MapDefectResult result;
  result.map = "walls.png";
  result.ok = true;
  result.defects = d;
  const std::string table = format_defects_table({result});
  EXPECT_NE(table.find("open rooms not judged on 1 map(s)"), std::string::npos) << table;
  EXPECT_NE(defects_csv({result}).find(",1,0,0,,"), std::string::npos) << defects_csv({result});
}

TEST(RoomDefects, AThinOpenRoomIsFlaggedOnce) {
  cv::Mat labels = cv::Mat::zeros(30, 120, CV_32SC1);
  labels(cv::Rect(5, 10, 100, 4)).setTo(1);  // 0.2 m x 5 m: thin
  OccupancyGrid grid = grid_like(labels, 0.05, kUnknown);
  grid.cells.at<unsigned char>(29, 119) = kOccupied;  // a wall far away: open rooms are judged
  DefectOptions straight;
  straight.open.ragged_share = 0.0;
  const RoomDefects d = topocut::count_room_defects(labels, grid, straight);
  EXPECT_EQ(d.thin, 1);
  EXPECT_EQ(d.open, 1);
  EXPECT_EQ(d.flagged, 1);
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
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "map,width,height,rooms,thin,specks,open,time_ms,floor_ms");
  // Bounded by the image's occupied frame on every side: closed.
  EXPECT_NE(format_defects_table(results).find("2 maps, 2 rooms: 0 thin, 0 specks, 0 open (0 rooms with a defect"),
            std::string::npos)
      << format_defects_table(results);
  fs::remove_all(dir);
  EXPECT_THROW(discover_map_files(dir.string()), Error);
}

}  // namespace
}  // namespace topocut
