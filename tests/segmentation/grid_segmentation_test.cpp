#include "topocut/segmentation/grid_segmentation.h"

#include <cmath>
#include <filesystem>
#include <string>
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "segmentation/growing_map.h"

namespace topocut {
namespace {

// A corridor along the bottom and three rooms above it, each opening into it through a 0.9 m door
// in a 0.2 m wall; origin away from zero so that frame mistakes show.
OccupancyGrid three_rooms() {
  OccupancyGrid grid;
  grid.cells = cv::Mat(120, 200, CV_8UC1, cv::Scalar(kOccupied));
  grid.resolution = 0.05;
  grid.origin = {-3.0, 4.0};
  grid.cells(cv::Rect(4, 84, 192, 32)).setTo(kFree);
  for (int i = 0; i < 3; ++i) {
    grid.cells(cv::Rect(4 + 64 * i, 4, 60, 76)).setTo(kFree);
    grid.cells(cv::Rect(4 + 64 * i + 21, 80, 18, 4)).setTo(kFree);
  }
  return grid;
}

TEST(GridSegmentation, TopDownKeepsTheSegmentationAndPlacesEveryRoom) {
  const OccupancyGrid grid = three_rooms();
  const Segmentation plain = segment(grid);
  const GridSegmentation s = segment_grid(grid, GridFrame{});
  ASSERT_EQ(s.segmentation.rooms.size(), 4u);
  EXPECT_EQ(cv::countNonZero(s.segmentation.labels != plain.labels), 0);
  ASSERT_EQ(s.placements.size(), s.segmentation.rooms.size());
  for (std::size_t k = 0; k < s.placements.size(); ++k) {
    const Room& room = s.segmentation.rooms[k];
    const RoomPlacement& p = s.placements[k];
    const cv::Point cell = world_to_cell(grid, p.inside);
    EXPECT_EQ(s.segmentation.labels.at<int>(cell), room.id) << "room " << room.id;
    for (const Point2& v : room.polygon.outer) {
      EXPECT_GE(v.x, p.min.x);
      EXPECT_GE(v.y, p.min.y);
      EXPECT_LE(v.x, p.max.x);
      EXPECT_LE(v.y, p.max.y);
    }
    EXPECT_LT(p.min.x, p.max.x);
    EXPECT_LT(p.min.y, p.max.y);
  }
  // The three room doors are narrow gaps in a wall: doors, not wider openings.
  ASSERT_EQ(s.segmentation.passages.size(), 3u);
  for (const Passage& passage : s.segmentation.passages) {
    EXPECT_TRUE(passage.door);
    EXPECT_NEAR(passage.width, 0.9, 0.11);
  }
}

// The cell each room's placement names, found the plain way: cv::distanceTransform of the whole
// map's interior cells (all four neighbours share the label; none on the map's edge), the deepest
// labelled cell of each room, the first in raster order among equals.
std::vector<cv::Point> deepest_by_distance_transform(const cv::Mat& labels, int rooms) {
  cv::Mat interior(labels.size(), CV_8UC1, cv::Scalar(0));
  for (int r = 1; r + 1 < labels.rows; ++r)
    for (int c = 1; c + 1 < labels.cols; ++c) {
      const int id = labels.at<int>(r, c);
      interior.at<unsigned char>(r, c) = id > 0 && labels.at<int>(r - 1, c) == id && labels.at<int>(r + 1, c) == id &&
                                                 labels.at<int>(r, c - 1) == id && labels.at<int>(r, c + 1) == id
                                             ? 255 : 0;
    }
  cv::Mat depth;
  cv::distanceTransform(interior, depth, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  std::vector<cv::Point> best(static_cast<std::size_t>(rooms) + 1, cv::Point(-1, -1));
  std::vector<float> best_depth(best.size(), -1.0f);
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c) {
      const int id = labels.at<int>(r, c);
      if (id <= 0 || !(depth.at<float>(r, c) > best_depth[static_cast<std::size_t>(id)])) continue;
      best_depth[static_cast<std::size_t>(id)] = depth.at<float>(r, c);
      best[static_cast<std::size_t>(id)] = {c, r};
    }
  return best;
}

// Rooms of overlapping rectangles and discs (ids 1 to rooms), some touching the map's edge, some one
// cell thin, on an unlabelled background: rooms of every shape whose deepest cell the plain
// transform knows.
Segmentation random_rooms(std::mt19937& random, int rows, int cols, int rooms) {
  Segmentation s;
  s.labels = cv::Mat::zeros(rows, cols, CV_32SC1);
  s.resolution = 0.1;
  s.origin = {1.0, -2.0};
  for (int id = 1; id <= rooms; ++id) {
    for (int shape = 0; shape < 3; ++shape) {
      const cv::Point at(static_cast<int>(random() % cols), static_cast<int>(random() % rows));
      const int size = 1 + static_cast<int>(random() % 15);
      if (random() % 2) cv::circle(s.labels, at, size, cv::Scalar(id), cv::FILLED);
      else cv::rectangle(s.labels, cv::Rect(at, cv::Size(size, 1 + static_cast<int>(random() % 15))), cv::Scalar(id), cv::FILLED);
    }
    Room room;
    room.id = id;
    room.centroid = {-7.0, -7.0};  // where a room with no labelled cell is placed
    s.rooms.push_back(room);
  }
  return s;
}

// Every room of s is placed at the centre of its cell in expected (x < 0: none, at its centroid).
void expect_placed_at(const Segmentation& s, const std::vector<cv::Point>& expected, int trial) {
  const GridSegmentation placed = in_frame(s, GridFrame{});
  for (std::size_t k = 0; k < s.rooms.size(); ++k) {
    const int id = s.rooms[k].id;
    const cv::Point cell = expected[static_cast<std::size_t>(id)];
    const Point2 inside = placed.placements[k].inside;
    const Point2 want = cell.x < 0 ? Point2{-7.0, -7.0}
                                   : Point2{s.origin.x + (cell.x + 0.5) * s.resolution,
                                            s.origin.y + (s.labels.rows - cell.y - 0.5) * s.resolution};
    EXPECT_EQ(inside.x, want.x) << "trial " << trial << ", room " << id;
    EXPECT_EQ(inside.y, want.y) << "trial " << trial << ", room " << id;
  }
}

TEST(GridSegmentation, EachRoomIsPlacedAtItsDeepestCell) {
  std::mt19937 random(36);
  for (int trial = 0; trial < 20; ++trial) {
    const int rows = 20 + static_cast<int>(random() % 60), cols = 20 + static_cast<int>(random() % 60);
    const int rooms = 1 + static_cast<int>(random() % 8);
    const Segmentation s = random_rooms(random, rows, cols, rooms);
    expect_placed_at(s, deepest_by_distance_transform(s.labels, rooms), trial);
  }
}

TEST(GridSegmentation, RoomsOfAMapTooTallForShortDepthsArePlacedAtTheirDeepestCells) {
  // A map more than 2^15 rows tall, its depths kept in 32 bits rather than 16: room 1 a corridor
  // from top to bottom whose deepest cells are in a square at its bottom end, more than 2^15 cells
  // down its columns, and random rooms beside that square.
  std::mt19937 random(37);
  constexpr int kRows = 32840, kCols = 90, kBottom = 80;
  for (int trial = 0; trial < 3; ++trial) {
    const int rooms = 1 + static_cast<int>(random() % 6);
    Segmentation s = random_rooms(random, kRows, kCols, 0);
    s.labels(cv::Rect(2, 1, 20, kRows - 2)).setTo(cv::Scalar(1));
    s.labels(cv::Rect(2, kRows - 36, 30, 30)).setTo(cv::Scalar(1));
    const Segmentation beside = random_rooms(random, kBottom, kCols - 35, rooms);
    cv::Mat shifted = beside.labels + 1;
    shifted.copyTo(s.labels(cv::Rect(35, kRows - kBottom, kCols - 35, kBottom)), beside.labels > 0);
    for (int id = 1; id <= rooms + 1; ++id) {
      Room room;
      room.id = id;
      room.centroid = {-7.0, -7.0};
      s.rooms.push_back(room);
    }
    const std::vector<cv::Point> expected = deepest_by_distance_transform(s.labels, rooms + 1);
    ASSERT_GT(expected[1].y, 32767) << "trial " << trial;
    expect_placed_at(s, expected, trial);
  }
}

TEST(GridSegmentation, BottomUpFlipsLabelsOnly) {
  const OccupancyGrid grid = three_rooms();
  const GridSegmentation top = segment_grid(grid, GridFrame{});
  const GridSegmentation bottom = segment_grid(grid, GridFrame{RowOrder::kBottomUp, 0.0});
  cv::Mat flipped;
  cv::flip(top.segmentation.labels, flipped, 0);
  EXPECT_EQ(cv::countNonZero(bottom.segmentation.labels != flipped), 0);
  ASSERT_EQ(bottom.segmentation.rooms.size(), top.segmentation.rooms.size());
  for (std::size_t k = 0; k < top.segmentation.rooms.size(); ++k) {
    EXPECT_EQ(bottom.segmentation.rooms[k].polygon, top.segmentation.rooms[k].polygon);
    EXPECT_EQ(bottom.placements[k].inside, top.placements[k].inside);
  }
}

TEST(GridSegmentation, YawTurnsTheGeometryAboutTheOrigin) {
  const OccupancyGrid grid = three_rooms();
  const double yaw = 0.5;
  const GridSegmentation flat = segment_grid(grid, GridFrame{});
  const GridSegmentation turned = segment_grid(grid, GridFrame{RowOrder::kTopDown, yaw});
  EXPECT_EQ(cv::countNonZero(turned.segmentation.labels != flat.segmentation.labels), 0);
  const auto turn = [&](const Point2& p) {
    const double dx = p.x - grid.origin.x, dy = p.y - grid.origin.y;
    return Point2{grid.origin.x + std::cos(yaw) * dx - std::sin(yaw) * dy, grid.origin.y + std::sin(yaw) * dx + std::cos(yaw) * dy};
  };
  for (std::size_t k = 0; k < flat.segmentation.rooms.size(); ++k) {
    const Room& a = flat.segmentation.rooms[k];
    const Room& b = turned.segmentation.rooms[k];
    EXPECT_NEAR(b.centroid.x, turn(a.centroid).x, 1e-9);
    EXPECT_NEAR(b.centroid.y, turn(a.centroid).y, 1e-9);
    EXPECT_NEAR(b.area, a.area, 1e-12);
    ASSERT_EQ(b.polygon.outer.size(), a.polygon.outer.size());
    EXPECT_NEAR(b.polygon.outer[0].x, turn(a.polygon.outer[0]).x, 1e-9);
    EXPECT_NEAR(turned.placements[k].inside.y, turn(flat.placements[k].inside).y, 1e-9);
  }
  const Segment2& cut = turned.segmentation.passages[0].cut;
  EXPECT_NEAR(std::hypot(cut.b.x - cut.a.x, cut.b.y - cut.a.y), flat.segmentation.passages[0].width, 1e-9);
}

TEST(GridSegmentation, IncrementalUpdatesComeInTheSameFrame) {
  const OccupancyGrid grid = three_rooms();
  IncrementalSegmenter segmenter;
  const GridSegmentation first = update_grid(segmenter, grid, GridFrame{RowOrder::kBottomUp, 0.0});
  const GridSegmentation again = update_grid(segmenter, grid, GridFrame{RowOrder::kBottomUp, 0.0});
  cv::Mat flipped;
  cv::flip(segmenter.result().labels, flipped, 0);
  EXPECT_EQ(cv::countNonZero(again.segmentation.labels != flipped), 0);
  EXPECT_EQ(cv::countNonZero(again.segmentation.labels != first.segmentation.labels), 0);
  EXPECT_EQ(again.segmentation.rooms.size(), first.segmentation.rooms.size());
}

void expect_same_placed_rooms(const GridSegmentation& got, const GridSegmentation& want, std::size_t step) {
  EXPECT_EQ(cv::countNonZero(got.segmentation.labels != want.segmentation.labels), 0) << "step " << step;
  ASSERT_EQ(got.placements.size(), want.placements.size()) << "step " << step;
  for (std::size_t k = 0; k < want.placements.size(); ++k) {
    const int id = want.segmentation.rooms[k].id;
    EXPECT_EQ(got.segmentation.rooms[k].id, id) << "step " << step;
    EXPECT_EQ(got.segmentation.rooms[k].polygon, want.segmentation.rooms[k].polygon) << "step " << step << ", room " << id;
    // Bit for bit: the same cell, and its centre computed in the same frame.
    EXPECT_EQ(got.placements[k].inside, want.placements[k].inside) << "step " << step << ", room " << id;
    EXPECT_EQ(got.placements[k].min, want.placements[k].min) << "step " << step << ", room " << id;
    EXPECT_EQ(got.placements[k].max, want.placements[k].max) << "step " << step << ", room " << id;
  }
}

// A map growing in size and origin, then unchanged, then changed inside one room and at a door:
// every update's placements are those in_frame() measures on the whole labels, in a frame turned
// and flipped too, and some rooms keep their cell from the update before (so the test sees both).
TEST(FramedUpdates, EveryUpdateIsInFramesBitForBitWhileUnchangedRoomsKeepTheirCells) {
  const std::vector<OccupancyGrid> grids = testing::growing_map_sequence();
  for (const GridFrame& frame : {GridFrame{}, GridFrame{RowOrder::kBottomUp, 0.3}}) {
    IncrementalSegmenter segmenter;
    FramedUpdates framed;
    int reused = 0, measured = 0, moved_and_reused = 0;
    for (std::size_t step = 0; step < grids.size(); ++step) {
      segmenter.update(grids[step]);
      const GridSegmentation got = framed.place(segmenter, frame);
      const GridSegmentation want = in_frame(segmenter.result(), frame);
      expect_same_placed_rooms(got, want, step);
      reused += framed.reused_rooms();
      measured += static_cast<int>(want.segmentation.rooms.size()) - framed.reused_rooms();
      if (segmenter.last_update().shift != cv::Point()) moved_and_reused += framed.reused_rooms();
    }
    EXPECT_GT(reused, 0);
    EXPECT_GT(measured, reused / 4);  // the changed rooms were measured: not every room kept
    EXPECT_GT(moved_and_reused, 0);   // cells kept across a frame that moved
    // resegment(): the whole map again, every room measured.
    segmenter.resegment();
    const GridSegmentation settled = framed.place(segmenter, frame);
    expect_same_placed_rooms(settled, in_frame(segmenter.result(), frame), grids.size());
    EXPECT_EQ(framed.reused_rooms(), 0);
  }
}

// The node's sequence on a Bormann map (revealed around its centre in 20 growing frames): the
// report lists every room whose cells changed, and every update's placements are in_frame()'s.
TEST(FramedUpdates, ABormannMapGrowingAsTheNodeSeesIt) {
  const std::string path = TOPOCUT_SHARED_DIR "/datasets/bormann/NLB.png";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared Bormann dataset not found at " << path;
  const cv::Mat grey = cv::imread(path, cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(grey.empty());
  OccupancyGrid world{cv::Mat(grey.size(), CV_8UC1, cv::Scalar(kUnknown)), 0.05, {-12.0, 3.0}};
  world.cells.setTo(kFree, grey > 250);
  world.cells.setTo(kOccupied, grey < 50);
  const std::vector<OccupancyGrid> grids = testing::node_sequence(world, 20);
  IncrementalSegmenter segmenter;
  FramedUpdates framed;
  const GridFrame frame{RowOrder::kBottomUp, 0.0};
  cv::Mat before;
  int reused = 0;
  for (std::size_t step = 0; step < grids.size(); ++step) {
    const Segmentation& after = segmenter.update(grids[step]);
    if (!before.empty() && !segmenter.last_update().every_room_relabelled)
      testing::expect_relabelled_rooms_listed(before, after, segmenter.last_update(), step);
    before = after.labels.clone();
    expect_same_placed_rooms(framed.place(segmenter, frame), in_frame(segmenter.result(), frame), step);
    reused += framed.reused_rooms();
  }
  EXPECT_GT(reused, 0);
}

// A result not placed (an update between two calls, or another segmenter) keeps no cell: the
// report compares with the result right before only.
TEST(FramedUpdates, AResultNotPlacedMakesEveryRoomMeasuredAgain) {
  const std::vector<OccupancyGrid> grids = testing::growing_map_sequence();
  IncrementalSegmenter segmenter, other;
  FramedUpdates framed;
  const std::size_t last = grids.size() - 1;
  segmenter.update(grids[last - 3]);
  framed.place(segmenter, GridFrame{});
  segmenter.update(grids[last - 2]);
  framed.place(segmenter, GridFrame{});
  ASSERT_GT(framed.reused_rooms(), 0);  // an unchanged map: every room kept
  segmenter.update(grids[last - 1]);
  segmenter.update(grids[last]);
  const GridSegmentation got = framed.place(segmenter, GridFrame{});
  EXPECT_EQ(framed.reused_rooms(), 0);
  expect_same_placed_rooms(got, in_frame(segmenter.result(), GridFrame{}), last);
  other.update(grids[last]);
  framed.place(other, GridFrame{});
  EXPECT_EQ(framed.reused_rooms(), 0);
}

}  // namespace
}  // namespace topocut
