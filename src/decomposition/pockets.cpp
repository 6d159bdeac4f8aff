// §3: pockets of the outer ring, their dual decomposition into a pocket hierarchy, pocket minima
// and the features of the outer ring.
#include <algorithm>

#include "decomposition/pass_state.h"

namespace topocut::dude {

namespace {

// The polygon of the chain stretch [lo, hi] (offsets from s) of a root pocket, closed by the bridge
// line: the corners at hi, hi-1, ..., lo, counter-clockwise (§3.2.1).
Poly pocket_polygon(const Poly& poly, int s, int lo, int hi, std::vector<int>& map) {
  std::vector<Pt> pts;
  std::vector<int> vids;
  map.clear();
  const int n = poly.ring_size(0);
  for (int o = hi; o >= lo; --o) {
    const int c = poly.ring_start[0] + (s - poly.ring_start[0] + o) % n;
    pts.push_back(poly.pt[c]);
    vids.push_back(poly.vid[c]);
    map.push_back(o);
  }
  Poly q;
  q.add_ring(pts, vids);
  return q;
}

// Adds the children found by the dual decomposition of root pocket `root` (§3.2).
void add_children(PassState& st, int root) {
  const Poly& poly = st.poly;
  const int s = st.pockets[root].s;
  const int len = st.pockets[root].len;
  const Pt& ps = poly.pt[s];
  const Pt& pe = poly.pt[st.pockets[root].e];
  auto corner_at = [&](int o) { return poly.ring_start[0] + (s - poly.ring_start[0] + o) % poly.ring_size(0); };

  // The stretches to decompose: the whole chain, or the parts between chain vertices on the bridge.
  std::vector<std::pair<int, int>> stretches;
  if (st.settings.options.pocket_polygon == PocketPolygon::kReference) {
    stretches.emplace_back(0, len);
  } else {
    int last = 0;
    bool deep = false;
    for (int o = 1; o <= len; ++o) {
      const int c = corner_at(o);
      if (o < len && CGAL::orientation(ps, pe, poly.pt[c]) != CGAL::COLLINEAR) {
        deep = true;
        continue;
      }
      if (deep && o - last >= 2) stretches.emplace_back(last, o);
      last = o;
      deep = false;
    }
  }

  struct Child {
    int lo, hi;
  };
  std::vector<Child> kids;
  std::vector<int> map;
  for (const auto& [from, to] : stretches) {
    const Poly q = pocket_polygon(poly, s, from, to, map);
    const PassResult dual = dude_pass(q, st.settings, false, st.depth + 1);
    for (const auto& [x, y] : dual.cuts) {
      int lo = map[x], hi = map[y];
      if (lo > hi) std::swap(lo, hi);
      if (hi - lo < 2 || (lo == 0 && hi == len)) continue;
      // Orient by the negative-area rule (§3.1): the chain lo..hi must enclose a clockwise region.
      if (!(chain_area2(poly, corner_at(lo), corner_at(hi)) < 0.0)) continue;
      kids.push_back({lo, hi});
    }
  }
  // Dual cuts do not cross, so the chain intervals are laminar: nest them with a stack (§3.2.4).
  std::sort(kids.begin(), kids.end(), [](const Child& a, const Child& b) {
    return a.lo != b.lo ? a.lo < b.lo : a.hi > b.hi;
  });
  std::vector<int> stack;  // pocket ids
  for (const Child& k : kids) {
    while (!stack.empty()) {
      const Pocket& top = st.pockets[stack.back()];
      const int tlo = poly.offset(s, top.s), thi = tlo + top.len;
      if (tlo <= k.lo && k.hi <= thi) break;
      stack.pop_back();
    }
    Pocket child;
    child.s = corner_at(k.lo);
    child.e = corner_at(k.hi);
    child.len = k.hi - k.lo;
    child.parent = stack.empty() ? root : stack.back();
    child.root = root;
    const int id = static_cast<int>(st.pockets.size());
    st.pockets.push_back(child);
    st.pockets[st.pockets[id].parent].kids.push_back(id);
    stack.push_back(id);
  }
}

// §3.3: pocket-minimum candidates of pocket p, children first.
void collect_minima(PassState& st, int p) {
  const Poly& poly = st.poly;
  const double tau = st.tau();
  const std::vector<int> kids = st.pockets[p].kids;
  for (int k : kids) collect_minima(st, k);
  const Pocket& b = st.pockets[p];
  const Pt& ps = poly.pt[b.s];
  const Pt& pe = poly.pt[b.e];

  std::vector<int> from_children;
  std::vector<char> excluded(b.len + 1, 0);
  std::vector<char> pm_kid_end(b.len + 1, 0);
  for (int k : kids) {
    const Pocket& kid = st.pockets[k];
    from_children.insert(from_children.end(), kid.pms.begin(), kid.pms.end());
    if (kid.pms.empty()) continue;
    const int lo = poly.offset(b.s, kid.s);
    for (int o = lo + 1; o < lo + kid.len; ++o) excluded[o] = 1;
    pm_kid_end[lo] = pm_kid_end[lo + kid.len] = 1;
  }

  // Convex hull of the remaining chain on the deep side of the bridge, as a polyline s -> ... -> e.
  std::vector<int> pts{b.s, b.e};
  for (int o = 1, c = poly.next(b.s); o < b.len; ++o, c = poly.next(c)) {
    if (!excluded[o] && CGAL::orientation(ps, pe, poly.pt[c]) == CGAL::LEFT_TURN) pts.push_back(c);
  }
  std::vector<int> hullchain{b.s};
  if (pts.size() > 2) {
    const std::vector<int> hull = hull_of(poly, pts);  // counter-clockwise: s, e, d1 .. dk
    const int h = static_cast<int>(hull.size());
    const int is = static_cast<int>(std::find(hull.begin(), hull.end(), b.s) - hull.begin());
    if (is < h) {
      for (int i = (is + h - 1) % h; i != is; i = (i + h - 1) % h) {
        if (hull[i] != b.e) hullchain.push_back(hull[i]);
      }
    }
  }
  hullchain.push_back(b.e);

  // The reference measures a vertex's deviation from the line of its chord; a vertex beyond the end
  // of the bridge (a needle-shaped pocket) is then dropped although it is deep (§8.4).
  const bool segment = st.settings.options.hull_chain_distance == HullChainDistance::kSegment;
  const std::vector<int> kept = approx(poly, hullchain, 0.75 * tau, segment);
  std::vector<int> own;
  for (std::size_t i = 1; i + 1 < kept.size(); ++i) {
    const int v = hullchain[kept[i]];
    const int o = poly.offset(b.s, v);
    if (pm_kid_end[o]) continue;
    if (dseg(poly.pt[v], ps, pe) >= tau) {
      own.push_back(v);
      st.owner[v] = p;
    }
  }

  // Prominence of own candidates against their neighbours among the pocket's features (§3.3.6-7).
  std::vector<std::pair<int, int>> list;  // (offset, corner)
  auto add = [&](int c) { list.emplace_back(poly.offset(b.s, c), c); };
  add(b.s);
  add(b.e);
  for (int k : kids) {
    add(st.pockets[k].s);
    add(st.pockets[k].e);
  }
  for (int c : from_children) add(c);
  for (int c : own) add(c);
  std::sort(list.begin(), list.end());
  list.erase(std::unique(list.begin(), list.end()), list.end());

  std::vector<int> pms = from_children;
  for (int v : own) {
    const auto it = std::lower_bound(list.begin(), list.end(), std::pair{poly.offset(b.s, v), v});
    if (it == list.begin() || it + 1 == list.end()) continue;
    const int before = (it - 1)->second, after = (it + 1)->second;
    if (dseg(poly.pt[v], poly.pt[before], poly.pt[after]) > tau / 2) pms.push_back(v);
  }
  std::sort(pms.begin(), pms.end(), [&](int x, int y) { return poly.offset(b.s, x) < poly.offset(b.s, y); });
  st.pockets[p].pms = std::move(pms);
}

// Hierarchical concavity (the paper's definition, §3.4): distance to the own bridge plus the
// concavity of the foot point with respect to the enclosing pocket, up to the hull.
double hierarchical_concavity(const PassState& st, const Pt& x, int p) {
  const Pocket& b = st.pockets[p];
  const Pt& ps = st.poly.pt[b.s];
  const Pt& pe = st.poly.pt[b.e];
  const double own = dseg(x, ps, pe);
  if (b.parent < 0) return own;
  return own + hierarchical_concavity(st, project_on_segment(x, ps, pe), b.parent);
}

void add_subtree_bridge_ends(PassState& st, int p) {
  for (int k : st.pockets[p].kids) {
    st.feature[st.pockets[k].s] = 1;
    st.feature[st.pockets[k].e] = 1;
    add_subtree_bridge_ends(st, k);
  }
}

}  // namespace

void analyse_outer(PassState& st) {
  const Poly& poly = st.poly;
  const int n0 = poly.ring_size(0);
  if (n0 <= 3) return;
  const double tau = st.tau();

  std::vector<int> ring0(n0);
  for (int i = 0; i < n0; ++i) ring0[i] = i;
  const std::vector<int> hull = hull_of(poly, ring0);
  std::vector<char> on_hull(n0, 0);
  for (int c : hull) on_hull[c] = 1;
  std::vector<int> h;  // hull corners in ring order (= counter-clockwise hull order)
  for (int c = 0; c < n0; ++c) {
    if (on_hull[c]) h.push_back(c);
  }
  const bool straight = st.settings.options.concavity == ConcavityMeasure::kStraightLine;
  for (std::size_t k = 0; k < h.size() && h.size() >= 2; ++k) {
    const int a = h[k], b = h[(k + 1) % h.size()];
    if (poly.next(a) == b) continue;
    bool deep = false;
    double depth = 0.0;
    for (int c = poly.next(a); c != b; c = poly.next(c)) {
      if (CGAL::orientation(poly.pt[a], poly.pt[b], poly.pt[c]) == CGAL::LEFT_TURN) deep = true;
      depth = std::max(depth, dseg(poly.pt[c], poly.pt[a], poly.pt[b]));
    }
    if (!deep) continue;
    Pocket pocket;
    pocket.s = a;
    pocket.e = b;
    pocket.len = poly.offset(a, b);
    pocket.root = static_cast<int>(st.pockets.size());
    st.roots.push_back(pocket.root);
    st.pockets.push_back(pocket);
    // With straight-line concavity a pocket shallower than tau cannot hold a pocket minimum: its
    // hierarchy only yields features and owners, needed only if the pass has minima at all.
    (straight && depth < tau ? st.shallow_roots : st.deep_roots).push_back(pocket.root);
  }
  for (int r : st.deep_roots) analyse_root(st, r);
}

void analyse_root(PassState& st, int r) {
  const Poly& poly = st.poly;
  if (st.depth < st.settings.max_depth) add_children(st, r);
  collect_minima(st, r);
  const Pocket& root = st.pockets[r];
  for (int v : root.pms) {
    const double c = st.settings.options.concavity == ConcavityMeasure::kHierarchical && st.owner[v] >= 0
                         ? hierarchical_concavity(st, poly.pt[v], st.owner[v])
                         : dseg(poly.pt[v], poly.pt[root.s], poly.pt[root.e]);
    if (c >= st.tau()) {
      st.pm[v] = 1;
      st.concavity[v] = c;
    }
  }
}

void outer_features(PassState& st) {
  const Poly& poly = st.poly;
  const int n0 = poly.ring_size(0);
  const double tau = st.tau();
  for (int r : st.shallow_roots) analyse_root(st, r);
  st.shallow_roots.clear();
  const std::vector<int>& roots = st.roots;

  // §3.6 features of the outer ring.
  std::vector<char> interior(n0, 0);
  for (int r : roots) {
    const Pocket& root = st.pockets[r];
    st.feature[root.s] = st.feature[root.e] = 1;
    for (int v : root.pms) {
      if (st.pm[v]) st.feature[v] = 1;
    }
    add_subtree_bridge_ends(st, r);
    for (int c = poly.next(root.s); c != root.e; c = poly.next(c)) interior[c] = 1;
  }
  for (std::size_t k = 0; k < roots.size(); ++k) {
    const int from = st.pockets[roots[k]].e;
    const int to = st.pockets[roots[(k + 1) % roots.size()]].s;
    std::vector<int> run;
    for (int c = from; c != to; c = poly.next(c)) run.push_back(c);
    if (run.size() <= 2) continue;
    for (int i : approx(poly, run, 0.75 * tau)) st.feature[run[i]] = 1;
  }
}

}  // namespace topocut::dude
