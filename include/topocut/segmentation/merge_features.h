#pragma once
// What merging knows of a candidate merge: two adjacent rooms in the making and one cut between them,
// described by measurements and ratios (cut length, widths and depths of both sides, areas,
// thickness, convexity of the union, what the rooms' outlines run along, the cut's angles to the
// walls), the same on every kind of map: lengths in the component's own scale (its typical piece and
// cut), areas and thicknesses in metres and in that scale. No feature is a rule's decision, so rules and the model can
// change apart.
#include <string>
#include <string_view>
#include <vector>

namespace topocut {

// The feature names, in the order of every feature vector. "narrow" is the side whose width beside
// the cut is smaller, "wide" the other.
const std::vector<std::string>& merge_feature_names();

// Index of a feature name, or -1.
int merge_feature_index(std::string_view name);

// One candidate merge as merging saw it, for training and inspection: its features, the pieces of its
// two rooms (indices into the component's pieces), the model's probability and whether it merged.
struct MergeStep {
  std::vector<double> features;
  std::vector<int> side_a, side_b;
  double probability = 0.0;
};

}  // namespace topocut
