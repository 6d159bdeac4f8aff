// The decomposition's option table (decompose.h). tau is left out (segment() sets it from the
// concavity in metres; the decompose command takes it as --tau). The reference variants are chosen
// by name: decomposition_choice_rows().
#include "topocut/core/option_choice.h"
#include "topocut/core/option_table.h"
#include "topocut/decomposition/decompose.h"

namespace topocut {

const std::vector<OptionRow<DecompositionOptions>>& decomposition_option_rows() {
  using D = DecompositionOptions;
  static const std::vector<OptionRow<D>> rows = {
      field_row("max-rounds", "N", OptionRange::kCount, &D::max_rounds, "cap on decomposition passes"),
      inverted_switch_row("keep-small-holes", &D::absorb_small_holes, "keep holes smaller than tau instead of absorbing them"),
      inverted_switch_row("keyholes", &D::restore_holes, "return pieces with keyhole rings instead of restoring their holes"),
      field_row("reference-selection-limit", "N", OptionRange::kWholeNumber, &D::reference_selection_limit,
                "with the reference cut selection, more cut sets than this use the greedy selection"),
  };
  return rows;
}

const std::vector<OptionRow<DecompositionOptions>>& decomposition_tau_rows() {
  static const std::vector<OptionRow<DecompositionOptions>> rows = {
      field_row("tau", "T", OptionRange::kPositive, &DecompositionOptions::tau, "maximum concavity, in the polygon's units"),
  };
  return rows;
}

const std::vector<ChoiceRow<DecompositionOptions>>& decomposition_choice_rows() {
  using D = DecompositionOptions;
  static const std::vector<ChoiceRow<D>> rows = {
      choice_row<D, CutSelection>("selection", &D::selection,
                                  {{"greedy", CutSelection::kGreedy}, {"reference", CutSelection::kReference}},
                                  "cut selection: greedy or reference (the authors' DP)"),
      choice_row<D, ConcavityMeasure>(
          "concavity-measure", &D::concavity,
          {{"straight", ConcavityMeasure::kStraightLine}, {"hierarchical", ConcavityMeasure::kHierarchical}},
          "how a pocket's concavity is measured: straight (reference code) or hierarchical (paper); the concavity bound itself is --tau"),
      choice_row<D, CandidateCuts>("candidates", &D::candidates,
                                   {{"validated", CandidateCuts::kValidated}, {"reference", CandidateCuts::kReference}},
                                   "candidate cuts: validated or reference (unchecked, repaired)"),
      choice_row<D, PocketPolygon>("pocket-polygons", &D::pocket_polygon,
                                   {{"split", PocketPolygon::kSplitOnBridge}, {"reference", PocketPolygon::kReference}},
                                   "dual pass on pockets: split (at the bridge) or reference"),
      choice_row<D, HullChainDistance>("hull-chain-distance", &D::hull_chain_distance,
                                       {{"segment", HullChainDistance::kSegment}, {"line", HullChainDistance::kLine}},
                                       "pocket hull-chain approximation: segment or line (reference)"),
      choice_row<D, SkinnyCutFilter>(
          "skinny", &D::skinny_cuts,
          {{"reference", SkinnyCutFilter::kReference}, {"all", SkinnyCutFilter::kAll}, {"off", SkinnyCutFilter::kOff}},
          "skinny-cut filter: reference, all or off"),
  };
  return rows;
}

}  // namespace topocut
