#include "topocut/segmentation/merge_features.h"

#include <cmath>

#include <gtest/gtest.h>

#include "segmentation/merging/room_graph.h"
#include "topocut/core/occupancy_grid.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;

double feature(const std::vector<double>& f, const std::string& name) {
  return f[static_cast<std::size_t>(merge_feature_index(name))];
}

// A 5 m x 2 m corridor cut across 3 m from its left end: A = [0, 60] x [0, 40] left of the cut
// (60, 0) -> (60, 40), B = [60, 100] x [0, 40] right of it.
PieceSet corridor_cut_across(CutRule rule) {
  PieceSet set;
  set.pieces = {{{{0, 0}, {60, 0}, {60, 40}, {0, 40}}, {}}, {{{60, 0}, {100, 0}, {100, 40}, {60, 40}}, {}}};
  set.add_cut({{60, 0}, {60, 40}}, rule);
  return set;
}

TEST(MergeFeatures, ACorridorCutAcrossMeasuresAsWorkedOutByHand) {
  const PieceSet set = corridor_cut_across(CutRule::kDecomposition);
  RoomGraph graph(PolygonWithHoles{}, set, cv::Mat(), kRes, 2.5);
  const std::vector<double> f = merge_features(graph, 0, RoomMergeOptions{});
  ASSERT_EQ(f.size(), merge_feature_names().size());
  EXPECT_NEAR(feature(f, "cut_over_narrow_width"), 1.0, 1e-9);  // the cut spans the corridor
  EXPECT_NEAR(feature(f, "narrow_over_wide_width"), 1.0, 1e-9);
  EXPECT_NEAR(feature(f, "log_narrow_width_over_cut_scale"), 0.0, 1e-9);  // 2 m wide, its one cut 2 m
  // Equal widths: the left side (A, 3 m deep) counts as narrow, B (2 m deep) as wide.
  EXPECT_NEAR(feature(f, "narrow_depth_over_width"), 1.5, 1e-9);
  EXPECT_NEAR(feature(f, "wide_depth_over_narrow_width"), 1.0, 1e-9);
  EXPECT_NEAR(feature(f, "log_narrow_area"), std::log(6.0), 1e-9);
  EXPECT_NEAR(feature(f, "log_wide_area"), std::log(4.0), 1e-9);
  EXPECT_NEAR(feature(f, "narrow_thickness"), 1.2, 1e-9);  // 2 x 6 m² / 10 m
  EXPECT_NEAR(feature(f, "wide_thickness"), 1.0, 1e-9);    // 2 x 4 m² / 8 m
  EXPECT_NEAR(feature(f, "union_solidity"), 1.0, 1e-6);
  EXPECT_NEAR(feature(f, "solidity_loss"), 0.0, 1e-6);
  EXPECT_NEAR(feature(f, "shared_over_perimeter"), 0.25, 1e-9);  // 2 m of B's 8 m
  EXPECT_NEAR(feature(f, "min_end_angle"), 1.0, 1e-9);  // both ends in a straight wall: pi
  EXPECT_NEAR(feature(f, "max_end_angle"), 1.0, 1e-9);
  EXPECT_NEAR(feature(f, "log_wall_continued_over_scale"), 0.0, 1e-9);
  EXPECT_NEAR(feature(f, "narrow_open_share"), 0.2, 1e-9);
  EXPECT_NEAR(feature(f, "wide_open_share"), 0.25, 1e-9);
  EXPECT_NEAR(feature(f, "union_thickness_over_narrow"), (2.0 * 10.0 / 14.0) / 1.2, 1e-9);
  EXPECT_NEAR(feature(f, "log_narrow_elongation"), std::log(1.5), 1e-9);  // 3 m x 2 m
  EXPECT_NEAR(feature(f, "log_union_elongation"), std::log(2.5), 1e-9);   // 5 m x 2 m
  EXPECT_EQ(feature(f, "ends_on_holes"), 0.0);
  // Without the grid every outline but the cuts counts as wall: all of A's 8 m and B's 6 m.
  EXPECT_NEAR(feature(f, "narrow_wall_share"), 1.0, 1e-9);
  EXPECT_NEAR(feature(f, "wide_wall_share"), 1.0, 1e-9);
  EXPECT_EQ(feature(f, "narrow_unknown_share"), 0.0);
  EXPECT_EQ(feature(f, "wide_unknown_share"), 0.0);
  EXPECT_NEAR(feature(f, "cut_skew"), 0.0, 1e-9);  // across the corridor, square to its walls
}

TEST(MergeFeatures, TheComponentsScalesAreItsTypicalPieceAndCut) {
  // Pieces 1.2 m and 1.0 m thick (A: 6 m², B: 4 m²): A holds more than half the area, so the
  // area-weighted median is A's thickness; the one cut is 2 m long.
  const PieceSet set = corridor_cut_across(CutRule::kDecomposition);
  RoomGraph graph(PolygonWithHoles{}, set, cv::Mat(), kRes, 2.5);
  EXPECT_NEAR(graph.piece_scale(), 1.2, 1e-9);
  EXPECT_NEAR(graph.cut_scale(), 2.0, 1e-9);
  const std::vector<double> f = merge_features(graph, 0, RoomMergeOptions{});
  EXPECT_NEAR(feature(f, "log_cut_over_scale"), std::log(2.0 / 1.2), 1e-9);
  EXPECT_NEAR(feature(f, "log_cut_over_cut_scale"), 0.0, 1e-9);
  EXPECT_NEAR(feature(f, "log_narrow_area_over_scale"), std::log(6.0 / 1.44), 1e-9);
  EXPECT_NEAR(feature(f, "narrow_thickness_over_scale"), 1.0, 1e-9);
}

TEST(MergeFeatures, ARaggedWallLeavesThePieceScaleWhereTheRoomPutsIt) {
  // The corridor with 15 notches of one cell in A's bottom wall (a robot's ragged wall): A is 2385
  // cells (5.9625 m²), its outline 1.5 m longer, its convex hull the 10 m of the straight room's. The
  // scale is 2 area / the hull's perimeter of A (still more than half the area): 1.1925 m, where
  // 2 area / the outline would give 1.037 m.
  PieceSet set = corridor_cut_across(CutRule::kDecomposition);
  Ring ragged{{0, 0}};
  for (int k = 0; k < 15; ++k) {
    const double x = 4.0 * k + 2.0;
    ragged.insert(ragged.end(), {{x, 0}, {x, 1}, {x + 1, 1}, {x + 1, 0}});
  }
  ragged.insert(ragged.end(), {{60, 0}, {60, 40}, {0, 40}});
  set.pieces[0].outer = ragged;
  RoomGraph graph(PolygonWithHoles{}, set, cv::Mat(), kRes, 2.5);
  EXPECT_NEAR(graph.room_area(0), 5.9625, 1e-9);
  EXPECT_NEAR(graph.piece_scale(), 2.0 * 5.9625 / 10.0, 1e-5);  // the hull in single precision
}

TEST(MergeFeatures, TheFeaturesInTheComponentsScaleReadTheSameAtEverySize) {
  // The same corridor at twice the cell size is twice as large: the lengths in metres move, the
  // lengths in the component's own scale do not (a sketch drawn larger, a home's rooms beside an office's).
  const PieceSet set = corridor_cut_across(CutRule::kDecomposition);
  RoomGraph small(PolygonWithHoles{}, set, cv::Mat(), kRes, 2.5), large(PolygonWithHoles{}, set, cv::Mat(), 2.0 * kRes, 5.0);
  const std::vector<double> a = merge_features(small, 0, RoomMergeOptions{}), b = merge_features(large, 0, RoomMergeOptions{});
  EXPECT_NEAR(feature(b, "log_narrow_area") - feature(a, "log_narrow_area"), std::log(4.0), 1e-9);
  for (const char* name : {"log_cut_over_scale", "log_cut_over_cut_scale", "log_narrow_width_over_scale",
                           "log_narrow_width_over_cut_scale", "log_narrow_area_over_scale", "log_wide_area_over_scale",
                           "narrow_thickness_over_scale", "wide_thickness_over_scale", "log_wall_continued_over_scale",
                           "log_hole_extent_over_scale"})
    EXPECT_NEAR(feature(a, name), feature(b, name), 1e-9) << name;
}

TEST(MergeFeatures, NoFeatureDependsOnTheRuleThatMadeTheCut) {
  const PieceSet decomposition = corridor_cut_across(CutRule::kDecomposition), door = corridor_cut_across(CutRule::kDoor);
  RoomGraph a(PolygonWithHoles{}, decomposition, cv::Mat(), kRes, 2.5), b(PolygonWithHoles{}, door, cv::Mat(), kRes, 2.5);
  EXPECT_EQ(merge_features(a, 0, RoomMergeOptions{}), merge_features(b, 0, RoomMergeOptions{}));
}

TEST(MergeFeatures, OutlinesAgainstNeverSeenCellsAreMeasuredFromTheGrid) {
  // The same corridor placed at cell (10, 10) of a 120 x 60 grid of walls, its floor free, and the
  // 10 columns beyond its right end (x = 110) never seen: B's outline is 2 m against never-seen cells
  // (its 2 m end), 4 m against walls (top and bottom), 2 m the cut; the shares are of the 6 m that
  // are no cut.
  cv::Mat cells(60, 120, CV_8UC1, cv::Scalar(kOccupied));
  cells(cv::Rect(10, 10, 100, 40)).setTo(kFree);
  cells(cv::Rect(110, 0, 10, 60)).setTo(kUnknown);
  PieceSet set;
  // In the grid coordinates the segmenter traces outlines in (x = column, y = rows-1-row at the cells'
  // centres), the free cells' outline runs half a cell outside their centres.
  set.pieces = {{{{9.5, 9.5}, {69.5, 9.5}, {69.5, 49.5}, {9.5, 49.5}}, {}},
                {{{69.5, 9.5}, {109.5, 9.5}, {109.5, 49.5}, {69.5, 49.5}}, {}}};
  set.add_cut({{69.5, 9.5}, {69.5, 49.5}}, CutRule::kDecomposition);
  RoomGraph graph(PolygonWithHoles{}, set, cells, kRes, 2.5);
  const std::vector<double> f = merge_features(graph, 0, RoomMergeOptions{});
  EXPECT_NEAR(feature(f, "wide_unknown_share"), 2.0 / 6.0, 1e-9);
  EXPECT_NEAR(feature(f, "wide_wall_share"), 4.0 / 6.0, 1e-9);
  EXPECT_NEAR(feature(f, "narrow_unknown_share"), 0.0, 1e-9);
  EXPECT_NEAR(feature(f, "narrow_wall_share"), 1.0, 1e-9);
}

TEST(MergeFeatures, ADiagonalAcrossARoomIsSkewedToItsWalls) {
  // A 2 m square cut corner to corner: at both ends the walls run at 45 degrees to the cut.
  PieceSet set;
  set.pieces = {{{{0, 0}, {40, 0}, {40, 40}}, {}}, {{{0, 0}, {40, 40}, {0, 40}}, {}}};
  set.add_cut({{0, 0}, {40, 40}}, CutRule::kDecomposition);
  RoomGraph graph(PolygonWithHoles{}, set, cv::Mat(), kRes, 2.5);
  EXPECT_NEAR(feature(merge_features(graph, 0, RoomMergeOptions{}), "cut_skew"), 1.0, 1e-9);
}

}  // namespace
}  // namespace topocut
