#pragma once
// Merge criteria: the rows of the rule list (segmentation_rules.h) that decide whether two rooms
// beside a cut are one room. A criterion reads a candidate merge's measurements and answers merge
// (with a priority: the highest is taken first), keep apart, or abstain; the merging asks the criteria
// that are on in list order and the first answer that is no abstention decides (all abstain: apart).
// The learned model answers every candidate, so the hand rules listed after it decide only with
// --no-learned-merge.
#include <algorithm>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "topocut/core/cut_rule.h"

namespace topocut {

class RoomGraph;  // one component's pieces as they merge (internal: src/segmentation/room_graph.h)
struct RoomMergeOptions;

struct MergeVerdict {
  enum Kind { kAbstain, kKeep, kMerge };
  Kind kind = kAbstain;
  // kMerge: the priority (the highest first); kKeep: what the criterion measured (the learned model's
  // probability, recorded in merge traces).
  double score = 0.0;

  static MergeVerdict abstain() { return {}; }
  static MergeVerdict keep(double score = 0.0) { return {kKeep, score}; }
  static MergeVerdict merge(double priority) { return {kMerge, priority}; }
};

// The two rooms beside one cut as a criterion sees them; each measure is taken when first asked
// (metres).
class MergeCandidate {
 public:
  MergeCandidate(RoomGraph& graph, std::size_t cut, const RoomMergeOptions& options);

  const RoomMergeOptions& options() const { return options_; }
  CutRule rule() const;              // the rule that made the cut
  double cut_length() const;         // m
  bool ends_on_furniture() const;    // an end lies on a furniture-sized obstacle
  double width(bool left);           // the room's width beside the cut (RoomMergeOptions::door_like)
  double narrow_width() { return std::min(width(true), width(false)); }
  double wide_width() { return std::max(width(true), width(false)); }
  const std::vector<double>& features();  // merge_features.h

  // For the library's own criteria, which read more of the rooms.
  RoomGraph& graph() { return graph_; }
  std::size_t cut() const { return cut_; }

 private:
  RoomGraph& graph_;
  std::size_t cut_;
  const RoomMergeOptions& options_;
  std::optional<double> width_[2];  // right, left
  std::optional<std::vector<double>> features_;
};

using MergeCriterion = std::function<MergeVerdict(MergeCandidate&)>;

// The library's criteria, each a row of segmentation_rules() (its name in brackets).
MergeVerdict corridor_continues(MergeCandidate& c);  // (corridor-rule) learned merging: a corridor goes on
MergeVerdict learned_merge(MergeCandidate& c);       // (learned-merge) the model's probability
MergeVerdict door_cuts_stay(MergeCandidate& c);      // (door-cuts) hand rules: a door rule's cut stays
MergeVerdict furniture_rule(MergeCandidate& c);      // (furniture-rule) hand rules: a cut ending on furniture
MergeVerdict width_step(MergeCandidate& c);          // (width-steps) hand rules: a room opening onto a wider one
MergeVerdict door_ratio_rule(MergeCandidate& c);     // (door-ratio) hand rules: a cut spanning the narrower room

}  // namespace topocut
