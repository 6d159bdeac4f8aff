// Room outlines on label runs: the wall cells, extents and outlines give, room by room, what their
// definitions on the whole image give (the exact distance transform thresholded; every cell visited;
// a flood fill of the room's window from its frame), on random label maps with holes, rooms inside
// rooms, rooms in several parts, rooms touching the map's edge and SLAM-like unknown rims.
#include <map>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/map/label_runs.h"
#include "topocut/map/room_outline.h"

namespace topocut {
namespace {

// The definitions, written with OpenCV's whole-image operations.
cv::Mat reference_walls(const cv::Mat& cells, double reach) {
  cv::Mat distance;
  cv::distanceTransform(cells != kOccupied, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance <= reach;
}

std::map<int, RoomExtent> reference_extents(const cv::Mat& labels) {
  std::map<int, RoomExtent> rooms;
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c) {
      const int id = labels.at<int>(r, c);
      if (id <= 0) continue;
      RoomExtent& room = rooms[id];
      room.box = room.cells == 0 ? cv::Rect(c, r, 1, 1) : (room.box | cv::Rect(c, r, 1, 1));
      ++room.cells;
    }
  return rooms;
}

RoomOutline reference_outline(const cv::Mat& labels, int id, const cv::Rect& box, const cv::Mat& cells, const cv::Mat& walls,
                              int band, const cv::Mat& floor) {
  const cv::Rect window(box.x - 1, box.y - 1, box.width + 2, box.height + 2);
  cv::Mat outside(window.size(), CV_8UC1, cv::Scalar(255));
  const cv::Rect inner = window & cv::Rect(0, 0, labels.cols, labels.rows);
  outside(inner - window.tl()).setTo(0, labels(inner) == id);
  cv::floodFill(outside, cv::Point(0, 0), cv::Scalar(128), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
  RoomOutline outline;
  const auto inside_grid = [&](int r, int c) { return r >= 0 && c >= 0 && r < labels.rows && c < labels.cols; };
  const auto drawn_wall = [&](int r, int c, int dr, int dc) {
    for (int k = 1; k <= band && inside_grid(r + k * dr, c + k * dc); ++k) {
      const int rr = r + k * dr, cc = c + k * dc;
      if (walls.at<unsigned char>(rr, cc)) return true;
      if (cells.at<unsigned char>(rr, cc) == kUnknown) continue;
      const int owner = labels.at<int>(rr, cc);
      return owner > 0 && owner != id && (floor.empty() || floor.at<unsigned char>(rr, cc) != 0);
    }
    return false;
  };
  const auto ragged = [&](int wr, int wc, int dr, int dc) {
    for (const int side : {-1, 1}) {
      const int sr = wr + side * dc, sc = wc + side * dr;
      if (outside.at<unsigned char>(sr, sc) == 128 || outside.at<unsigned char>(sr + dr, sc + dc) != 128) return true;
    }
    return false;
  };
  const auto edge = [&](int wr, int wc, int dr, int dc) {
    if (outside.at<unsigned char>(wr, wc) != 128) return;
    const int r = window.y + wr, c = window.x + wc;
    if (!inside_grid(r, c)) {
      ++outline.unknown;
      return;
    }
    const int other = labels.at<int>(r, c);
    if (other > 0) {
      ++outline.neighbours[other];
    } else if (cells.at<unsigned char>(r, c) != kFree) {
      const bool wall = walls.at<unsigned char>(r, c) || (cells.at<unsigned char>(r, c) == kUnknown && drawn_wall(r, c, dr, dc));
      ++(wall ? outline.wall : outline.unknown);
      if (!wall && ragged(wr - dr, wc - dc, dr, dc)) ++outline.ragged;
    }
  };
  for (int wr = 1; wr + 1 < window.height; ++wr)
    for (int wc = 1; wc + 1 < window.width; ++wc) {
      if (outside.at<unsigned char>(wr, wc) == 128) continue;
      edge(wr - 1, wc, -1, 0);
      edge(wr + 1, wc, 1, 0);
      edge(wr, wc - 1, 0, -1);
      edge(wr, wc + 1, 0, 1);
    }
  return outline;
}

// A grid of free, occupied and unknown cells with rooms drawn over it: rectangles and discs, rooms
// inside rooms, a room in two parts, walls and unknown rims and bands, rooms at the map's edge.
struct RandomMap {
  cv::Mat cells, labels, floor;
};

RandomMap random_map(cv::RNG& rng, int rows, int cols) {
  RandomMap m;
  m.cells = cv::Mat(rows, cols, CV_8UC1, cv::Scalar(kFree));
  for (int k = 0; k < rows * cols / 300 + 2; ++k) {
    const cv::Point p(rng.uniform(0, cols), rng.uniform(0, rows));
    const unsigned char value = rng.uniform(0, 3) == 0 ? kUnknown : kOccupied;
    if (rng.uniform(0, 2) == 0)
      cv::line(m.cells, p, p + cv::Point(rng.uniform(-30, 31), rng.uniform(-30, 31)), cv::Scalar(value), rng.uniform(1, 3));
    else
      cv::rectangle(m.cells, cv::Rect(p, cv::Size(rng.uniform(1, 12), rng.uniform(1, 12))), cv::Scalar(value), cv::FILLED);
  }
  m.labels = cv::Mat::zeros(rows, cols, CV_32SC1);
  const int rooms = rng.uniform(1, 12);
  for (int id = 1; id <= rooms; ++id) {
    const cv::Point p(rng.uniform(-5, cols), rng.uniform(-5, rows));
    if (rng.uniform(0, 3) == 0)
      cv::circle(m.labels, p, rng.uniform(1, 20), cv::Scalar(id), cv::FILLED);
    else
      cv::rectangle(m.labels, cv::Rect(p, cv::Size(rng.uniform(1, 40), rng.uniform(1, 40))), cv::Scalar(id), cv::FILLED);
    if (rng.uniform(0, 4) == 0)  // a second part, or a hole punched through another room
      cv::rectangle(m.labels, cv::Rect(cv::Point(rng.uniform(0, cols), rng.uniform(0, rows)), cv::Size(rng.uniform(1, 8), rng.uniform(1, 8))),
                    cv::Scalar(rng.uniform(0, 2) == 0 ? id : 0), cv::FILLED);
  }
  m.floor = cv::Mat(rows, cols, CV_8UC1);
  rng.fill(m.floor, cv::RNG::UNIFORM, 0, 8);
  m.floor = m.floor != 0;
  return m;
}

TEST(RoomOutline, WallCellsAreTheDistanceTransformThresholded) {
  cv::RNG rng(3);
  for (int round = 0; round < 12; ++round) {
    const RandomMap m = random_map(rng, rng.uniform(1, 90), rng.uniform(1, 120));
    for (const double reach : {0.0, 0.5, 1.0, 1.5, 2.0 + 1e-9, 0.15 / 0.05 + 1e-9, 4.4, 7.0, 12.5}) {
      const cv::Mat mine = wall_cells(m.cells, reach), reference = reference_walls(m.cells, reach);
      EXPECT_EQ(cv::countNonZero(mine != reference), 0) << "round " << round << ", reach " << reach;
    }
  }
  EXPECT_EQ(cv::countNonZero(wall_cells(cv::Mat(20, 30, CV_8UC1, cv::Scalar(kFree)), 3.0)), 0);
}

TEST(RoomOutline, ExtentsAndOutlinesAreTheFloodFilledWindows) {
  cv::RNG rng(4);
  int open = 0, compared = 0;
  for (int round = 0; round < 60; ++round) {
    const RandomMap m = random_map(rng, rng.uniform(1, 80), rng.uniform(1, 110));
    const cv::Mat walls = wall_cells(m.cells, 1.5);
    const LabelRuns runs = label_runs(m.labels);
    const std::map<int, RoomExtent> extents = room_extents(runs), expected = reference_extents(m.labels);
    ASSERT_EQ(extents.size(), expected.size());
    for (const auto& [id, extent] : expected) {
      ASSERT_EQ(extents.at(id).box, extent.box);
      ASSERT_EQ(extents.at(id).cells, extent.cells);
      for (const cv::Mat& floor : {cv::Mat(), m.floor}) {
        const RoomOutline a = room_outline(runs, id, extent.box, m.cells, walls, 3, floor);
        const RoomOutline b = reference_outline(m.labels, id, extent.box, m.cells, walls, 3, floor);
        EXPECT_EQ(a.unknown, b.unknown) << "round " << round << ", room " << id;
        EXPECT_EQ(a.ragged, b.ragged) << "round " << round << ", room " << id;
        EXPECT_EQ(a.wall, b.wall) << "round " << round << ", room " << id;
        EXPECT_EQ(a.neighbours, b.neighbours) << "round " << round << ", room " << id;
        open += b.open(0.5, 0.3);
        ++compared;
      }
    }
  }
  // The maps hold open rooms and walled ones both.
  EXPECT_GT(open, 0);
  EXPECT_LT(open, compared);
}

}  // namespace
}  // namespace topocut
