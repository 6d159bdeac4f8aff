// §4: holes. Each hole is decomposed as a polygon (the other dual space); a hole that needs no cut
// is "simple" and described by its diameter, otherwise "complex" and described by its cut tree.
#include <algorithm>
#include <limits>

#include "decomposition/pass_state.h"
#include "decomposition/ring_measures.h"

namespace topocut::dude {

Diameter diameter_of(const Poly& poly, const std::vector<int>& ring) {
  Diameter d;
  const std::vector<int> hull = hull_of(poly, ring);
  auto d2 = [&](int a, int b) { return sq(poly.pt[a].x() - poly.pt[b].x()) + sq(poly.pt[a].y() - poly.pt[b].y()); };
  double best = -1.0;
  std::vector<int> ends;  // corners taking part in a diametral pair
  for (std::size_t i = 0; i < hull.size(); ++i) {
    for (std::size_t j = i + 1; j < hull.size(); ++j) {
      const double v = d2(hull[i], hull[j]);
      if (v > best) {
        best = v;
        ends = {hull[i], hull[j]};
      } else if (v == best) {
        ends.push_back(hull[i]);
        ends.push_back(hull[j]);
      }
    }
  }
  if (ends.empty()) return d;
  // Ties are broken geometrically (smallest point first) so that the result does not depend on the
  // ring's start or orientation.
  d.m1 = *std::min_element(ends.begin(), ends.end(), [&](int a, int b) {
    return poly.pt[a] != poly.pt[b] ? poly.pt[a] < poly.pt[b] : a < b;
  });
  double far = -1.0;
  for (int c : ring) {
    const double v = d2(d.m1, c);
    if (v > far || (v == far && (poly.pt[c] < poly.pt[d.m2] || (poly.pt[c] == poly.pt[d.m2] && c < d.m2)))) {
      far = v;
      d.m2 = c;
    }
  }
  d.length = std::sqrt(far);
  double w = 0.0;
  for (int c : ring) w = std::max(w, dline(poly.pt[c], poly.pt[d.m1], poly.pt[d.m2]));
  d.width2 = 2.0 * w;
  return d;
}

namespace {

std::vector<int> chain_between(const Poly& poly, int from, int to) {
  std::vector<int> chain{from};
  for (int c = poly.next(from); c != from; c = poly.next(c)) {
    chain.push_back(c);
    if (c == to) break;
  }
  return chain;
}

// §4.2: a hole whose dual pass produced no cut.
void simple_hole(PassState& st, int h) {
  const Poly& poly = st.poly;
  const double tau = st.tau();
  std::vector<int> ring;
  for (int c = poly.ring_start[h]; c < poly.ring_start[h + 1]; ++c) ring.push_back(c);
  const Diameter d = diameter_of(poly, ring);
  const bool small = std::min(d.length, d.width2) < tau;
  if (small && st.top && st.settings.options.absorb_small_holes) {
    st.deleted[h] = 1;
    return;
  }
  std::vector<int> features{d.m1, d.m2};
  if (!small) {
    st.pm[d.m1] = st.pm[d.m2] = 1;
    st.concavity[d.m1] = st.concavity[d.m2] = d.length;
  }
  const Pt& a = poly.pt[d.m1];
  const Pt& b = poly.pt[d.m2];
  for (const auto& [from, to] : {std::pair{d.m1, d.m2}, std::pair{d.m2, d.m1}}) {
    const std::vector<int> chain = chain_between(poly, from, to);
    const std::vector<int> kept = approx(poly, chain, tau);
    for (std::size_t i = 1; i + 1 < kept.size(); ++i) {
      const int v = chain[kept[i]];
      features.push_back(v);
      const double c = dline(poly.pt[v], a, b);
      st.concavity[v] = c;
      if (c > tau && !small) st.pm[v] = 1;
    }
  }
  if (features.size() < 3) {
    int far = -1;
    double best = -1.0;
    for (int c : ring) {
      if (c == d.m1 || c == d.m2) continue;
      const double v = dline(poly.pt[c], a, b);
      if (v > best || (v == best && poly.pt[c] < poly.pt[far])) {
        best = v;
        far = c;
      }
    }
    if (far >= 0) features.push_back(far);
  }
  for (int v : features) {
    st.feature[v] = 1;
    st.hole_owner[v] = h;
  }
}

// Maximum nesting depth of laminar intervals.
int nesting_depth(std::vector<std::pair<int, int>> intervals) {
  std::sort(intervals.begin(), intervals.end(), [](const auto& x, const auto& y) {
    return x.first != y.first ? x.first < y.first : x.second > y.second;
  });
  std::vector<std::pair<int, int>> stack;
  int depth = 0;
  for (const auto& iv : intervals) {
    while (!stack.empty() && !(stack.back().first <= iv.first && iv.second <= stack.back().second)) stack.pop_back();
    stack.push_back(iv);
    depth = std::max(depth, static_cast<int>(stack.size()));
  }
  return depth;
}

// The other cuts of a complex hole, as intervals of ring offsets when the ring is numbered from
// one cut's first end point: those on its first side (a) and on its second (b).
struct CutSides {
  std::vector<std::pair<int, int>> a, b;
  std::vector<int> a_ids, b_ids;  // the cut of each interval
};

CutSides sides_of(const Poly& poly, const std::vector<std::pair<int, int>>& cuts, int i, int m) {
  const int k = static_cast<int>(cuts.size());
  CutSides sides;
  const int s = cuts[i].first;
  const int t = poly.offset(s, cuts[i].second);
  for (int j = 0; j < k; ++j) {
    if (j == i) continue;
    int pu = poly.offset(s, cuts[j].first), pw = poly.offset(s, cuts[j].second);
    if (pu <= t && pw <= t) {
      sides.a.emplace_back(std::min(pu, pw), std::max(pu, pw));
      sides.a_ids.push_back(j);
    } else {
      if (pu == 0) pu = m;
      if (pw == 0) pw = m;
      sides.b.emplace_back(std::min(pu, pw), std::max(pu, pw));
      sides.b_ids.push_back(j);
    }
  }
  return sides;
}

// §4.3.1 the root of the cut tree: the cut whose sides nest least deep. Ties between equally deep
// roots go to the geometrically smallest cut, not to ring order, so the result does not depend on
// where the ring starts.
int root_cut(const Poly& poly, const std::vector<std::pair<int, int>>& cuts, int m) {
  const int k = static_cast<int>(cuts.size());
  auto ends_sorted = [&](int i) {
    Pt a = poly.pt[cuts[i].first], b = poly.pt[cuts[i].second];
    if (b < a) std::swap(a, b);
    return std::pair{a, b};
  };
  int root = 0, best = std::numeric_limits<int>::max();
  for (int i = 0; i < k; ++i) {
    const CutSides sides = sides_of(poly, cuts, i, m);
    const int depth = 1 + std::max(nesting_depth(sides.a), nesting_depth(sides.b));
    if (depth < best || (depth == best && ends_sorted(i) < ends_sorted(root))) {
      best = depth;
      root = i;
    }
  }
  return root;
}

// §4.3.2 the skeleton-like cut concavity hc of every cut: the path length from the root's midpoint
// down the cut tree (intervals nested on each side) to the cut's midpoint.
std::vector<double> cut_concavity(const Poly& poly, const std::vector<std::pair<int, int>>& cuts, int root, int m) {
  std::vector<double> hc(cuts.size(), 0.0);
  CutSides sides = sides_of(poly, cuts, root, m);
  auto mid = [&](int j) {
    const Pt& p = poly.pt[cuts[j].first];
    const Pt& q = poly.pt[cuts[j].second];
    return Pt((p.x() + q.x()) / 2, (p.y() + q.y()) / 2);
  };
  for (auto* side : {&sides.a, &sides.b}) {
    const std::vector<int>& ids = side == &sides.a ? sides.a_ids : sides.b_ids;
    std::vector<int> order(ids.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::sort(order.begin(), order.end(), [&](int x, int y) {
      const auto& u = (*side)[x];
      const auto& w = (*side)[y];
      return u.first != w.first ? u.first < w.first : u.second > w.second;
    });
    std::vector<int> stack;  // positions in side
    for (int x : order) {
      while (!stack.empty() && !((*side)[stack.back()].first <= (*side)[x].first &&
                                 (*side)[x].second <= (*side)[stack.back()].second)) {
        stack.pop_back();
      }
      const int parent = stack.empty() ? root : ids[stack.back()];
      hc[ids[x]] = hc[parent] + dist(mid(parent), mid(ids[x]));
      stack.push_back(x);
    }
  }
  return hc;
}

// The distinct cut end points in corner order, each with the least hc of the cuts ending there.
struct CutEnds {
  std::vector<int> corners;
  std::vector<double> hc;  // per corner of the polygon; infinity where no cut ends
};

CutEnds cut_ends(const Poly& poly, const std::vector<std::pair<int, int>>& cuts, const std::vector<double>& hc) {
  CutEnds ends{{}, std::vector<double>(poly.corners(), std::numeric_limits<double>::infinity())};
  for (std::size_t j = 0; j < cuts.size(); ++j) {
    for (int c : {cuts[j].first, cuts[j].second}) {
      ends.hc[c] = std::min(ends.hc[c], hc[j]);
      ends.corners.push_back(c);
    }
  }
  std::sort(ends.corners.begin(), ends.corners.end());
  ends.corners.erase(std::unique(ends.corners.begin(), ends.corners.end()), ends.corners.end());
  return ends;
}

// §4.3.3 features of the chains between consecutive cut end points; a reflex one's concavity is
// its depth below the chain's chord on top of the nearer end's hc.
std::vector<int> chain_features(PassState& st, const CutEnds& ends) {
  const Poly& poly = st.poly;
  const double tau = st.tau();
  std::vector<int> features;
  for (std::size_t i = 0; i < ends.corners.size(); ++i) {
    const int first = ends.corners[i], last = ends.corners[(i + 1) % ends.corners.size()];
    const std::vector<int> chain = chain_between(poly, first, last);
    const std::vector<int> kept = approx(poly, chain, 0.8 * tau);
    for (std::size_t j = 1; j + 1 < kept.size(); ++j) {
      const int v = chain[kept[j]];
      features.push_back(v);
      if (!is_reflex(poly, v)) continue;
      const double depth = dline(poly.pt[v], poly.pt[first], poly.pt[last]);
      st.concavity[v] = std::min(ends.hc[first], ends.hc[last]) + depth;
      if (depth > tau) st.pm[v] = 1;
    }
  }
  return features;
}

// §4.3.5 the root's first reflex end point (the smaller point first): its concavity reaches across
// the root to the other end's reflex neighbours.
void root_end_concavity(PassState& st, const std::pair<int, int>& root) {
  const Poly& poly = st.poly;
  int rs = root.first, rt = root.second;
  if (poly.pt[rt] < poly.pt[rs]) std::swap(rs, rt);  // "start" end point: the smaller point
  for (const auto& [r, q] : {std::pair{rs, rt}, std::pair{rt, rs}}) {
    if (!is_reflex(poly, r)) continue;
    int pre = -1, nxt = -1;
    for (int c = poly.prev(q); c != q; c = poly.prev(c)) {
      if (is_reflex(poly, c)) {
        pre = c;
        break;
      }
    }
    for (int c = poly.next(q); c != q; c = poly.next(c)) {
      if (is_reflex(poly, c)) {
        nxt = c;
        break;
      }
    }
    if (pre >= 0 && nxt >= 0) {
      const double c = dist(poly.pt[r], poly.pt[q]) + dseg(poly.pt[q], poly.pt[pre], poly.pt[nxt]);
      st.concavity[r] = c;
      if (c > st.tau()) st.pm[r] = 1;
    }
    break;
  }
}

// §4.3: a hole whose dual pass produced cuts (corner pairs on ring h).
void complex_hole(PassState& st, int h, const std::vector<std::pair<int, int>>& cuts) {
  const Poly& poly = st.poly;
  const int m = poly.ring_size(h);
  const int root = root_cut(poly, cuts, m);
  const CutEnds ends = cut_ends(poly, cuts, cut_concavity(poly, cuts, root, m));
  std::vector<int> features = chain_features(st, ends);
  // §4.3.4 cut end points.
  for (int c : ends.corners) {
    features.push_back(c);
    if (is_reflex(poly, c)) st.concavity[c] = ends.hc[c];
  }
  root_end_concavity(st, cuts[root]);
  for (int v : features) {
    st.feature[v] = 1;
    st.hole_owner[v] = h;
  }
}

}  // namespace

void analyse_holes(PassState& st) {
  const Poly& poly = st.poly;
  for (int h = 1; h < poly.rings(); ++h) {
    // The hole as a counter-clockwise polygon of its own, first corner kept first.
    std::vector<Pt> pts;
    std::vector<int> vids, map;
    const int begin = poly.ring_start[h], end = poly.ring_start[h + 1];
    for (int i = 0; i < end - begin; ++i) {
      const int c = i == 0 ? begin : end - i;
      pts.push_back(poly.pt[c]);
      vids.push_back(poly.vid[c]);
      map.push_back(c);
    }
    Poly hole;
    hole.add_ring(pts, vids);
    PassResult dual;
    if (st.depth < st.settings.max_depth) dual = dude_pass(hole, st.settings, false, st.depth + 1);
    if (dual.cuts.empty()) {
      simple_hole(st, h);
    } else {
      std::vector<std::pair<int, int>> cuts;
      for (const auto& [x, y] : dual.cuts) cuts.emplace_back(std::min(map[x], map[y]), std::max(map[x], map[y]));
      std::sort(cuts.begin(), cuts.end());
      complex_hole(st, h, cuts);
    }
  }
}

}  // namespace topocut::dude
