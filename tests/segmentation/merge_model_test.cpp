#include "topocut/segmentation/merge_model.h"

#include <cmath>

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/segmentation/merge_features.h"

namespace topocut {
namespace {

std::vector<double> features_with(const std::string& name, double value) {
  std::vector<double> f(merge_feature_names().size(), 0.0);
  f[static_cast<std::size_t>(merge_feature_index(name))] = value;
  return f;
}

TEST(MergeModel, ALinearTermAndATreeAddUpInTheLogit) {
  const MergeModel model = parse_merge_model(
      "# a comment\n"
      "topocut-merge-model 1\n"
      "threshold 0.4\n"
      "bias -1\n"
      "cut_over_narrow_width 0.5 0.25 2   # (x - 0.5) / 0.25 * 2\n"
      "tree\n"
      "split furniture_end 0.5 1 2\n"
      "leaf 0.5\n"
      "leaf -3\n"
      "end\n");
  EXPECT_DOUBLE_EQ(model.threshold, 0.4);
  // x = 1: -1 + 4 + 0.5 (no furniture: the first leaf) = 3.5.
  EXPECT_NEAR(merge_probability(model, features_with("cut_over_narrow_width", 1.0)), 1.0 / (1.0 + std::exp(-3.5)), 1e-12);
  // Furniture and x = 0.5: -1 + 0 - 3 = -4.
  std::vector<double> table = features_with("furniture_end", 1.0);
  table[static_cast<std::size_t>(merge_feature_index("cut_over_narrow_width"))] = 0.5;
  EXPECT_NEAR(merge_probability(model, table), 1.0 / (1.0 + std::exp(4.0)), 1e-12);
}

TEST(MergeModel, BadTextIsAnErrorNamingTheLine) {
  const std::string head = "topocut-merge-model 1\n";
  for (const std::string& text :
       {std::string("bias 0\n"), head + "no_such_feature 0 1 1\n", head + "log_cut_length 0 0 1\n",
        head + "log_cut_length 0 1 1\nlog_cut_length 0 1 1\n", head + "bias nan\n", head + "tree\nleaf 1\n",
        head + "tree\nsplit furniture_end 0.5 0 1\nleaf 1\nend\n", head + "tree\nsplit furniture_end 0.5 1 5\nleaf 1\nleaf 2\nend\n",
        head + "tree\nend\n", head + "bias 1 2\n"}) {
    EXPECT_THROW(parse_merge_model(text), Error) << text;
  }
  try {
    parse_merge_model(head + "threshold 0.5\nwhat 1 2 3\n");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
}

TEST(MergeModel, TheShippedModelParsesAndUsesKnownFeatures) {
  const MergeModel& model = default_merge_model();
  EXPECT_FALSE(model.trees.empty() && model.features.empty());
  for (const auto& tree : model.trees) {
    for (const MergeTreeNode& node : tree) {
      if (node.feature >= 0) {
        EXPECT_LT(static_cast<std::size_t>(node.feature), merge_feature_names().size());
      }
    }
  }
  const double p = merge_probability(model, std::vector<double>(merge_feature_names().size(), 0.0));
  EXPECT_GT(p, 0.0);
  EXPECT_LT(p, 1.0);
}

}  // namespace
}  // namespace topocut
