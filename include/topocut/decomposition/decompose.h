#pragma once
// Dual-space decomposition (DuDe, Liu, Xi & Lien, CVPR 2014) of a polygon with holes into nearly
// convex pieces, cutting only where the concavity exceeds tau. See ../shared/design/dude-algorithm.md.
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut {

// How the concavity of a pocket vertex is measured (dude-algorithm.md §3.4).
enum class ConcavityMeasure {
  kStraightLine,  // distance to the root hull bridge: the reference code's behaviour
  kHierarchical,  // distance to own bridge plus the bridges above it: the paper's definition
};

// How the cut sets are chosen (dude-algorithm.md §6).
enum class CutSelection {
  kReference,  // the reference's knapsack-like DP and pruning (roughly cubic)
  kGreedy,     // weight-ordered greedy with conflict checks (§6.4), near-linear
};

struct DecompositionOptions {
  double tau = 2.5;      // maximum concavity, in the polygon's units
  int max_rounds = 100;  // cap on decomposition passes, so adversarial input terminates
  ConcavityMeasure concavity = ConcavityMeasure::kStraightLine;
  CutSelection selection = CutSelection::kGreedy;
};

struct Cut {
  Segment2 segment;  // both end points are vertices of the piece it split
  int pass = 0;      // 0-based round in which the cut was applied
};

struct PocketMinimum {
  Point2 vertex;
  double concavity = 0.0;
  int pass = 0;
};

struct Decomposition {
  std::vector<PolygonWithHoles> pieces;       // outer CCW, holes CW; tile the input minus absorbed holes
  std::vector<Cut> cuts;                      // in the order applied
  std::vector<PocketMinimum> pocket_minima;   // per pass, diagnostics
  std::vector<Ring> absorbed_holes;           // holes judged too small for tau and covered by pieces
  int rounds = 0;                             // passes run
};

// Decomposes polygon into pieces whose concavity is at most options.tau (see the spec for the
// acceptance rule). Throws Error on invalid input (fewer than 3 vertices, non-finite coordinates,
// self-intersecting rings, holes outside the outer ring, tau <= 0).
Decomposition decompose(const PolygonWithHoles& polygon, const DecompositionOptions& options = {});

}  // namespace topocut
