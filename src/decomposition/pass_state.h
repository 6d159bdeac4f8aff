#pragma once
// Per-pass state of DuDe (Appendix A of the spec): arrays indexed by corner, owned by one pass, so
// nothing leaks between passes (the reference's use-after-free, §8.5.3, cannot happen).
#include <utility>
#include <vector>

#include "decomposition/dude.h"

namespace topocut::dude {

// A pocket (§3): the region between a bridge s-e and the outer-ring chain s -> ... -> e.
struct Pocket {
  int s = -1, e = -1;  // corners on ring 0
  int len = 0;         // chain length in edges (offset of e from s)
  int parent = -1;     // enclosing pocket, -1 for a root pocket
  int root = -1;       // the root (hull-edge) pocket of the tree
  std::vector<int> kids;
  std::vector<int> pms;  // pocket-minimum candidates collected in this pocket's subtree (§3.3)
};

struct PassState {
  PassState(const Poly& p, const Settings& s)
      : poly(p),
        settings(s),
        owner(p.corners(), -1),
        hole_owner(p.corners(), -1),
        concavity(p.corners(), 0.0),
        feature(p.corners(), 0),
        pm(p.corners(), 0),
        dpre(p.corners(), -1),
        dnext(p.corners(), -1),
        deleted(p.rings(), 0) {}

  const Poly& poly;
  const Settings& settings;
  std::vector<int> owner;        // §3.3.5 pocket id
  std::vector<int> hole_owner;   // §4.4 ring id
  std::vector<double> concavity; // §3.4 / §4
  std::vector<char> feature;     // §5.1
  std::vector<char> pm;          // final pocket minima of this pass
  std::vector<int> dpre, dnext;  // neighbouring features (§5.1)
  std::vector<Pocket> pockets;
  std::vector<int> roots;          // root (hull-edge) pockets in ring order
  std::vector<int> deep_roots;     // analysed by analyse_outer
  std::vector<int> shallow_roots;  // analysed only when features are needed (outer_features)
  std::vector<char> deleted;     // per ring: hole judged noise (§4.2)
  int depth = 0;
  bool top = false;

  double tau() const { return settings.tau; }
  // True when corner x lies on pocket p's chain after its start: next(s) .. e inclusive.
  bool on_chain(int p, int x) const {
    const Pocket& k = pockets[p];
    if (poly.ring[x] != 0) return false;
    const int off = poly.offset(k.s, x);
    return off >= 1 && off <= k.len;
  }
};

// §3: hull and root pockets; the hierarchy and pocket minima of every root pocket that can hold one.
void analyse_outer(PassState& st);
// §3.2-3.4 for one root pocket: dual decomposition, minima candidates, final minima.
void analyse_root(PassState& st, int root);
// §3.6: completes the remaining root pockets and marks the features of the outer ring.
void outer_features(PassState& st);
// §4: holes as polygons; simple holes may be deleted; hole minima and hole features.
void analyse_holes(PassState& st);
// §5.1-5.3: features -> dpre/dnext, then candidate diagonals (corner pairs, first < second).
std::vector<std::pair<int, int>> candidate_diagonals(PassState& st);
// §5.4-6.4: cut sets and their selection; returns the chosen diagonals as corner pairs.
std::vector<std::pair<int, int>> select_cuts(const PassState& st, const std::vector<std::pair<int, int>>& diagonals);

// True for each segment (corner pair) that lies strictly inside poly's interior except at its end
// points (deleted rings ignored): no boundary edge or vertex on its relative interior, and it leaves
// both end corners inside their wedges.
std::vector<char> segments_inside(const Poly& poly, const std::vector<std::pair<int, int>>& segments,
                                  const std::vector<char>& deleted_rings);

// The subset of segments (corner pairs, in the given order) that keeps every segment not crossing
// or overlapping one kept earlier (sharing an end point is fine).
std::vector<char> non_crossing_prefix(const Poly& poly, const std::vector<std::pair<int, int>>& segments);

}  // namespace topocut::dude
