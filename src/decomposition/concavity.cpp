#include "topocut/decomposition/concavity.h"

#include <algorithm>

#include "decomposition/dude.h"
#include "decomposition/ring_measures.h"
#include "decomposition/validate.h"

namespace topocut {

Concavity measure_concavity(const PolygonWithHoles& polygon) {
  Concavity result;
  dude::Poly poly;
  int vid = 0;
  auto add = [&](const Ring& ring, bool ccw) {
    Ring r = dude::is_counter_clockwise(ring) == ccw ? ring : dude::reversed_keep_first(ring);
    std::vector<dude::Pt> pts;
    std::vector<int> vids;
    for (const Point2& p : r) {
      pts.emplace_back(p.x, p.y);
      vids.push_back(vid++);
    }
    poly.add_ring(pts, vids);
  };
  if (polygon.outer.size() < 3) return result;
  add(polygon.outer, true);
  for (const Ring& hole : polygon.holes) {
    if (hole.size() >= 3) add(hole, false);
  }

  const int n = poly.ring_size(0);
  std::vector<int> ring0(n);
  for (int i = 0; i < n; ++i) ring0[i] = i;
  const std::vector<int> hull = dude::hull_of(poly, ring0);
  std::vector<char> on_hull(n, 0);
  for (int c : hull) on_hull[c] = 1;
  std::vector<int> h;
  for (int c = 0; c < n; ++c) {
    if (on_hull[c]) h.push_back(c);
  }
  for (std::size_t k = 0; k < h.size() && h.size() >= 2; ++k) {
    const int a = h[k], b = h[(k + 1) % h.size()];
    for (int c = poly.next(a); c != b; c = poly.next(c)) {
      result.pocket_depth = std::max(result.pocket_depth, dude::dseg(poly.pt[c], poly.pt[a], poly.pt[b]));
    }
  }
  for (int r = 1; r < poly.rings(); ++r) {
    std::vector<int> ring;
    for (int c = poly.ring_start[r]; c < poly.ring_start[r + 1]; ++c) ring.push_back(c);
    const dude::Diameter d = dude::diameter_of(poly, ring);
    result.hole = std::max(result.hole, std::min(d.length, d.width2));
  }
  return result;
}

}  // namespace topocut
