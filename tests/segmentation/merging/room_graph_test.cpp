#include "segmentation/merging/room_graph.h"

#include <algorithm>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "topocut/core/occupancy_grid.h"
#include "topocut/map/free_space_polygons.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;

// A corridor of n square pieces of 20 x 20 cells (1 m) side by side, each cut from the next, and a
// tooth beside each piece but the last (pieces n, n + 1, ...), cut from it: cuts in two directions.
PieceSet comb(int n) {
  PieceSet set;
  for (int i = 0; i < n; ++i) {
    const double x0 = 20.0 * i, x1 = x0 + 20.0;
    set.pieces.push_back({{{x0, 0}, {x1, 0}, {x1, 20}, {x0, 20}}, {}});
  }
  for (int i = 0; i + 1 < n; ++i) {
    const double x0 = 20.0 * i, x1 = x0 + 20.0;
    set.pieces.push_back({{{x0, 20}, {x1, 20}, {x1, 40}, {x0, 40}}, {}});
  }
  for (int i = 0; i + 1 < n; ++i) set.add_cut({{20.0 * (i + 1), 0}, {20.0 * (i + 1), 20}}, CutRule::kDecomposition);
  for (int i = 0; i + 1 < n; ++i) set.add_cut({{20.0 * i, 20}, {20.0 * (i + 1), 20}}, CutRule::kDecomposition);
  return set;
}

// What room_sides() stands for: every cut with a piece of room r on a side, in cut order.
std::vector<std::size_t> sides_by_definition(RoomGraph& g, int r) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < g.sides().size(); ++k) {
    const RoomGraph::Side& s = g.sides()[k];
    if (s.left >= 0 && (g.root(s.left) == r || g.root(s.right) == r)) out.push_back(k);
  }
  return out;
}

double shared_by_definition(RoomGraph& g, int r, int s) {
  double length = 0.0;
  for (const RoomGraph::Side& side : g.sides()) {
    if (side.left < 0) continue;
    const int a = g.root(side.left), b = g.root(side.right);
    if (a != b && ((a == r && (s < 0 || b == s)) || (b == r && (s < 0 || a == s)))) length += side.length;
  }
  return length;
}

TEST(RoomGraph, ARoomsCutsAndMeasuresAreThoseOfEveryCutBesideIt) {
  const PieceSet set = comb(8);
  RoomGraph g(PolygonWithHoles{}, set, cv::Mat(), kRes, 0.0);
  ASSERT_EQ(g.sides().size(), 14u);
  // Rooms of several pieces, as merging makes them (not all of them touching: the measures must not care).
  g.unite(0, 1);
  g.unite(1, 8);
  g.unite(2, 9);
  g.unite(5, 12);
  g.unite(6, 5);
  for (std::size_t p = 0; p < g.piece_count(); ++p) {
    const int r = g.root(static_cast<int>(p));
    if (r != static_cast<int>(p)) continue;
    EXPECT_EQ(g.room_sides(r), sides_by_definition(g, r)) << "room " << r;
    EXPECT_EQ(g.shared_cut_length(r, -1), shared_by_definition(g, r, -1)) << "room " << r;
    for (std::size_t q = 0; q < g.piece_count(); ++q)
      EXPECT_EQ(g.shared_cut_length(r, static_cast<int>(q)), shared_by_definition(g, r, static_cast<int>(q)));
  }
  // Pieces 0, 1, 8 (three squares of 1 m) and the two cuts inside: 12 m - 2 x 2 m.
  EXPECT_NEAR(g.room_perimeter(g.root(0)), 8.0, 1e-12);
  // Between that room and the room of pieces 2 and 9: the cut from 1 to 2 and the one from 1 to 9.
  EXPECT_NEAR(g.shared_cut_length(g.root(0), g.root(2)), 2.0, 1e-12);
}

// A room of 5 m x 1 m in the upper half of a 120 x 60 grid of walls (columns 10..109, rows 5..24),
// never-seen cells beyond its right end (columns 110..119 of the upper half), and a never-seen band
// where the room's mirror image would be (rows 35..54): the outline must be read where the room is.
// Its outline as the segmenter traces it, cut by hand 3 m from the left end into A and B.
TEST(RoomGraph, OutlinesAreMeasuredAgainstTheCellsBesideThemInTheTracedFrame) {
  cv::Mat cells(60, 120, CV_8UC1, cv::Scalar(kOccupied));
  cells(cv::Rect(10, 5, 100, 20)).setTo(kFree);
  cells(cv::Rect(110, 0, 10, 30)).setTo(kUnknown);
  cells(cv::Rect(0, 35, 120, 20)).setTo(kUnknown);
  const FreeSpacePolygons traced = free_space_polygons(cells == kFree, kRes);
  ASSERT_EQ(traced.components.size(), 1u);
  const Box box = bounding_box(traced.components[0].polygon.outer);
  // Grid coordinates: x = column, y = rows-1-row at the cells' centres; the outline on the cells' edges.
  ASSERT_EQ(box.x0, 9.5);
  ASSERT_EQ(box.x1, 109.5);
  ASSERT_EQ(box.y0, 34.5);
  ASSERT_EQ(box.y1, 54.5);
  const double cut = 69.5;  // between columns 69 and 70
  PieceSet set;
  set.pieces = {{{{box.x0, box.y0}, {cut, box.y0}, {cut, box.y1}, {box.x0, box.y1}}, {}},
                {{{cut, box.y0}, {box.x1, box.y0}, {box.x1, box.y1}, {cut, box.y1}}, {}}};
  set.add_cut({{cut, box.y0}, {cut, box.y1}}, CutRule::kDecomposition);
  RoomGraph g(traced.components[0].polygon, set, cells, kRes, 2.5);
  // A: 3 m + 3 m + 1 m of wall: all of its 8 m of outline but the 1 m cut.
  EXPECT_NEAR(g.own_outline(g.root(0)), 7.0, 1e-9);
  EXPECT_NEAR(g.wall_share(g.root(0)), 1.0, 1e-9);
  EXPECT_NEAR(g.unknown_share(g.root(0)), 0.0, 1e-9);
  // B: 2 m + 2 m of wall and its 1 m end against never-seen cells, in the 5 m that are no cut.
  EXPECT_NEAR(g.wall_share(g.root(1)), 4.0 / 5.0, 1e-9);
  EXPECT_NEAR(g.unknown_share(g.root(1)), 1.0 / 5.0, 1e-9);
}

// Every measure a room keeps (its cuts, perimeter, cuts to other rooms, hull area, the width and depth
// beside each cut) as a graph measured after every merge has it is what a graph merged the same way
// and measured only at the end finds, to the bit: nothing kept outlives the room it was measured in.
TEST(RoomGraph, MeasuresKeptAsRoomsGrowAreThoseMeasuredAfresh) {
  const PieceSet set = comb(8);
  const std::vector<std::pair<int, int>> merges{{0, 1}, {8, 1}, {2, 9}, {3, 2}, {12, 5}, {6, 12}, {4, 0}, {13, 7}, {3, 6}};
  RoomGraph watched(PolygonWithHoles{}, set, cv::Mat(), kRes, 0.0);
  auto measures = [](RoomGraph& g) {
    std::vector<double> out;
    for (std::size_t p = 0; p < g.piece_count(); ++p) {
      const int r = g.root(static_cast<int>(p));
      if (r != static_cast<int>(p)) continue;
      const std::vector<std::size_t>& sides = g.room_sides(r);
      out.insert(out.end(), sides.begin(), sides.end());
      out.push_back(g.room_perimeter(r));
      out.push_back(g.shared_cut_length(r, -1));
      out.push_back(g.convex_hull_area({r}));
      for (const std::size_t k : sides) {
        const RoomGraph::Side& s = g.sides()[k];
        const bool left = g.root(s.left) == r;
        out.push_back(g.side_width(k, r, left, 1.0));
        out.push_back(g.side_depth(k, r, left));
      }
    }
    return out;
  };
  for (std::size_t m = 0; m < merges.size(); ++m) {
    measures(watched);
    watched.unite(merges[m].first, merges[m].second);
    RoomGraph fresh(PolygonWithHoles{}, set, cv::Mat(), kRes, 0.0);
    for (std::size_t i = 0; i <= m; ++i) fresh.unite(merges[i].first, merges[i].second);
    EXPECT_EQ(measures(watched), measures(fresh)) << "after merge " << m;
  }
}

}  // namespace
}  // namespace topocut
