// The decomposition's option table (decompose.h). tau is left out (segment() sets it from the
// concavity in metres; the decompose command takes it as --tau), and so are the reference variants
// chosen by name (selection, concavity measure, ...), which the decompose command reads as text.
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

}  // namespace topocut
