// §1 dude_pass: one pass of the dual-space decomposition over one polygon, and the cut filters that
// the reference applies to top-level passes (§6.5).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_set>

#include <CGAL/Polygon_2_algorithms.h>

#include "decomposition/pass_state.h"
#include "decomposition/ring_measures.h"

namespace topocut::dude {

namespace {

// §3.6 special case: an outer ring without pockets around holes is described by its diameter.
void outer_diameter_features(PassState& st) {
  const Poly& poly = st.poly;
  std::vector<int> ring;
  for (int c = poly.ring_start[0]; c < poly.ring_start[1]; ++c) ring.push_back(c);
  const Diameter d = diameter_of(poly, ring);
  if (d.m1 < 0 || d.m2 < 0) return;
  st.feature[d.m1] = st.feature[d.m2] = 1;
  for (const auto& [from, to] : {std::pair{d.m1, d.m2}, std::pair{d.m2, d.m1}}) {
    std::vector<int> chain{from};
    for (int c = poly.next(from); c != from; c = poly.next(c)) {
      chain.push_back(c);
      if (c == to) break;
    }
    for (int i : approx(poly, chain, st.tau())) st.feature[chain[i]] = 1;
  }
}

// True when p lies strictly inside the polygon (deleted holes ignored).
bool strictly_inside(const Poly& poly, const std::vector<char>& deleted, const Pt& p) {
  for (int r = 0; r < poly.rings(); ++r) {
    if (deleted[r]) continue;
    const auto begin = poly.pt.begin() + poly.ring_start[r];
    const auto end = poly.pt.begin() + poly.ring_start[r + 1];
    const CGAL::Bounded_side side = CGAL::bounded_side_2(begin, end, p, K());
    if (side == CGAL::ON_BOUNDARY) return false;
    if ((side == CGAL::ON_BOUNDED_SIDE) != (r == 0)) return false;
  }
  return true;
}

// §6.5.2: the reference's repair of a cut that crosses the boundary: keep the end point whose
// side is free, move the other one to an end of the first crossed edge.
std::pair<int, int> repair(const PassState& st, std::pair<int, int> cut) {
  const Poly& poly = st.poly;
  const auto [a, b] = cut;
  const K::Segment_2 seg(poly.pt[a], poly.pt[b]);
  double best_a = std::numeric_limits<double>::infinity(), best_b = best_a;
  int edge_a = -1, edge_b = -1;
  Pt ia(0, 0), ib(0, 0);
  for (int c = 0; c < poly.corners(); ++c) {
    if (st.deleted[poly.ring[c]]) continue;
    const K::Segment_2 edge(poly.pt[c], poly.pt[poly.next(c)]);
    const auto hit = CGAL::intersection(seg, edge);
    if (!hit) continue;
    const Pt* x = boost::get<Pt>(&*hit);
    if (!x) continue;  // collinear overlap: ignored like the reference
    const double da = dist(*x, poly.pt[a]), db = dist(*x, poly.pt[b]);
    if (da < 1e-8 || db < 1e-8) continue;
    if (da < best_a) {
      best_a = da;
      edge_a = c;
      ia = *x;
    }
    if (db < best_b) {
      best_b = db;
      edge_b = c;
      ib = *x;
    }
  }
  if (edge_a < 0) return cut;
  auto mid = [](const Pt& p, const Pt& q) { return Pt((p.x() + q.x()) / 2, (p.y() + q.y()) / 2); };
  const bool free_a = strictly_inside(poly, st.deleted, mid(poly.pt[a], ia));
  const bool free_b = strictly_inside(poly, st.deleted, mid(poly.pt[b], ib));
  if (!free_a && !free_b) return cut;
  const bool keep_a = free_a && (!free_b || best_a >= best_b);
  const int kept = keep_a ? a : b;
  const int edge = keep_a ? edge_a : edge_b;
  const int e1 = edge, e2 = poly.next(edge);
  const int moved = dist(poly.pt[e1], poly.pt[kept]) <= dist(poly.pt[e2], poly.pt[kept]) ? e1 : e2;
  return {std::min(kept, moved), std::max(kept, moved)};
}

// Boundary length walked forward from a until b is met, or infinity once `limit` is exceeded.
double walk_length(const Poly& poly, int a, int b, double limit) {
  if (poly.ring[a] != poly.ring[b]) return std::numeric_limits<double>::infinity();
  double length = 0.0;
  for (int c = a; c != b; c = poly.next(c)) {
    length += dist(poly.pt[c], poly.pt[poly.next(c)]);
    if (length >= limit) return std::numeric_limits<double>::infinity();
  }
  return length;
}

std::vector<std::pair<int, int>> filter_top(const PassState& st, std::vector<std::pair<int, int>> cuts) {
  const Poly& poly = st.poly;
  const DecompositionOptions& options = st.settings.options;
  const double tau = st.tau();
  if (options.candidates == CandidateCuts::kReference) {
    for (auto& cut : cuts) cut = repair(st, cut);
  }
  // The filters below depend on the order of the cuts and of their end points: use geometry (the
  // smaller point first, cuts by their points), not ring positions, so that where a ring starts
  // does not matter.
  for (auto& cut : cuts) {
    if (poly.pt[cut.second] < poly.pt[cut.first] ||
        (poly.pt[cut.second] == poly.pt[cut.first] && cut.second < cut.first)) {
      std::swap(cut.first, cut.second);
    }
  }
  std::sort(cuts.begin(), cuts.end(), [&](const auto& x, const auto& y) {
    if (poly.pt[x.first] != poly.pt[y.first]) return poly.pt[x.first] < poly.pt[y.first];
    if (poly.pt[x.second] != poly.pt[y.second]) return poly.pt[x.second] < poly.pt[y.second];
    return x < y;
  });
  std::vector<std::pair<int, int>> kept;
  std::unordered_set<std::uint64_t> seen;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const auto [a, b] = cuts[i];
    if (a == b) continue;
    if (poly.ring[a] == poly.ring[b] && (poly.next(a) == b || poly.next(b) == a)) continue;  // ring neighbours
    int va = poly.vid[a], vb = poly.vid[b];
    if (va > vb) std::swap(va, vb);
    if (!seen.insert((static_cast<std::uint64_t>(va) << 32) | static_cast<std::uint32_t>(vb)).second) continue;
    const bool test_skinny = options.skinny_cuts == SkinnyCutFilter::kAll ||
                             (options.skinny_cuts == SkinnyCutFilter::kReference && i + 1 < cuts.size());
    if (test_skinny && (walk_length(poly, a, b, 2 * tau) < 2 * tau || walk_length(poly, b, a, 3 * tau) < 3 * tau)) {
      continue;
    }
    kept.push_back({a, b});
  }
  // Safety net: only interior diagonals that do not cross are applied. Validated candidates are
  // triangulation edges or diagonals checked against the boundary already, so for them the local
  // tests (both ends leave into their wedges) suffice; the reference's candidates get the full test.
  std::vector<char> inside(kept.size(), 1);
  if (options.candidates == CandidateCuts::kReference) {
    inside = segments_inside(poly, kept, st.deleted);
  } else {
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const auto [a, b] = kept[i];
      inside[i] = in_wedge(poly, a, poly.pt[b]) && in_wedge(poly, b, poly.pt[a]);
    }
  }
  std::vector<std::pair<int, int>> valid;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (inside[i]) valid.push_back(kept[i]);
  }
  const std::vector<char> keep = non_crossing_prefix(poly, valid);
  std::vector<std::pair<int, int>> result;
  for (std::size_t i = 0; i < valid.size(); ++i) {
    if (keep[i]) result.emplace_back(std::min(valid[i].first, valid[i].second), std::max(valid[i].first, valid[i].second));
  }
  return result;
}

}  // namespace

PassResult dude_pass(const Poly& poly, const Settings& settings, bool top, int depth) {
  PassState st(poly, settings);
  st.top = top;
  st.depth = depth;
  PassResult result;
  analyse_outer(st);
  analyse_holes(st);
  bool holes_left = false;
  for (int r = 1; r < poly.rings(); ++r) {
    if (st.deleted[r]) {
      result.deleted_holes.push_back(r);
    } else {
      holes_left = true;
    }
  }
  for (int c = 0; c < poly.corners(); ++c) {
    if (st.pm[c]) result.pms.emplace_back(c, st.concavity[c]);
  }
  if (result.pms.empty()) return result;
  outer_features(st);
  if (st.roots.empty() && holes_left) outer_diameter_features(st);
  const std::vector<std::pair<int, int>> diagonals = candidate_diagonals(st);
  std::vector<std::pair<int, int>> cuts = select_cuts(st, diagonals);
  if (top) cuts = filter_top(st, std::move(cuts));
  result.cuts = std::move(cuts);
  return result;
}

}  // namespace topocut::dude
