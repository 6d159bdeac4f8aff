#include "topocut/segmentation/merge_model.h"

#include <cmath>
#include <cstring>
#include <sstream>

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"
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

// The parser converts plain decimals itself (std::from_chars) and leaves the rest to the stream: a
// bias must read as the stream reads it, to the bit, or be refused as the stream refuses it.
TEST(MergeModel, NumbersReadAsTheStreamReadsThem) {
  for (const std::string number :
       {"0", "-0", "1", "-2.5", "0.1", "3.14159265358979323846264338327950288", "1e-310", "1e-400", "-4.9406564584124654e-324",
        "1.7976931348623157e308", "2E5", "6.02e+23", "+7", "8.", ".5", "00012.50", "123456789012345678901234567890"}) {
    std::istringstream stream(number);
    double expected = 0.0;
    const bool read = static_cast<bool>(stream >> expected) && std::isfinite(expected);
    const std::string text = "topocut-merge-model 1\nbias " + number + "\n";
    if (!read) {
      EXPECT_THROW(parse_merge_model(text), Error) << number;
      continue;
    }
    const double bias = parse_merge_model(text).bias;
    EXPECT_EQ(std::memcmp(&bias, &expected, sizeof bias), 0) << number << ": " << bias << " against " << expected;
  }
  for (const std::string refused : {"1e400", "-1e999", "inf", "nan", "1e", "-", "1.5x", "0x10"})
    EXPECT_THROW(parse_merge_model("topocut-merge-model 1\nbias " + refused + "\n"), Error) << refused;
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


// A model text of `trees` trees, each a chain of `depth` splits ending in leaves.
std::string chain_model(std::size_t trees, int depth) {
  std::string text = "topocut-merge-model 1\n";
  for (std::size_t t = 0; t < trees; ++t) {
    text += "tree\n";
    for (int d = 0; d < depth; ++d)  // node 2d splits to leaf 2d+1 or on to node 2d+2
      text += "split furniture_end 0.5 " + std::to_string(2 * d + 1) + " " + std::to_string(2 * d + 2) + "\nleaf 0\n";
    text += "leaf 0.1\nend\n";
  }
  return text;
}

std::string error_of(const std::string& text) {
  try {
    parse_merge_model(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(MergeModel, AModelAtTheLimitsParsesAndOneBeyondAnyIsRefused) {
  // Each limit bounds what one candidate costs: trees x (depth + 1) nodes visited.
  const MergeModel at = parse_merge_model(chain_model(kMaxMergeTrees, 0));
  EXPECT_EQ(at.trees.size(), kMaxMergeTrees);
  EXPECT_NO_THROW(parse_merge_model(chain_model(1, kMaxMergeTreeDepth)));
  EXPECT_NE(error_of(chain_model(kMaxMergeTrees + 1, 0)).find("more than 1000 trees"), std::string::npos);
  EXPECT_NE(error_of(chain_model(1, kMaxMergeTreeDepth + 1)).find("deeper than 12 splits"), std::string::npos);
  // A chain deeper than the limit hidden in one tree of many still fails, naming its line.
  EXPECT_NE(error_of(chain_model(3, 2) + chain_model(1, 40).substr(22)).find("line "), std::string::npos);
  // Nodes: 5000 trees' worth would pass trees x depth in count, not in nodes.
  std::string wide = "topocut-merge-model 1\ntree\n";
  for (std::size_t i = 0; i <= kMaxMergeModelNodes; ++i) wide += "leaf 0\n";
  EXPECT_NE(error_of(wide + "end\n").find("tree nodes"), std::string::npos);
  // The text itself: more than the file limit of every front end.
  EXPECT_NE(error_of(std::string(kMaxMergeModelBytes + 1, '#')).find("bytes, more than the limit of 4 MiB"), std::string::npos);
}

TEST(MergeModel, ValidateRefusesWhatTheParserWouldRefuse) {
  EXPECT_NO_THROW(validate(default_merge_model()));
  MergeModel model = parse_merge_model(chain_model(2, 3));
  EXPECT_NO_THROW(validate(model));
  MergeModel backwards = model;
  backwards.trees[1][2].yes = 0;
  EXPECT_THROW(validate(backwards), Error);
  MergeModel unknown = model;
  unknown.trees[0][0].feature = 100000;
  EXPECT_THROW(validate(unknown), Error);
  MergeModel too_many = model;
  too_many.trees.assign(kMaxMergeTrees + 1, model.trees[0]);
  EXPECT_THROW(validate(too_many), Error);
  MergeModel lopsided = model;
  lopsided.scale.push_back(1.0);
  EXPECT_THROW(validate(lopsided), Error);
}

}  // namespace
}  // namespace topocut
