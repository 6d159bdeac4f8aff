#include "topocut/segmentation/merge_model.h"

#include <cmath>
#include <sstream>

#include "topocut/core/error.h"
#include "topocut/segmentation/merge_features.h"

namespace topocut {

// The text of src/segmentation/merge_model.txt, built into the library (CMakeLists.txt).
extern const char* const kShippedMergeModelText;

namespace {

double finite_number(std::istringstream& in, int line, const std::string& what) {
  double value = 0.0;
  if (!(in >> value) || !std::isfinite(value))
    throw Error("merge model, line " + std::to_string(line) + ": " + what + " must be a finite number");
  return value;
}

void expect_end(std::istringstream& in, int line) {
  std::string extra;
  if (in >> extra) throw Error("merge model, line " + std::to_string(line) + ": unexpected '" + extra + "'");
}

Error line_error(int line, const std::string& what) { return Error("merge model, line " + std::to_string(line) + ": " + what); }

int feature_named(const std::string& name, int line) {
  const int index = merge_feature_index(name);
  if (index < 0) throw line_error(line, "unknown feature '" + name + "'");
  return index;
}

// One node line of a tree ("split NAME THRESHOLD YES NO" or "leaf VALUE").
MergeTreeNode tree_node(const std::string& key, std::istringstream& in, int line) {
  MergeTreeNode node;
  if (key == "leaf") {
    node.value = finite_number(in, line, "a leaf's value");
  } else if (key == "split") {
    std::string name;
    in >> name;
    node.feature = feature_named(name, line);
    node.threshold = finite_number(in, line, "a split's threshold");
    if (!(in >> node.yes >> node.no)) throw line_error(line, "a split needs its two next nodes");
  } else {
    throw line_error(line, "expected 'split', 'leaf' or 'end' in a tree, not '" + key + "'");
  }
  expect_end(in, line);
  return node;
}

// Every split points forwards to a node of its own tree, so evaluation ends at a leaf.
void check_tree(const std::vector<MergeTreeNode>& tree, int line) {
  if (tree.empty()) throw line_error(line, "a tree without nodes");
  const int size = static_cast<int>(tree.size());
  for (int i = 0; i < size; ++i) {
    const MergeTreeNode& n = tree[static_cast<std::size_t>(i)];
    if (n.feature >= 0 && (n.yes <= i || n.no <= i || n.yes >= size || n.no >= size))
      throw line_error(line, "node " + std::to_string(i) + " of the tree points outside it or backwards");
  }
}

}  // namespace

MergeModel parse_merge_model(const std::string& text) {
  MergeModel model;
  model.text = text;
  std::istringstream lines(text);
  std::string raw;
  int number = 0;
  bool header = false, in_tree = false;
  while (std::getline(lines, raw)) {
    ++number;
    std::istringstream in(raw.substr(0, raw.find('#')));
    std::string key;
    if (!(in >> key)) continue;
    if (in_tree) {
      if (key == "end") {
        expect_end(in, number);
        check_tree(model.trees.back(), number);
        in_tree = false;
      } else {
        model.trees.back().push_back(tree_node(key, in, number));
      }
    } else if (!header) {
      int version = 0;
      if (key != "topocut-merge-model" || !(in >> version) || version != 1)
        throw Error("merge model, line " + std::to_string(number) + ": expected 'topocut-merge-model 1'");
      expect_end(in, number);
      header = true;
    } else if (key == "threshold") {
      model.threshold = finite_number(in, number, "the threshold");
      expect_end(in, number);
    } else if (key == "bias") {
      model.bias = finite_number(in, number, "the bias");
      expect_end(in, number);
    } else if (key == "tree") {
      expect_end(in, number);
      model.trees.emplace_back();
      in_tree = true;
    } else {
      const int index = feature_named(key, number);
      for (const int f : model.features)
        if (f == index) throw Error("merge model, line " + std::to_string(number) + ": feature '" + key + "' given twice");
      model.features.push_back(index);
      model.mean.push_back(finite_number(in, number, "the mean"));
      const double scale = finite_number(in, number, "the scale");
      if (scale <= 0.0) throw Error("merge model, line " + std::to_string(number) + ": the scale must be positive");
      model.scale.push_back(scale);
      model.weight.push_back(finite_number(in, number, "the weight"));
      expect_end(in, number);
    }
  }
  if (!header) throw Error("merge model: no 'topocut-merge-model 1' line");
  if (in_tree) throw Error("merge model: the last tree has no 'end'");
  return model;
}

const MergeModel& default_merge_model() {
  static const MergeModel model = parse_merge_model(kShippedMergeModelText);
  return model;
}

double merge_probability(const MergeModel& model, const std::vector<double>& features) {
  double z = model.bias;
  for (std::size_t i = 0; i < model.features.size(); ++i) {
    const double x = features[static_cast<std::size_t>(model.features[i])];
    z += model.weight[i] * (x - model.mean[i]) / model.scale[i];
  }
  for (const std::vector<MergeTreeNode>& tree : model.trees) {
    std::size_t at = 0;
    while (tree[at].feature >= 0) {
      const MergeTreeNode& n = tree[at];
      at = static_cast<std::size_t>(features[static_cast<std::size_t>(n.feature)] <= n.threshold ? n.yes : n.no);
    }
    z += tree[at].value;
  }
  return 1.0 / (1.0 + std::exp(-z));
}

}  // namespace topocut
