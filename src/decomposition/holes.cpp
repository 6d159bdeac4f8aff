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

// §4.3: a hole whose dual pass produced cuts (corner pairs on ring h).
void complex_hole(PassState& st, int h, const std::vector<std::pair<int, int>>& cuts) {
  const Poly& poly = st.poly;
  const double tau = st.tau();
  const int m = poly.ring_size(h);
  const int k = static_cast<int>(cuts.size());

  // Intervals of the other cuts when the ring is numbered from cut i's first end point.
  auto sides = [&](int i, std::vector<std::pair<int, int>>& a, std::vector<std::pair<int, int>>& b,
                   std::vector<int>& a_ids, std::vector<int>& b_ids) {
    const int s = cuts[i].first;
    const int t = poly.offset(s, cuts[i].second);
    for (int j = 0; j < k; ++j) {
      if (j == i) continue;
      int pu = poly.offset(s, cuts[j].first), pw = poly.offset(s, cuts[j].second);
      if (pu <= t && pw <= t) {
        a.emplace_back(std::min(pu, pw), std::max(pu, pw));
        a_ids.push_back(j);
      } else {
        if (pu == 0) pu = m;
        if (pw == 0) pw = m;
        b.emplace_back(std::min(pu, pw), std::max(pu, pw));
        b_ids.push_back(j);
      }
    }
  };
  // Ties between equally deep roots go to the geometrically smallest cut, not to ring order, so
  // the result does not depend on where the ring starts.
  auto ends_sorted = [&](int i) {
    Pt a = poly.pt[cuts[i].first], b = poly.pt[cuts[i].second];
    if (b < a) std::swap(a, b);
    return std::pair{a, b};
  };
  int root = 0, best = std::numeric_limits<int>::max();
  for (int i = 0; i < k; ++i) {
    std::vector<std::pair<int, int>> a, b;
    std::vector<int> ai, bi;
    sides(i, a, b, ai, bi);
    const int depth = 1 + std::max(nesting_depth(a), nesting_depth(b));
    if (depth < best || (depth == best && ends_sorted(i) < ends_sorted(root))) {
      best = depth;
      root = i;
    }
  }

  // Cut tree below the root and the skeleton-like cut concavity hc (§4.3.2).
  std::vector<double> hc(k, 0.0);
  {
    std::vector<std::pair<int, int>> a, b;
    std::vector<int> ai, bi;
    sides(root, a, b, ai, bi);
    auto mid = [&](int j) {
      const Pt& p = poly.pt[cuts[j].first];
      const Pt& q = poly.pt[cuts[j].second];
      return Pt((p.x() + q.x()) / 2, (p.y() + q.y()) / 2);
    };
    for (auto* side : {&a, &b}) {
      const std::vector<int>& ids = side == &a ? ai : bi;
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
  }
  std::vector<double> end_hc(poly.corners(), std::numeric_limits<double>::infinity());
  std::vector<int> ends;
  for (int j = 0; j < k; ++j) {
    for (int c : {cuts[j].first, cuts[j].second}) {
      end_hc[c] = std::min(end_hc[c], hc[j]);
      ends.push_back(c);
    }
  }
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());

  std::vector<int> features;
  // §4.3.3 chains between consecutive cut end points.
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const int first = ends[i], last = ends[(i + 1) % ends.size()];
    const std::vector<int> chain = chain_between(poly, first, last);
    const std::vector<int> kept = approx(poly, chain, 0.8 * tau);
    for (std::size_t j = 1; j + 1 < kept.size(); ++j) {
      const int v = chain[kept[j]];
      features.push_back(v);
      if (!is_reflex(poly, v)) continue;
      const double depth = dline(poly.pt[v], poly.pt[first], poly.pt[last]);
      st.concavity[v] = std::min(end_hc[first], end_hc[last]) + depth;
      if (depth > tau) st.pm[v] = 1;
    }
  }
  // §4.3.4 cut end points.
  for (int c : ends) {
    features.push_back(c);
    if (is_reflex(poly, c)) st.concavity[c] = end_hc[c];
  }
  // §4.3.5 the root's end points.
  int rs = cuts[root].first, rt = cuts[root].second;
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
      if (c > tau) st.pm[r] = 1;
    }
    break;
  }
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
