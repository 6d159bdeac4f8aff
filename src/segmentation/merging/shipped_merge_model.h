#pragma once
// The shipped merge model as the build compiles it (tools/compile_merge_model.cpp writes
// generated/shipped_merge_model.cpp from src/segmentation/merging/merge_model.txt): arrays the
// loader copies, so that no program parses the model's 16,840 nodes from text on every start.
#include <cstddef>

#include "topocut/segmentation/merge_model.h"

namespace topocut::shipped {

// The model's parts; its trees' nodes one after another, tree_sizes[t] nodes for tree t.
struct MergeModelArrays {
  const int* features;
  const double* mean;
  const double* scale;
  const double* weight;
  std::size_t linear_terms;
  const MergeTreeNode* nodes;
  const int* tree_sizes;
  std::size_t trees;
  double bias;
  double threshold;
};

extern const MergeModelArrays kMergeModel;  // generated/shipped_merge_model.cpp
extern const char* const kMergeModelText;   // generated/merge_model_text.cpp: the text it was compiled from

}  // namespace topocut::shipped
