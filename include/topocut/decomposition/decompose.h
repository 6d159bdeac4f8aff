#pragma once
// Dual-space decomposition (DuDe, Liu, Xi & Lien, CVPR 2014) of a polygon with holes into nearly
// convex pieces, cutting only where the concavity exceeds tau. See ../shared/design/dude-algorithm.md.
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/core/option_choice.h"
#include "topocut/core/option_table.h"

namespace topocut {

// How the concavity of a pocket vertex is measured (dude-algorithm.md §3.4).
enum class ConcavityMeasure {
  kStraightLine,  // distance to the root hull bridge: the reference code's behaviour
  kHierarchical,  // distance to own bridge plus the bridges above it: the paper's definition
};

// How the cut sets are chosen (dude-algorithm.md §6).
enum class CutSelection {
  kReference,  // the reference's knapsack-like DP and pruning (roughly cubic; capped, see options)
  kGreedy,     // weight-ordered greedy with conflict checks (§6.4), near-linear
};

// Where candidate cuts come from (dude-algorithm.md §5.2, §6.5).
enum class CandidateCuts {
  // Diagonals of the simplified polygon are kept only if they lie inside the real polygon; every
  // candidate is a true interior diagonal (no repair needed, pieces never overlap).
  kValidated,
  // The reference: simplified-polygon diagonals are taken unchecked and selected cuts that cross the
  // boundary are "repaired" by moving one end point (§6.5). Cuts still invalid after the repair are
  // dropped, so pieces never overlap, but the reference's lost cuts (§8.5.1) are reproduced.
  kReference,
};

// What the dual pass of a pocket (§3.2) decomposes.
enum class PocketPolygon {
  // The pocket is split where its chain touches the bridge and each part is decomposed on its own.
  // Pockets along a flat wall (e.g. wall stubs next to a door) otherwise contain zero-width stretches
  // on the bridge whose corners look like deep reflex vertices; their spurious dual cuts then hide
  // the wall tips, so thin walls with doors are never cut.
  kSplitOnBridge,
  kReference,  // the whole chain plus the bridge as one (degenerate) polygon, as the reference
};

// How far a vertex of a pocket's hull chain is from its chord when the chain is approximated to
// pick pocket-minimum candidates (§3.3.4).
enum class HullChainDistance {
  kLine,     // distance to the chord's line, as the reference: a deep vertex beyond the end of the
             // bridge (a needle-shaped pocket) is dropped, and its piece is accepted too deep (§8.4)
  kSegment,  // distance to the chord itself, consistent with the depth test that follows
};

// The reference drops "skinny" cuts whose end points are close along the boundary (§6.5).
enum class SkinnyCutFilter {
  kReference,  // as the reference: every selected cut but the last one in the list is tested
  kAll,        // every selected cut is tested
  kOff,        // no skinny filter
};

struct DecompositionOptions {
  double tau = 2.5;      // maximum concavity, in the polygon's units
  int max_rounds = 100;  // cap on decomposition passes, so adversarial input terminates
  ConcavityMeasure concavity = ConcavityMeasure::kStraightLine;
  CutSelection selection = CutSelection::kGreedy;
  CandidateCuts candidates = CandidateCuts::kValidated;
  SkinnyCutFilter skinny_cuts = SkinnyCutFilter::kReference;
  PocketPolygon pocket_polygon = PocketPolygon::kSplitOnBridge;
  HullChainDistance hull_chain_distance = HullChainDistance::kSegment;
  // The reference deletes holes whose size, min(diameter, 2 * width), is below tau (§4.2): the
  // pieces then cover them. When false such holes stay holes of the pieces (they never get cuts).
  bool absorb_small_holes = true;
  // With kReference selection, inputs with more cut sets than this use the greedy selection instead
  // (the reference DP is roughly cubic in the number of cut sets).
  int reference_selection_limit = 150;
  // Final pieces whose outer ring runs along a slit to a hole (a "keyhole" left by a cut that
  // merged a hole) are returned as outer ring plus hole; false keeps the keyhole ring.
  bool restore_holes = true;
};

// The fields of DecompositionOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<DecompositionOptions>>& decomposition_option_rows();
// tau itself, in the polygon's units, for the front ends that decompose a polygon (decompose --tau,
// Python's decompose(tau=)); segment() sets it from --concavity in metres.
const std::vector<OptionRow<DecompositionOptions>>& decomposition_tau_rows();
// The fields of DecompositionOptions chosen by name (the reference variants: selection, concavity
// measure, candidates, pocket polygons, hull-chain distance, skinny cuts), as option_choice.h rows.
const std::vector<ChoiceRow<DecompositionOptions>>& decomposition_choice_rows();

struct Cut {
  Segment2 segment;  // both end points are input vertices; the open segment lies inside the piece it split
  int pass = 0;      // 0-based round in which the cut was applied
};

// A vertex a pass had to resolve (concavity >= tau for pockets, > tau for holes).
struct PocketMinimum {
  Point2 vertex;
  double concavity = 0.0;  // as measured by options.concavity (holes: §4.2-4.3)
  int pass = 0;
  bool on_hole = false;  // the vertex belongs to a hole (§4) rather than to the outer boundary (§3)
};

struct Decomposition {
  // Outer ring CCW, holes CW. Interiors are disjoint and the pieces cover the input plus its
  // absorbed holes exactly; every vertex is an input vertex.
  std::vector<PolygonWithHoles> pieces;
  std::vector<Cut> cuts;                      // in the order applied; cuts never cross
  std::vector<PocketMinimum> pocket_minima;   // of every pass on every piece, diagnostics
  std::vector<Ring> absorbed_holes;           // holes judged too small for tau and covered by pieces
  int rounds = 0;                             // rounds of passes run (at most options.max_rounds)
  // False when max_rounds stopped the work while a pass still had cuts to make: the pieces tile
  // the input, but some may be deeper than tau.
  bool complete = true;
};

// Decomposes polygon (rings in any orientation) into pieces that no further DuDe pass would cut:
// the reference's acceptance rule, which is not a hard bound on concavity (measure_concavity in
// concavity.h measures it). Deterministic. Throws Error on invalid input: fewer than 3 distinct
// vertices, non-finite coordinates, rings that cross or touch (themselves or each other), holes
// outside the outer ring or inside another hole, tau not positive, max_rounds < 1.
Decomposition decompose(const PolygonWithHoles& polygon, const DecompositionOptions& options = {});

}  // namespace topocut
