// Small exact-predicate helpers shared by the DuDe stages.
#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/property_map.h>

#include <algorithm>

#include "decomposition/dude.h"

namespace topocut::dude {

void Poly::add_ring(const std::vector<Pt>& points, const std::vector<int>& vids) {
  if (ring_start.empty()) ring_start.push_back(0);
  const int r = rings();
  pt.insert(pt.end(), points.begin(), points.end());
  vid.insert(vid.end(), vids.begin(), vids.end());
  ring.insert(ring.end(), points.size(), r);
  ring_start.push_back(static_cast<int>(pt.size()));
}

double dseg(const Pt& p, const Pt& a, const Pt& b) {
  const Pt q = project_on_segment(p, a, b);
  return dist(p, q);
}

Pt project_on_segment(const Pt& p, const Pt& a, const Pt& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double len2 = dx * dx + dy * dy;
  if (len2 <= 0.0) return a;
  const double t = ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / len2;
  if (t <= 0.0) return a;
  if (t >= 1.0) return b;
  return Pt(a.x() + t * dx, a.y() + t * dy);
}

double dline(const Pt& p, const Pt& a, const Pt& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double len = std::sqrt(dx * dx + dy * dy);
  if (len <= 0.0) return dist(p, a);
  return std::abs(dx * (p.y() - a.y()) - dy * (p.x() - a.x())) / len;
}

int cw_class(const Pt& v, const Pt& r, const Pt& q) {
  switch (CGAL::orientation(v, r, q)) {
    case CGAL::RIGHT_TURN:
      return 1;
    case CGAL::LEFT_TURN:
      return 3;
    default:
      return CGAL::angle(r, v, q) == CGAL::OBTUSE ? 2 : 0;
  }
}

int cw_compare(const Pt& v, const Pt& r, const Pt& a, const Pt& b) {
  const int ca = cw_class(v, r, a);
  const int cb = cw_class(v, r, b);
  if (ca != cb) return ca < cb ? -1 : 1;
  if (ca == 0 || ca == 2) return 0;
  switch (CGAL::orientation(v, a, b)) {
    case CGAL::RIGHT_TURN:
      return -1;
    case CGAL::LEFT_TURN:
      return 1;
    default:
      return 0;
  }
}

bool in_wedge(const Pt& pred, const Pt& v, const Pt& succ, const Pt& q) {
  if (cw_class(v, pred, q) == 0) return false;
  return cw_compare(v, pred, q, succ) < 0;
}

bool in_wedge(const Poly& poly, int c, const Pt& q) {
  return in_wedge(poly.pt[poly.prev(c)], poly.pt[c], poly.pt[poly.next(c)], q);
}

bool is_reflex(const Poly& poly, int c) {
  return CGAL::orientation(poly.pt[poly.prev(c)], poly.pt[c], poly.pt[poly.next(c)]) != CGAL::LEFT_TURN;
}

std::vector<int> approx(const Poly& poly, const std::vector<int>& chain, double t, bool segment_distance) {
  const int n = static_cast<int>(chain.size());
  std::vector<int> kept;
  if (n <= 2) {
    for (int i = 0; i < n; ++i) kept.push_back(i);
    return kept;
  }
  std::vector<char> keep(n, 0);
  keep[0] = keep[n - 1] = 1;
  std::vector<std::pair<int, int>> stack{{0, n - 1}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (j - i < 2) continue;
    const Pt& a = poly.pt[chain[i]];
    const Pt& b = poly.pt[chain[j]];
    int best = -1;
    double best_d = -1.0;
    for (int k = i + 1; k < j; ++k) {
      const Pt& p = poly.pt[chain[k]];
      const double d = segment_distance ? dseg(p, a, b) : dline(p, a, b);
      if (d >= best_d) {
        best_d = d;
        best = k;
      }
    }
    if (best_d >= t) {
      keep[best] = 1;
      stack.push_back({best, j});
      stack.push_back({i, best});
    }
  }
  for (int i = 0; i < n; ++i) {
    if (keep[i]) kept.push_back(i);
  }
  return kept;
}

std::vector<int> hull_of(const Poly& poly, const std::vector<int>& corners) {
  // Keep the first corner given for each point: sort (vertex id, position) pairs, then filter.
  std::vector<std::pair<int, int>> keyed(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) keyed[i] = {poly.vid[corners[i]], static_cast<int>(i)};
  std::sort(keyed.begin(), keyed.end());
  std::vector<char> keep(corners.size(), 1);
  bool repeats = false;
  for (std::size_t i = 1; i < keyed.size(); ++i) {
    if (keyed[i].first == keyed[i - 1].first) {
      keep[keyed[i].second] = 0;
      repeats = true;
    }
  }
  std::vector<int> unique;
  if (repeats) {
    for (std::size_t i = 0; i < corners.size(); ++i) {
      if (keep[i]) unique.push_back(corners[i]);
    }
  } else {
    unique = corners;
  }
  std::vector<int> hull;
  if (unique.size() < 3) return unique;
  using Map = CGAL::Pointer_property_map<Pt>::const_type;
  using Traits = CGAL::Convex_hull_traits_adapter_2<K, Map>;
  CGAL::convex_hull_2(unique.begin(), unique.end(), std::back_inserter(hull),
                      Traits(CGAL::make_property_map(poly.pt)));
  return hull;
}

double chain_area2(const Poly& poly, int a, int b) {
  const Pt& o = poly.pt[a];
  double twice = 0.0;
  int c = a;
  while (c != b) {
    const int d = poly.next(c);
    const double x1 = poly.pt[c].x() - o.x(), y1 = poly.pt[c].y() - o.y();
    const double x2 = poly.pt[d].x() - o.x(), y2 = poly.pt[d].y() - o.y();
    twice += x1 * y2 - x2 * y1;
    c = d;
  }
  return twice;  // the closing edge b -> a contributes nothing relative to a
}

}  // namespace topocut::dude
