#include "topocut/segmentation/merge_model.h"

#include <cmath>
#include <cstring>
#include <sstream>

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"
#include "topocut/segmentation/merge_features.h"
#include "topocut/segmentation/room_merging.h"

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
       {std::string("bias 0\n"), head + "no_such_feature 0 1 1\n", head + "cut_skew 0 0 1\n",
        head + "cut_skew 0 1 1\ncut_skew 0 1 1\n", head + "bias nan\n", head + "tree\nleaf 1\n",
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

std::string error_of(const std::string& text) {
  try {
    parse_merge_model(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Whether two models' trees hold the same nodes, their numbers to the bit.
bool same_trees(const MergeModel& a, const MergeModel& b) {
  if (a.trees.size() != b.trees.size()) return false;
  for (std::size_t t = 0; t < a.trees.size(); ++t) {
    if (a.trees[t].size() != b.trees[t].size()) return false;
    for (std::size_t i = 0; i < a.trees[t].size(); ++i) {
      const MergeTreeNode& x = a.trees[t][i];
      const MergeTreeNode& y = b.trees[t][i];
      if (x.feature != y.feature || x.yes != y.yes || x.no != y.no || std::memcmp(&x.threshold, &y.threshold, sizeof(double)) != 0 ||
          std::memcmp(&x.value, &y.value, sizeof(double)) != 0)
        return false;
    }
  }
  return true;
}

// Plain tree node lines are read without the stream: the shipped model's nodes read the same when a
// comment on every line sends each through the stream instead; spellings the stream accepts read
// as it reads them, and what it refuses stays refused.
TEST(MergeModel, TreeNodesReadAsTheStreamReadsThem) {
  const MergeModel& shipped = default_merge_model();
  std::string commented;
  std::istringstream lines(shipped.text);
  for (std::string line; std::getline(lines, line);) commented += line + " # read by the stream\n";
  EXPECT_TRUE(same_trees(parse_merge_model(commented), shipped));

  const std::string head = "topocut-merge-model 1\ntree\n", tail = "\nleaf 0.5\nleaf -3\nend\n";
  const MergeModel plain = parse_merge_model(head + "split furniture_end 0.25 1 2" + tail);
  for (const std::string split : {"\tsplit  furniture_end\t0.25 1 2 ", "split furniture_end 0.25 +1 2", "split furniture_end .25 01 2",
                                  "split furniture_end 0.25 1 2\r", "split furniture_end 2.5e-1 1 2#", "split furniture_end 25.e-2 1 2",
                                  "split furniture_end 0.25E+0 1 2"})
    EXPECT_TRUE(same_trees(parse_merge_model(head + split + tail), plain)) << split;
  for (const std::string bad : {"split furniture_end 0.25 1", "split furniture_end 0.25 1 2 3", "split no_such_feature 0.25 1 2",
                                "split furniture_end 0.25 1 99999999999", "split furniture_end 0.25 -1 2", "leaf", "leaf 1 2", "split furniture_end inf 1 2",
                                "split furniture_end 0x1 1 2", "leaf nan", "leaf 1e400", "leaf 1e"})
    EXPECT_NE(error_of(head + bad + tail).find("line "), std::string::npos) << bad;
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

// The shipped model is compiled into arrays at build time (tools/compile_merge_model.cpp): they hold
// exactly what parsing its text gives, number for number, so the library answers as if it read the text.
TEST(MergeModel, TheCompiledShippedModelIsItsParsedText) {
  const MergeModel& compiled = default_merge_model();
  const MergeModel parsed = parse_merge_model(compiled.text);
  EXPECT_GT(parsed.trees.size(), 0U);
  EXPECT_TRUE(same_trees(compiled, parsed));
  EXPECT_EQ(compiled.features, parsed.features);
  const auto same_numbers = [](const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
  };
  EXPECT_TRUE(same_numbers(compiled.mean, parsed.mean));
  EXPECT_TRUE(same_numbers(compiled.scale, parsed.scale));
  EXPECT_TRUE(same_numbers(compiled.weight, parsed.weight));
  EXPECT_TRUE(same_numbers({compiled.bias, compiled.threshold}, {parsed.bias, parsed.threshold}));
  EXPECT_NO_THROW(validate(compiled));
}

// The options hold a model shared by their copies and checked when made: a model validate() refuses
// is refused there, so no merging meets it.
TEST(MergeModel, SharedModelIsCheckedOnceAndSharedByCopies) {
  const SharedMergeModel shipped;
  EXPECT_EQ(&*shipped, &default_merge_model());
  MergeModel model = parse_merge_model(chain_model(2, 3));
  const SharedMergeModel given = model;
  const SharedMergeModel copy = given;
  EXPECT_EQ(&*copy, &*given);
  EXPECT_EQ(copy->text, model.text);
  EXPECT_EQ(copy->trees.size(), 2U);
  model.trees[1][2].yes = 0;  // points backwards
  EXPECT_THROW(SharedMergeModel{model}, Error);
  RoomMergeOptions options;
  EXPECT_EQ(&*options.model, &default_merge_model());
  options.model = parse_merge_model(chain_model(1, 2));
  const RoomMergeOptions copied = options;
  EXPECT_EQ(&*copied.model, &*options.model);
  EXPECT_NE(&*copied.model, &default_merge_model());
}

}  // namespace
}  // namespace topocut
