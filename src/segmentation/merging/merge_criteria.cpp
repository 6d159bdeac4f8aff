#include "topocut/segmentation/merge_criteria.h"

#include "segmentation/merging/room_graph.h"
#include "topocut/core/infinity.h"
#include "topocut/segmentation/merge_model.h"
#include "topocut/segmentation/room_merging.h"

namespace topocut {

MergeCandidate::MergeCandidate(RoomGraph& graph, std::size_t cut, const RoomMergeOptions& options)
    : graph_(graph), cut_(cut), options_(options) {}

CutRule MergeCandidate::rule() const { return graph_.sides()[cut_].rule; }

double MergeCandidate::cut_length() const { return graph_.sides()[cut_].length; }

bool MergeCandidate::ends_on_furniture() const { return graph_.sides()[cut_].furniture; }

double MergeCandidate::width(bool left) {
  std::optional<double>& w = width_[left ? 1 : 0];
  if (!w) {
    const RoomGraph::Side& s = graph_.sides()[cut_];
    w = graph_.side_width(cut_, graph_.root(left ? s.left : s.right), left, options_.door_like.width_depth);
  }
  return *w;
}

const std::vector<double>& MergeCandidate::features() {
  if (!features_) features_ = merge_features(graph_, cut_, options_);
  return *features_;
}

namespace {

// The learned criteria's answer: merge above the model's threshold.
MergeVerdict by_probability(double probability, const RoomMergeOptions& options) {
  return probability > options.model->threshold ? MergeVerdict::merge(probability) : MergeVerdict::keep(probability);
}

}  // namespace

// Both sides strips of about the same thickness (at most 2.5 m), the cut across the narrower one, the
// union no thicker, and each side at least 3 times as long as it is thick; doors and wall openings are
// left to the model. Measured neutral on every set (the model merges nearly all of them itself); it
// keeps the bends of long corridors.
MergeVerdict corridor_continues(MergeCandidate& c) {
  static const int cut = merge_feature_index("cut_over_narrow_width"), narrow = merge_feature_index("narrow_thickness"),
                   wide = merge_feature_index("wide_thickness"), grown = merge_feature_index("union_thickness_over_narrow");
  if (!c.options().learned || is_door_rule(c.rule())) return MergeVerdict::abstain();
  const std::vector<double>& f = c.features();
  const auto at = [&f](int i) { return f[static_cast<std::size_t>(i)]; };
  if (at(cut) < 0.9 || at(grown) > 1.25) return MergeVerdict::abstain();
  if (std::max(at(narrow), at(wide)) > 2.5 || std::max(at(narrow), at(wide)) > 1.25 * std::min(at(narrow), at(wide)))
    return MergeVerdict::abstain();
  RoomGraph& g = c.graph();
  const RoomGraph::Side& s = g.sides()[c.cut()];
  if (std::min(g.elongation({g.root(s.left)}), g.elongation({g.root(s.right)})) < 3.0) return MergeVerdict::abstain();
  return by_probability(1.0, c.options());
}

MergeVerdict learned_merge(MergeCandidate& c) { return by_probability(merge_probability(*c.options().model, c.features()), c.options()); }

MergeVerdict door_cuts_stay(MergeCandidate& c) { return is_door_rule(c.rule()) ? MergeVerdict::keep() : MergeVerdict::abstain(); }

// A room does not end at a table: the most clearly non-door-like cut of all.
MergeVerdict furniture_rule(MergeCandidate& c) {
  return c.ends_on_furniture() ? MergeVerdict::merge(kInfinity) : MergeVerdict::abstain();
}

// A room that opens onto a much wider, deep space (step_ratio) stays a room of its own. Across a wall
// line (the narrow room's wall drawn on) the wider side need only reach deeper than the narrow room is
// wide (step_wall_line_depth times): an L-shaped corridor's corner is as deep as the corridor is wide,
// so it still merges.
MergeVerdict width_step(MergeCandidate& c) {
  const RoomMergeOptions& o = c.options();
  const double narrow = c.narrow_width();
  if (narrow <= 0.0 || narrow >= o.step_ratio * c.wide_width()) return MergeVerdict::abstain();
  RoomGraph& g = c.graph();
  const RoomGraph::Side& s = g.sides()[c.cut()];
  const int left = g.root(s.left), right = g.root(s.right);
  if (std::min(g.room_area(left), g.room_area(right)) < o.step_min_area) return MergeVerdict::abstain();
  const bool left_narrow = c.width(true) <= c.width(false);
  const double depth = g.side_depth(c.cut(), left_narrow ? right : left, !left_narrow);
  const double enough = c.rule() == CutRule::kWallLine ? o.step_wall_line_depth * narrow : o.step_min_wide_depth;
  return depth >= enough ? MergeVerdict::keep() : MergeVerdict::abstain();
}

// A cut narrower than door_like.ratio times the narrower room is door-like (door_like_cut.h) and
// stays; a cut closer to the narrower room's width (a corridor cut across) merges, the clearest first.
MergeVerdict door_ratio_rule(MergeCandidate& c) {
  const double narrow = c.narrow_width();
  if (narrow <= 0.0) return MergeVerdict::merge(kInfinity);
  const double score = c.cut_length() / narrow;
  return score >= c.options().door_like.ratio ? MergeVerdict::merge(score) : MergeVerdict::keep(score);
}

}  // namespace topocut
