#include "topocut/segmentation/rooms_from_pieces.h"

#include <algorithm>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace topocut {
namespace {

// A 10 x 4 free block (cells 0..9 x 0..3, grid y = 3 - row) at 0.5 m, origin (10, 20), cut at
// grid x = 3.5 into a 4-column and a 6-column piece.
struct Split {
  OccupancyGrid grid{cv::Mat(4, 10, CV_8UC1, cv::Scalar(kFree)), 0.5, {10.0, 20.0}};
  PieceSet set;
  Split() {
    set.pieces.push_back({{{3.5, -0.5}, {9.5, -0.5}, {9.5, 3.5}, {3.5, 3.5}}, {}});  // right, listed first
    set.pieces.push_back({{{-0.5, -0.5}, {3.5, -0.5}, {3.5, 3.5}, {-0.5, 3.5}}, {}});
    set.cuts.push_back({{3.5, -0.5}, {3.5, 3.5}});
  }
};

TEST(RoomsFromPieces, RoomsFollowRasterOrderAndCutsBecomePassages) {
  const Split t;
  const Segmentation s = rooms_from_pieces(t.grid, t.set);
  ASSERT_EQ(s.rooms.size(), 2u);
  EXPECT_EQ(s.labels.at<int>(0, 0), 1);  // the left piece owns the first cell
  EXPECT_EQ(s.labels.at<int>(0, 9), 2);
  EXPECT_EQ(cv::countNonZero(s.labels == 1), 16);
  EXPECT_DOUBLE_EQ(s.rooms[0].labelled_area, 16 * 0.25);
  EXPECT_DOUBLE_EQ(s.rooms[1].labelled_area, 24 * 0.25);
  EXPECT_DOUBLE_EQ(s.rooms[0].area, 16 * 0.25);  // the pieces cover exactly their cells here
  EXPECT_DOUBLE_EQ(s.rooms[1].area, 24 * 0.25);
  // Room 1 covers columns 0..3: centroid x = 10 + 2 * 0.5, y = 20 + 2 * 0.5.
  EXPECT_DOUBLE_EQ(s.rooms[0].centroid.x, 11.0);
  EXPECT_DOUBLE_EQ(s.rooms[0].centroid.y, 21.0);
  // Its polygon in metres: grid (-0.5, -0.5) is the world corner (10, 20).
  EXPECT_DOUBLE_EQ(area(s.rooms[0].polygon), 4.0);
  EXPECT_EQ(s.rooms[0].polygon.outer[0], (Point2{10.0, 20.0}));
  ASSERT_EQ(s.passages.size(), 1u);
  EXPECT_EQ(s.passages[0].room_a, 1);
  EXPECT_EQ(s.passages[0].room_b, 2);
  EXPECT_DOUBLE_EQ(s.passages[0].width, 2.0);
  EXPECT_EQ(s.passages[0].cut.a, (Point2{12.0, 20.0}));
  EXPECT_EQ(s.passages[0].cut.b, (Point2{12.0, 22.0}));
}

TEST(RoomsFromPieces, UncoveredFreeCellsJoinTheNearestPieceAndObstaclesStayZero) {
  Split t;
  t.grid.cells.at<unsigned char>(1, 1) = kOccupied;
  t.set.pieces[1] = {{{-0.5, -0.5}, {2.5, -0.5}, {2.5, 3.5}, {-0.5, 3.5}}, {}};  // leaves column 3 uncovered
  const Segmentation s = rooms_from_pieces(t.grid, t.set);
  EXPECT_EQ(s.labels.at<int>(1, 1), 0);
  EXPECT_EQ(cv::countNonZero(s.labels == 0), 1);
  // Column 3 is next to both pieces; breadth-first search from raster-ordered sources gives it
  // to the piece whose cell comes first in each row: the left one (column 2 precedes column 4).
  EXPECT_EQ(s.labels.at<int>(0, 3), 1);
  // The cut no longer has the left piece on its left side: no passage.
  EXPECT_TRUE(s.passages.empty());
}

// Given the pieces' spans (the open rooms' stage rasterized them already), the same segmentation.
TEST(RoomsFromPieces, ThePiecesSpansGivenGiveTheSameRooms) {
  Split t;
  t.grid.cells.at<unsigned char>(1, 1) = kOccupied;
  t.set.pieces[1] = {{{-0.5, -0.5}, {2.5, -0.5}, {2.5, 3.5}, {-0.5, 3.5}}, {}};  // column 3 left to the completion
  for (const bool cover : {false, true}) {
    RoomLabelOptions options;
    options.cover_absorbed_obstacles = cover;
    const Segmentation own = rooms_from_pieces(t.grid, t.set, options);
    const Segmentation given = rooms_from_pieces(t.grid, t.set, polygon_spans(t.set.pieces, t.grid.cells.size()), options);
    EXPECT_EQ(cv::countNonZero(own.labels != given.labels), 0);
    ASSERT_EQ(own.rooms.size(), given.rooms.size());
    for (std::size_t k = 0; k < own.rooms.size(); ++k) {
      EXPECT_EQ(own.rooms[k].polygon, given.rooms[k].polygon);
      EXPECT_DOUBLE_EQ(own.rooms[k].labelled_area, given.rooms[k].labelled_area);
    }
    EXPECT_EQ(own.passages.size(), given.passages.size());
  }
}

TEST(RoomsFromPieces, KeyholeCutsAndEmptyPiecesAreNotPassages) {
  Split t;
  t.set.cuts.push_back({{0.0, 0.0}, {1.0, 1.0}});                           // inside one piece
  t.set.pieces.push_back({{{20, 20}, {21, 20}, {21, 21}}, {}});             // labels no cell
  const Segmentation s = rooms_from_pieces(t.grid, t.set);
  EXPECT_EQ(s.rooms.size(), 2u);
  EXPECT_EQ(s.passages.size(), 1u);
}

TEST(RoomsFromPieces, PieceContaining) {
  const Split t;
  EXPECT_EQ(piece_containing(t.set.pieces, {1.0, 1.0}), 1);
  EXPECT_EQ(piece_containing(t.set.pieces, {5.0, 1.0}), 0);
  EXPECT_EQ(piece_containing(t.set.pieces, {50.0, 1.0}), -1);
}

TEST(RoomsFromPieces, PassagesOfManyPiecesAreThoseOfTheLinearSearch) {
  // A lattice of 4 x 4-cell pieces, a few overlapping pieces and degenerate ones among them, and
  // cuts along shared edges, inside pieces and outside all of them: the passages are those that
  // piece_containing() gives, piece by piece.
  constexpr int kColumns = 23, kRows = 17, kSide = 4;
  OccupancyGrid grid{cv::Mat(kRows * kSide, kColumns * kSide, CV_8UC1, cv::Scalar(kFree)), 0.05, {0.0, 0.0}};
  PieceSet set;
  auto square = [](double x0, double y0, double x1, double y1) { return PolygonWithHoles{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}}; };
  cv::RNG rng(9);
  for (int j = 0; j < kRows; ++j) {
    for (int i = 0; i < kColumns; ++i) {
      const double x0 = i * kSide - 0.5, y0 = j * kSide - 0.5;
      set.pieces.push_back(square(x0, y0, x0 + kSide, y0 + kSide));
      if (rng.uniform(0, 9) == 0) set.pieces.push_back(square(x0 + 1, y0 + 1, x0 + 3, y0 + 3));  // inside the one before
      if (rng.uniform(0, 15) == 0) set.pieces.push_back({{{x0, y0}, {x0 + 1, y0}}, {}});        // no area
      if (i > 0) set.cuts.push_back({{x0, y0}, {x0, y0 + kSide}});
      if (j > 0) set.cuts.push_back({{x0, y0}, {x0 + kSide, y0}});
      if (rng.uniform(0, 5) == 0) set.cuts.push_back({{x0 + 0.5, y0 + 0.5}, {x0 + 1.5, y0 + 2.5}});
    }
  }
  set.cuts.push_back({{-10.0, -10.0}, {-10.0, -5.0}});
  const Segmentation s = rooms_from_pieces(grid, set);
  // A piece's room: the label of a cell centre it contains (1.5 cells into its box), if no piece
  // before it contains that centre.
  auto room_of = [&](int piece) {
    const Box box = bounding_box(set.pieces[static_cast<std::size_t>(piece)].outer);
    const Point2 centre{box.x0 + 1.5, box.y0 + 1.5};
    if (piece_containing(set.pieces, centre) != piece) return 0;
    return s.labels.at<int>(grid.height() - 1 - static_cast<int>(centre.y), static_cast<int>(centre.x));
  };
  std::vector<std::pair<int, int>> expected;
  for (const Segment2& cut : set.cuts) {
    Point2 left, right;
    if (!cut_sides(cut.a, cut.b, left, right)) continue;
    const int a = piece_containing(set.pieces, left), b = piece_containing(set.pieces, right);
    if (a < 0 || b < 0) continue;
    const int ra = room_of(a), rb = room_of(b);
    if (ra != 0 && rb != 0 && ra != rb) expected.emplace_back(std::min(ra, rb), std::max(ra, rb));
  }
  std::sort(expected.begin(), expected.end());
  std::vector<std::pair<int, int>> found;
  for (const Passage& p : s.passages) found.emplace_back(p.room_a, p.room_b);
  EXPECT_GT(expected.size(), 600u);
  EXPECT_EQ(found, expected);
}

}  // namespace
}  // namespace topocut
