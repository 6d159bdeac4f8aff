#pragma once
// A learned merging criterion: the probability that two adjacent rooms in the making are one room of
// people's, as a logistic regression over the named features of merge_features.h. The shipped model
// (src/segmentation/merging/merge_model.txt, built into the library) is fitted by
// scripts/train_merge_model.py on people's rooms; another can be loaded from its text.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace topocut {

// The size of a model any front end accepts (a file, Python's text, a MergeModel built in code):
// weighing one candidate visits at most one path per tree, so these bound merging's cost per
// candidate at kMaxMergeTrees x (kMaxMergeTreeDepth + 1) nodes (the shipped model, far smaller, says
// its size in its header), and the nodes bound its memory.
inline constexpr std::size_t kMaxMergeTrees = 1000;
inline constexpr int kMaxMergeTreeDepth = 12;               // splits on a tree's longest path
inline constexpr std::size_t kMaxMergeModelNodes = 100000;  // of all trees together

// A node of a regression tree: a split (feature >= 0: go to yes when the feature is at most threshold,
// else to no) or a leaf (feature < 0: value).
struct MergeTreeNode {
  int feature = -1;
  double threshold = 0.0;
  int yes = 0, no = 0;
  double value = 0.0;
};

struct MergeModel {
  // p(one room) = 1 / (1 + exp(-z)), z = bias + sum_i weight_i * (feature_i - mean_i) / scale_i +
  // the sum of the trees' leaves, over the features named in features (indices into
  // merge_feature_names()); merged while p > threshold.
  std::vector<int> features;
  std::vector<double> mean, scale, weight;
  std::vector<std::vector<MergeTreeNode>> trees;  // each rooted at its node 0
  double bias = 0.0;
  double threshold = 0.5;
  std::string text;  // the model's text as parsed (for reports and equality)
};

// Parses a model's text: '#' comments, then "topocut-merge-model 1", "threshold T", "bias B", one line
// "NAME MEAN SCALE WEIGHT" per linear feature (NAME one of merge_feature_names()), and trees: "tree",
// its nodes in order ("split NAME THRESHOLD YES NO", YES and NO node numbers later in the tree, or
// "leaf VALUE"), "end". Throws Error naming the line on anything else (unknown or repeated feature,
// scale <= 0, a value that is not finite, a node pointing backwards or outside its tree), and on a
// model beyond the limits above or a text longer than kMaxMergeModelBytes (core/input_file.h).
MergeModel parse_merge_model(const std::string& text);

// Throws Error unless model is one parse_merge_model() could give: features named once, positive
// scales, finite numbers, trees whose splits point forwards inside them, within the limits above.
void validate(const MergeModel& model);

// The model shipped with the library.
const MergeModel& default_merge_model();

// A model as the options hold it: shared by every copy of them and checked once, when made (the
// shipped model's 16,840 nodes were copied with each copy of the options and walked again by
// every merging). Converts from a MergeModel, which it validates (throws Error); made empty, it
// holds the shipped model.
class SharedMergeModel {
 public:
  SharedMergeModel();
  SharedMergeModel(MergeModel model);  // NOLINT(google-explicit-constructor): options.model = parse_merge_model(text)
  const MergeModel& operator*() const { return *model_; }
  const MergeModel* operator->() const { return model_.get(); }

 private:
  std::shared_ptr<const MergeModel> model_;
};

// p(one room) for a full feature vector (merge_feature_names() order).
double merge_probability(const MergeModel& model, const std::vector<double>& features);

}  // namespace topocut
