// The shipped merge model and the options' shared model (merge_model.h), built from the arrays the
// build compiled from the model's text (shipped_merge_model.h).
#include <memory>
#include <utility>
#include <vector>

#include "segmentation/merging/shipped_merge_model.h"
#include "topocut/segmentation/merge_model.h"

namespace topocut {

namespace {

MergeModel from_arrays(const shipped::MergeModelArrays& a) {
  MergeModel model;
  model.features.assign(a.features, a.features + a.linear_terms);
  model.mean.assign(a.mean, a.mean + a.linear_terms);
  model.scale.assign(a.scale, a.scale + a.linear_terms);
  model.weight.assign(a.weight, a.weight + a.linear_terms);
  model.trees.reserve(a.trees);
  const MergeTreeNode* node = a.nodes;
  for (std::size_t t = 0; t < a.trees; ++t) {
    model.trees.emplace_back(node, node + a.tree_sizes[t]);
    node += a.tree_sizes[t];
  }
  model.bias = a.bias;
  model.threshold = a.threshold;
  model.text = shipped::kMergeModelText;
  return model;
}

// The shipped model, made on first use and shared by every SharedMergeModel made empty. The
// compiler checked it as parse_merge_model() checks a text; a test checks the two agree.
const std::shared_ptr<const MergeModel>& shipped_model() {
  static const std::shared_ptr<const MergeModel> model = std::make_shared<const MergeModel>(from_arrays(shipped::kMergeModel));
  return model;
}

}  // namespace

const MergeModel& default_merge_model() { return *shipped_model(); }

SharedMergeModel::SharedMergeModel() : model_(shipped_model()) {}

SharedMergeModel::SharedMergeModel(MergeModel model) {
  validate(model);
  model_ = std::make_shared<const MergeModel>(std::move(model));
}

}  // namespace topocut
