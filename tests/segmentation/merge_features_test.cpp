#include "topocut/segmentation/merge_features.h"

#include <cmath>

#include <gtest/gtest.h>

#include "segmentation/room_graph.h"

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
  RoomGraph graph(PolygonWithHoles{}, set, kRes, 2.5);
  const std::vector<double> f = merge_features(graph, 0, RoomMergeOptions{});
  ASSERT_EQ(f.size(), merge_feature_names().size());
  EXPECT_NEAR(feature(f, "log_cut_length"), std::log(2.0), 1e-9);
  EXPECT_NEAR(feature(f, "cut_over_narrow_width"), 1.0, 1e-9);  // the cut spans the corridor
  EXPECT_NEAR(feature(f, "narrow_over_wide_width"), 1.0, 1e-9);
  EXPECT_NEAR(feature(f, "log_narrow_width"), std::log(2.0), 1e-9);
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
  EXPECT_EQ(feature(f, "rule_door") + feature(f, "rule_wall_opening") + feature(f, "rule_island_cut") +
                feature(f, "rule_wall_line"),
            0.0);
  EXPECT_NEAR(feature(f, "min_end_angle"), 1.0, 1e-9);  // both ends in a straight wall: pi
  EXPECT_NEAR(feature(f, "max_end_angle"), 1.0, 1e-9);
  EXPECT_NEAR(feature(f, "log_wall_continued"), 0.0, 1e-9);
  EXPECT_NEAR(feature(f, "narrow_open_share"), 0.2, 1e-9);
  EXPECT_NEAR(feature(f, "wide_open_share"), 0.25, 1e-9);
  EXPECT_NEAR(feature(f, "union_thickness_over_narrow"), (2.0 * 10.0 / 14.0) / 1.2, 1e-9);
  EXPECT_NEAR(feature(f, "log_narrow_elongation"), std::log(1.5), 1e-9);  // 3 m x 2 m
  EXPECT_NEAR(feature(f, "log_union_elongation"), std::log(2.5), 1e-9);   // 5 m x 2 m
  EXPECT_EQ(feature(f, "ends_on_holes"), 0.0);
  EXPECT_EQ(feature(f, "hand_rule_merge"), 1.0);  // the hand rules merge a corridor cut across
}

TEST(MergeFeatures, TheCutsRuleIsAFeatureAndADoorIsNeverAHandRuleMerge) {
  const PieceSet set = corridor_cut_across(CutRule::kDoor);
  RoomGraph graph(PolygonWithHoles{}, set, kRes, 2.5);
  const std::vector<double> f = merge_features(graph, 0, RoomMergeOptions{});
  EXPECT_EQ(feature(f, "rule_door"), 1.0);
  EXPECT_EQ(feature(f, "hand_rule_merge"), 0.0);
}

}  // namespace
}  // namespace topocut
