// §7.1 applying the cuts of a pass: the rings plus the cuts form a planar graph whose bounded faces
// are the pieces. Cuts are attached to corners (not points), so keyhole rings with repeated points
// need no special case: at each corner the cuts are ordered clockwise inside its wedge and a face is
// traced by always leaving along the next ray clockwise.
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>

#include "decomposition/dude.h"

namespace topocut::dude {

namespace {

double area2_of(const Poly& poly, const std::vector<int>& cycle) {
  if (cycle.empty()) return 0.0;
  const Pt& o = poly.pt[cycle[0]];
  double twice = 0.0;
  for (std::size_t i = 0; i < cycle.size(); ++i) {
    const Pt& p = poly.pt[cycle[i]];
    const Pt& q = poly.pt[cycle[(i + 1) % cycle.size()]];
    twice += (p.x() - o.x()) * (q.y() - o.y()) - (q.x() - o.x()) * (p.y() - o.y());
  }
  return twice;
}

// The rays leaving each corner: index 0 = predecessor, 1..m = its cuts clockwise, m+1 = successor.
struct CornerRays {
  std::vector<std::vector<int>> at;      // per corner: its cut indices, clockwise inside its wedge
  std::vector<std::pair<int, int>> slot; // per cut: its position in the ray list of either end
  std::vector<int> base;                 // outgoing rays of corner c: base[c] + (1..m+1) - 1
};

int other_end(const std::vector<std::pair<int, int>>& cuts, int cut, int c) {
  return cuts[cut].first == c ? cuts[cut].second : cuts[cut].first;
}

// Cuts are ordered clockwise from the predecessor at each corner (ties by index), so that leaving
// along the next ray clockwise traces a face whatever the keyholes.
CornerRays corner_rays(const Poly& poly, const std::vector<std::pair<int, int>>& cuts) {
  const int n = poly.corners();
  CornerRays rays;
  std::vector<std::vector<int>>& at = rays.at;
  at.resize(n);
  for (int i = 0; i < static_cast<int>(cuts.size()); ++i) {
    at[cuts[i].first].push_back(i);
    at[cuts[i].second].push_back(i);
  }
  for (int c = 0; c < n; ++c) {
    if (at[c].size() < 2) continue;
    const Pt& v = poly.pt[c];
    const Pt& ref = poly.pt[poly.prev(c)];
    std::sort(at[c].begin(), at[c].end(), [&](int x, int y) {
      const int cmp = cw_compare(v, ref, poly.pt[other_end(cuts, x, c)], poly.pt[other_end(cuts, y, c)]);
      return cmp != 0 ? cmp < 0 : x < y;
    });
  }
  rays.slot.resize(cuts.size());
  for (int c = 0; c < n; ++c) {
    for (int k = 0; k < static_cast<int>(at[c].size()); ++k) {
      const int cut = at[c][k];
      (cuts[cut].first == c ? rays.slot[cut].first : rays.slot[cut].second) = k + 1;
    }
  }
  rays.base.assign(n + 1, 0);
  for (int c = 0; c < n; ++c) rays.base[c + 1] = rays.base[c] + static_cast<int>(at[c].size()) + 1;
  return rays;
}

// Every ray of a kept ring is walked once; counter-clockwise cycles are pieces' outer rings,
// clockwise ones holes (zero-area cycles are dropped).
void trace_cycles(const Poly& poly, const std::vector<std::pair<int, int>>& cuts, const CornerRays& rays,
                  const std::vector<char>& deleted, std::vector<std::vector<int>>& outers,
                  std::vector<std::vector<int>>& holes) {
  const int n = poly.corners();
  const std::vector<std::vector<int>>& at = rays.at;
  const std::vector<int>& base = rays.base;
  std::vector<char> used(base[n], 0);
  for (int c0 = 0; c0 < n; ++c0) {
    if (deleted[poly.ring[c0]]) continue;
    for (int k0 = 1; k0 <= static_cast<int>(at[c0].size()) + 1; ++k0) {
      if (used[base[c0] + k0 - 1]) continue;
      std::vector<int> cycle;
      int c = c0, k = k0;
      while (!used[base[c] + k - 1]) {
        used[base[c] + k - 1] = 1;
        cycle.push_back(c);
        const int m = static_cast<int>(at[c].size());
        if (k == m + 1) {
          c = poly.next(c);
          k = 1;
        } else {
          const int cut = at[c][k - 1];
          const int d = other_end(cuts, cut, c);
          const int arrive = cuts[cut].first == d ? rays.slot[cut].first : rays.slot[cut].second;
          c = d;
          k = arrive + 1;
        }
      }
      const double a2 = area2_of(poly, cycle);
      if (a2 > 0) {
        outers.push_back(std::move(cycle));
      } else if (a2 < 0) {
        holes.push_back(std::move(cycle));
      }
    }
  }
}

// Each hole cycle belongs to the outer cycle that contains it: per outer cycle, its holes. A hole
// whose corners all lie on outer boundaries or in no piece is dropped (cannot happen for a valid
// split).
std::vector<std::vector<int>> holes_by_owner(const Poly& poly, const std::vector<std::vector<int>>& outers,
                                             const std::vector<std::vector<int>>& holes) {
  std::vector<std::vector<Pt>> outer_pts(outers.size());
  std::vector<CGAL::Bbox_2> boxes(outers.size());
  for (std::size_t i = 0; i < outers.size(); ++i) {
    for (int c : outers[i]) outer_pts[i].push_back(poly.pt[c]);
    boxes[i] = CGAL::bbox_2(outer_pts[i].begin(), outer_pts[i].end());
  }
  std::vector<std::vector<int>> holes_of(outers.size());
  for (std::size_t h = 0; h < holes.size(); ++h) {
    int owner = outers.size() == 1 ? 0 : -1;
    for (std::size_t j = 0; owner < 0 && j < holes[h].size(); ++j) {
      const Pt& p = poly.pt[holes[h][j]];
      bool on_boundary = false;
      for (std::size_t i = 0; i < outers.size(); ++i) {
        if (!CGAL::do_overlap(boxes[i], p.bbox())) continue;
        const CGAL::Bounded_side side = CGAL::bounded_side_2(outer_pts[i].begin(), outer_pts[i].end(), p, K());
        if (side == CGAL::ON_BOUNDED_SIDE) {
          owner = static_cast<int>(i);
          break;
        }
        if (side == CGAL::ON_BOUNDARY) on_boundary = true;
      }
      if (!on_boundary && owner < 0) break;  // inside no piece: cannot happen for a valid split
    }
    if (owner >= 0) holes_of[owner].push_back(static_cast<int>(h));
  }
  return holes_of;
}

}  // namespace

std::vector<Poly> split(const Poly& poly, const std::vector<std::pair<int, int>>& cuts,
                        const std::vector<int>& deleted_holes) {
  std::vector<char> deleted(poly.rings(), 0);
  for (int h : deleted_holes) deleted[h] = 1;
  const CornerRays rays = corner_rays(poly, cuts);
  std::vector<std::vector<int>> outers, holes;
  trace_cycles(poly, cuts, rays, deleted, outers, holes);
  const std::vector<std::vector<int>> holes_of = holes_by_owner(poly, outers, holes);

  std::vector<Poly> pieces;
  pieces.reserve(outers.size());
  for (std::size_t i = 0; i < outers.size(); ++i) {
    Poly piece;
    auto add = [&](const std::vector<int>& cycle) {
      std::vector<Pt> pts;
      std::vector<int> vids;
      for (int c : cycle) {
        pts.push_back(poly.pt[c]);
        vids.push_back(poly.vid[c]);
      }
      piece.add_ring(pts, vids);
    };
    add(outers[i]);
    for (int h : holes_of[i]) add(holes[h]);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

}  // namespace topocut::dude
