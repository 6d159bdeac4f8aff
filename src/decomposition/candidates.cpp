// §5: features, the simplified polygon and candidate diagonals from two constrained Delaunay
// triangulations; plus the exact "segment strictly inside" test used to validate cuts.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "decomposition/pass_state.h"

namespace topocut::dude {

namespace {

struct VInfo {
  int id = -1;  // local point id; -1 for points CGAL creates at constraint crossings
};
struct FInfo {
  int level = -1;  // nesting level; odd = inside the polygon
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VInfo, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Face = CDT::Face_handle;
using Vertex = CDT::Vertex_handle;

std::uint64_t pair_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// Distinct points of a set of corners: local id per point, the corners of each point.
struct PointSet {
  std::vector<int> local;   // per corner of the poly: local point id or -1
  std::vector<Pt> points;   // per local id
  std::vector<int> first;   // per local id: its first corner (ascending corner order)
  std::vector<int> next;    // per corner: the next corner of the same point, or -1

  PointSet(const Poly& poly, const std::vector<int>& selected) : local(poly.corners(), -1), next(poly.corners(), -1) {
    // Corners of one point are found by sorting on the vertex id (no hashing, no per-point lists).
    std::vector<int> order(selected);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return poly.vid[a] != poly.vid[b] ? poly.vid[a] < poly.vid[b] : a < b;
    });
    points.reserve(order.size());
    first.reserve(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
      const int c = order[i];
      if (i > 0 && poly.vid[order[i - 1]] == poly.vid[c]) {
        local[c] = local[order[i - 1]];
        next[order[i - 1]] = c;
      } else {
        local[c] = static_cast<int>(points.size());
        points.push_back(poly.pt[c]);
        first.push_back(c);
      }
    }
  }
};

// Builds a CDT with one vertex per local point; returns the handle of each local id.
std::vector<Vertex> insert_points(CDT& cdt, const PointSet& set) {
  std::vector<std::pair<Pt, VInfo>> input;
  input.reserve(set.points.size());
  for (std::size_t i = 0; i < set.points.size(); ++i) input.emplace_back(set.points[i], VInfo{static_cast<int>(i)});
  cdt.insert(input.begin(), input.end());
  std::vector<Vertex> handle(set.points.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info().id >= 0) handle[v->info().id] = v;
  }
  for (std::size_t i = 0; i < handle.size(); ++i) {
    if (handle[i] == Vertex()) handle[i] = cdt.insert(set.points[i]);  // coincident point: share the vertex
  }
  return handle;
}

// Nesting levels by flood fill from the infinite face (CGAL's polygon_triangulation example
// pattern); crossing an edge for which `boundary` is false keeps the level.
template <class IsBoundary>
void mark_levels(CDT& cdt, IsBoundary boundary) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().level = -1;
  std::deque<std::pair<Face, int>> border{{cdt.infinite_face(), 0}};
  std::vector<Face> stack;
  while (!border.empty()) {
    const auto [start, level] = border.front();
    border.pop_front();
    if (start->info().level != -1) continue;
    start->info().level = level;
    stack.push_back(start);
    while (!stack.empty()) {
      const Face f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const Face n = f->neighbor(i);
        if (n->info().level != -1) continue;
        if (boundary(f, i)) {
          border.emplace_back(n, level + 1);
        } else {
          n->info().level = level;
          stack.push_back(n);
        }
      }
    }
  }
}

bool inside_face(const CDT& cdt, Face f) { return !cdt.is_infinite(f) && f->info().level % 2 == 1; }

// Each point's degree (edges to other points of the set), counted when first asked: what
// free_segment() asks about for the few segments it tests. CGAL's own edge test circulates around
// either end, which is quadratic when many segments start at a vertex of high degree (the base
// corners of a comb); circulating around the end of lower degree is not, and hashing every edge of
// the triangulation for a few questions costs an allocation per edge.
class VertexDegrees {
 public:
  explicit VertexDegrees(std::size_t points) : degree_(points, -1) {}

  int of(const CDT& cdt, Vertex v) {
    int& d = degree_[static_cast<std::size_t>(v->info().id)];
    if (d < 0) {
      d = 0;
      auto n = cdt.incident_vertices(v), done = n;
      do {
        if (!cdt.is_infinite(n) && n->info().id >= 0) ++d;
      } while (++n != done);
    }
    return d;
  }

 private:
  std::vector<int> degree_;
};

// The edge va-vb of the triangulation, found around va; false if there is none.
bool find_edge(const CDT& cdt, Vertex va, Vertex vb, CDT::Edge& edge) {
  auto fc = cdt.incident_faces(va), done = fc;
  do {
    const int k = fc->index(va);
    if (fc->vertex(CDT::ccw(k)) == vb) {
      edge = CDT::Edge(fc, CDT::cw(k));
      return true;
    }
  } while (++fc != done);
  return false;
}

// True when the segment between two vertices crosses no constrained edge and passes through no
// other vertex: a walk through the triangles it crosses, with exact orientation tests. The walk
// starts at the end of lower degree (the answer does not depend on the direction).
bool free_segment(const CDT& cdt, VertexDegrees& degrees, Vertex va, Vertex vb) {
  if (degrees.of(cdt, va) > degrees.of(cdt, vb)) std::swap(va, vb);
  if (CDT::Edge edge; find_edge(cdt, va, vb, edge)) return !cdt.is_constrained(edge);
  const Pt& a = va->point();
  const Pt& b = vb->point();
  // The triangle at va whose angle contains the direction to b: (va, right, left) counter-clockwise.
  Face f;
  Vertex right, left;
  auto fc = cdt.incident_faces(va), done = fc;
  do {
    if (!cdt.is_infinite(fc)) {
      const int k = fc->index(va);
      const Vertex p = fc->vertex(CDT::ccw(k)), q = fc->vertex(CDT::cw(k));
      const CGAL::Orientation op = CGAL::orientation(a, p->point(), b);
      const CGAL::Orientation oq = CGAL::orientation(a, q->point(), b);
      if (op == CGAL::COLLINEAR && CGAL::angle(p->point(), a, b) == CGAL::ACUTE) return false;  // through p
      if (oq == CGAL::COLLINEAR && CGAL::angle(q->point(), a, b) == CGAL::ACUTE) return false;  // through q
      if (op == CGAL::LEFT_TURN && oq == CGAL::RIGHT_TURN) {
        f = fc;
        right = p;
        left = q;
        break;
      }
    }
  } while (++fc != done);
  if (f == Face()) return false;
  Vertex third = va;
  // number_of_faces() circulates around the infinite vertex: asked once, not per step, since the
  // hull of a comb holds every tooth and the walk would grow quadratic.
  const std::size_t max_steps = cdt.number_of_faces();
  for (std::size_t steps = 0; steps <= max_steps; ++steps) {
    const int k = f->index(third);
    if (cdt.is_constrained(CDT::Edge(f, k))) return false;
    const Face g = f->neighbor(k);
    const Vertex r = g->vertex(cdt.mirror_index(f, k));
    if (r == vb) return true;
    if (cdt.is_infinite(r)) return false;
    switch (CGAL::orientation(a, b, r->point())) {
      case CGAL::RIGHT_TURN:
        third = right;
        right = r;
        break;
      case CGAL::LEFT_TURN:
        third = left;
        left = r;
        break;
      default:
        return false;  // through r
    }
    f = g;
  }
  return false;
}


// Whether segments a-b and c-d (corner pairs of poly) cannot both stand: the same segment, one
// running along the other from a shared end point, or any other contact (touching included).
// Exact predicates on the corners' points, shared end points by vertex id. Not door_cuts'
// segments_conflict, which is floating point on loose points and lets two segments with a shared
// end point overlap: using either for the other would change results.
bool segments_conflict(const Poly& poly, int a, int b, int c, int d) {
  const int va = poly.vid[a], vb = poly.vid[b], vc = poly.vid[c], vd = poly.vid[d];
  const bool c_shared = vc == va || vc == vb;
  const bool d_shared = vd == va || vd == vb;
  if (c_shared && d_shared) return true;
  if (c_shared || d_shared) {
    const Pt& s = c_shared ? poly.pt[c] : poly.pt[d];
    const Pt& other = c_shared ? poly.pt[d] : poly.pt[c];
    const Pt& far = (c_shared ? vc : vd) == va ? poly.pt[b] : poly.pt[a];
    return CGAL::orientation(s, far, other) == CGAL::COLLINEAR && CGAL::angle(other, s, far) == CGAL::ACUTE;
  }
  return CGAL::do_intersect(K::Segment_2(poly.pt[a], poly.pt[b]), K::Segment_2(poly.pt[c], poly.pt[d]));
}

}  // namespace

std::vector<char> segments_inside(const Poly& poly, const std::vector<std::pair<int, int>>& segments,
                                  const std::vector<char>& deleted_rings) {
  std::vector<char> ok(segments.size(), 1);
  if (segments.empty()) return ok;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto [a, b] = segments[i];
    if (poly.vid[a] == poly.vid[b] || !in_wedge(poly, a, poly.pt[b]) || !in_wedge(poly, b, poly.pt[a])) ok[i] = 0;
  }
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, int>;
  std::vector<Box> seg_boxes, edge_boxes;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (!ok[i]) continue;
    const auto [a, b] = segments[i];
    seg_boxes.emplace_back(poly.pt[a].bbox() + poly.pt[b].bbox(), static_cast<int>(i));
  }
  for (int c = 0; c < poly.corners(); ++c) {
    if (deleted_rings[poly.ring[c]]) continue;
    edge_boxes.emplace_back(poly.pt[c].bbox() + poly.pt[poly.next(c)].bbox(), c);
  }
  auto test = [&](const Box& sb, const Box& eb) {
    const int i = sb.info();
    if (!ok[i]) return;
    const auto [a, b] = segments[i];
    const int c = eb.info();
    // Sharing both end points with a boundary edge, the segment is that edge.
    if (segments_conflict(poly, a, b, c, poly.next(c))) ok[i] = 0;
  };
  CGAL::box_intersection_d(seg_boxes.begin(), seg_boxes.end(), edge_boxes.begin(), edge_boxes.end(), test);
  return ok;
}

std::vector<char> non_crossing_prefix(const Poly& poly, const std::vector<std::pair<int, int>>& segments) {
  std::vector<char> keep(segments.size(), 1);
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, int>;
  std::vector<Box> boxes;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    boxes.emplace_back(poly.pt[segments[i].first].bbox() + poly.pt[segments[i].second].bbox(), static_cast<int>(i));
  }
  std::vector<std::vector<int>> earlier(segments.size());
  auto test = [&](const Box& x, const Box& y) {
    int i = x.info(), j = y.info();
    if (i > j) std::swap(i, j);
    const auto [a, b] = segments[i];
    const auto [c, d] = segments[j];
    if (segments_conflict(poly, a, b, c, d)) earlier[j].push_back(i);
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), test);
  for (std::size_t j = 0; j < segments.size(); ++j) {
    for (int i : earlier[j]) {
      if (keep[i]) keep[j] = 0;
    }
  }
  return keep;
}

namespace {

using CornerPairs = std::vector<std::pair<int, int>>;

// §5.3 bridge-breaking test: a cut must involve some concavity and must leave its pocket.
bool bridge_breaking(const PassState& st, int a, int b) {
  const int pa = st.owner[a], pb = st.owner[b], ha = st.hole_owner[a], hb = st.hole_owner[b];
  if (pa < 0 && pb < 0 && ha < 0 && hb < 0) return false;
  if (pa == pb && ha == hb) return false;
  if (pa >= 0 && pb < 0 && st.on_chain(pa, b)) return false;
  if (pb >= 0 && pa < 0 && st.on_chain(pb, a)) return false;
  return true;
}

// §5.3 hole-span test: a diagonal from a hole feature must not end on one of its simplified edges.
bool hole_span_ok(const PassState& st, int a, int b) {
  int f = -1, other = -1;
  if (st.hole_owner[a] >= 0) {
    f = a;
    other = b;
  } else if (st.hole_owner[b] >= 0) {
    f = b;
    other = a;
  } else {
    return true;
  }
  if (st.dpre[f] < 0 || st.poly.ring[other] != st.poly.ring[f]) return true;
  for (int c = f;; c = st.poly.prev(c)) {
    if (c == other) return false;
    if (c == st.dpre[f]) break;
  }
  for (int c = f;; c = st.poly.next(c)) {
    if (c == other) return false;
    if (c == st.dnext[f]) break;
  }
  return true;
}

// §5.3: both tests a candidate diagonal must pass.
bool acceptable(const PassState& st, int a, int b) { return bridge_breaking(st, a, b) && hole_span_ok(st, a, b); }

// The corner of local point `lp` whose interior wedge contains the direction to q, or -1.
int corner_toward(const Poly& poly, const PointSet& set, int lp, const Pt& q) {
  const int c0 = set.first[lp];
  if (set.next[c0] < 0) return in_wedge(poly, c0, q) ? c0 : -1;
  for (int c = c0; c >= 0; c = set.next[c]) {
    if (in_wedge(poly, c, q)) return c;
  }
  return -1;
}

// The unconstrained edges of a triangulation with both faces inside, by local point ids: the
// candidate diagonals before they are tied to corners.
template <class Triangulation>
CornerPairs inside_edges(const Triangulation& cdt) {
  CornerPairs edges;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    const Face f = e->first;
    const int i = e->second;
    if (cdt.is_constrained(*e)) continue;
    if (!inside_face(cdt, f) || !inside_face(cdt, f->neighbor(i))) continue;
    const int u = f->vertex(CDT::cw(i))->info().id, w = f->vertex(CDT::ccw(i))->info().id;
    if (u >= 0 && w >= 0) edges.emplace_back(u, w);
  }
  return edges;
}

// The reference's second triangulation (§5.2.2): all simplified-polygon diagonals are constraints,
// including those that cross the boundary, for which CGAL inserts crossing points. Those points
// change the triangulation nearby (this is how the reference loses the cut of §8.5.1). The
// constraint hierarchy tells boundary sub-edges from diagonal sub-edges for the inside test.
CornerPairs reference_fine_edges(const Poly& poly, const PointSet& set, const std::vector<int>& corners,
                                 const CornerPairs& s_diagonals) {
  using CDTP = CGAL::Constrained_triangulation_plus_2<CDT>;
  CDTP cdt;
  std::vector<Vertex> handle(set.points.size());
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    handle[i] = cdt.insert(set.points[i]);
    if (handle[i]->info().id < 0) handle[i]->info().id = static_cast<int>(i);
  }
  for (int c : corners) {
    const Vertex va = handle[set.local[c]], vb = handle[set.local[poly.next(c)]];
    if (va != vb) cdt.insert_constraint(va, vb);
  }
  std::set<CDTP::Constraint_id> diagonal_ids;
  for (const auto& [a, b] : s_diagonals) {
    diagonal_ids.insert(cdt.insert_constraint(handle[set.local[a]], handle[set.local[b]]));
  }
  mark_levels(cdt, [&](Face f, int i) {
    if (!cdt.is_constrained(CDT::Edge(f, i))) return false;
    const Vertex u = f->vertex(CDT::cw(i)), w = f->vertex(CDT::ccw(i));
    for (auto it = cdt.contexts_begin(u, w); it != cdt.contexts_end(u, w); ++it) {
      if (diagonal_ids.count(it->id()) == 0) return true;
    }
    return false;
  });
  return inside_edges(cdt);
}

// §5.1 simplified polygon: the features of each ring kept, linked by dpre/dnext (in st); a ring
// with fewer than 3 features is dropped from it, its features linked to their plain neighbours.
struct SimplifiedPolygon {
  std::vector<int> feature_corners;  // of rings kept
  CornerPairs edges;                 // feature -> next feature
};

SimplifiedPolygon simplified_polygon(PassState& st) {
  const Poly& poly = st.poly;
  SimplifiedPolygon s;
  for (int r = 0; r < poly.rings(); ++r) {
    if (st.deleted[r]) continue;
    std::vector<int> f;
    for (int c = poly.ring_start[r]; c < poly.ring_start[r + 1]; ++c) {
      if (st.feature[c]) f.push_back(c);
    }
    if (f.size() < 3) {
      for (int c : f) {
        st.dpre[c] = poly.prev(c);
        st.dnext[c] = poly.next(c);
      }
      continue;
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      const int c = f[i];
      st.dpre[c] = f[(i + f.size() - 1) % f.size()];
      st.dnext[c] = f[(i + 1) % f.size()];
      s.feature_corners.push_back(c);
      s.edges.emplace_back(c, st.dnext[c]);
    }
  }
  return s;
}

// Step 1: the accepted diagonals of the simplified polygon's triangulation, one per vertex pair,
// sorted. They need not lie inside the full polygon (step 2 checks).
CornerPairs simplified_diagonals(const PassState& st, const SimplifiedPolygon& simplified, bool reference) {
  const Poly& poly = st.poly;
  CornerPairs s_diagonals;
  if (simplified.feature_corners.empty()) return s_diagonals;
  PointSet set(poly, simplified.feature_corners);
  CDT cdt;
  const std::vector<Vertex> handle = insert_points(cdt, set);
  for (const auto& [a, b] : simplified.edges) {
    const Vertex va = handle[set.local[a]], vb = handle[set.local[b]];
    if (va != vb) cdt.insert_constraint(va, vb);
  }
  mark_levels(cdt, [&](Face f, int i) { return cdt.is_constrained(CDT::Edge(f, i)); });
  std::unordered_set<std::uint64_t> seen;
  for (const auto& [u, w] : inside_edges(cdt)) {
    int a = corner_toward(poly, set, u, set.points[w]);
    int b = corner_toward(poly, set, w, set.points[u]);
    if (reference) {
      // The reference stores the diagonal with the feature vertices whatever the real boundary does.
      if (a < 0) a = set.first[u];
      if (b < 0) b = set.first[w];
    }
    if (a < 0 || b < 0) continue;
    if (a > b) std::swap(a, b);
    if (!acceptable(st, a, b)) continue;
    if (seen.insert(pair_key(poly.vid[a], poly.vid[b])).second) s_diagonals.emplace_back(a, b);
  }
  std::sort(s_diagonals.begin(), s_diagonals.end());
  return s_diagonals;
}

// The full-resolution polygon (rings not deleted), triangulated with its boundary as constraints.
struct FullTriangulation {
  std::vector<int> all_corners;
  PointSet set;
  CDT cdt;
  std::vector<Vertex> handle;  // per local point id

  FullTriangulation(const Poly& poly, const std::vector<char>& deleted)
      : all_corners(kept_corners(poly, deleted)), set(poly, all_corners), handle(insert_points(cdt, set)) {
    for (int c : all_corners) {
      const Vertex va = handle[set.local[c]], vb = handle[set.local[poly.next(c)]];
      if (va != vb) cdt.insert_constraint(va, vb);
    }
  }

  static std::vector<int> kept_corners(const Poly& poly, const std::vector<char>& deleted) {
    std::vector<int> corners;
    corners.reserve(poly.corners());
    for (int c = 0; c < poly.corners(); ++c) {
      if (!deleted[poly.ring[c]]) corners.push_back(c);
    }
    return corners;
  }
};

// Step 2 check: the simplified diagonals that lie inside the full polygon (valid), and, in
// reference mode only, the others (kept by the reference as unchecked constraints).
struct CheckedDiagonals {
  CornerPairs valid, invalid;
};

CheckedDiagonals check_inside(const Poly& poly, const FullTriangulation& full, const CornerPairs& s_diagonals,
                              bool reference) {
  const PointSet& set = full.set;
  std::vector<char> s_valid(s_diagonals.size(), 0);
  VertexDegrees degrees(set.points.size());
  for (std::size_t i = 0; i < s_diagonals.size(); ++i) {
    const auto [a, b] = s_diagonals[i];
    s_valid[i] = poly.vid[a] != poly.vid[b] && in_wedge(poly, a, poly.pt[b]) && in_wedge(poly, b, poly.pt[a]) &&
                 free_segment(full.cdt, degrees, full.handle[set.local[a]], full.handle[set.local[b]]);
  }
  CheckedDiagonals checked;
  for (std::size_t i = 0; i < s_diagonals.size(); ++i) {
    if (s_valid[i]) {
      checked.valid.push_back(s_diagonals[i]);
    } else if (reference) {
      checked.invalid.push_back(s_diagonals[i]);
    }
  }
  return checked;
}

// Step 2 triangulation: the valid simplified diagonals become constraints of the full polygon's
// triangulation, and its inside edges (local point ids) are the fine candidates; with unchecked
// diagonals, the reference's own triangulation instead.
CornerPairs fine_edges(const Poly& poly, FullTriangulation& full, const CheckedDiagonals& checked,
                       const CornerPairs& s_diagonals) {
  if (!checked.invalid.empty()) return reference_fine_edges(poly, full.set, full.all_corners, s_diagonals);
  CDT& cdt = full.cdt;
  std::unordered_set<std::uint64_t> constraint_diagonals;
  for (const auto& [a, b] : checked.valid) {
    cdt.insert_constraint(full.handle[full.set.local[a]], full.handle[full.set.local[b]]);
    constraint_diagonals.insert(pair_key(full.set.local[a], full.set.local[b]));
  }
  mark_levels(cdt, [&](Face f, int i) {
    if (!cdt.is_constrained(CDT::Edge(f, i))) return false;
    const int u = f->vertex(CDT::cw(i))->info().id, w = f->vertex(CDT::ccw(i))->info().id;
    return constraint_diagonals.count(pair_key(u, w)) == 0;
  });
  return inside_edges(cdt);
}

// The final list: valid simplified diagonals, then (reference) the unchecked ones with the fine
// diagonals that cross none of them, then the other fine diagonals, one per vertex pair, sorted.
CornerPairs merged_diagonals(const Poly& poly, const CheckedDiagonals& checked, CornerPairs fine) {
  CornerPairs result;
  std::unordered_set<std::uint64_t> diagonal_keys;
  for (const auto& d : checked.valid) {
    result.push_back(d);
    diagonal_keys.insert(pair_key(poly.vid[d.first], poly.vid[d.second]));
  }
  const CornerPairs& invalid_s = checked.invalid;
  if (!invalid_s.empty()) {
    // The reference has its unchecked diagonals as constraints here, so nothing may cross them.
    CornerPairs both = invalid_s;
    both.insert(both.end(), fine.begin(), fine.end());
    const std::vector<char> keep = non_crossing_prefix(poly, both);
    CornerPairs kept;
    for (std::size_t i = invalid_s.size(); i < both.size(); ++i) {
      if (keep[i]) kept.push_back(both[i]);
    }
    fine.swap(kept);
    for (const auto& d : invalid_s) {
      result.push_back(d);
      diagonal_keys.insert(pair_key(poly.vid[d.first], poly.vid[d.second]));
    }
  }
  for (const auto& d : fine) {
    if (diagonal_keys.insert(pair_key(poly.vid[d.first], poly.vid[d.second])).second) result.push_back(d);
  }
  std::sort(result.begin(), result.end());
  return result;
}

}  // namespace

std::vector<std::pair<int, int>> candidate_diagonals(PassState& st) {
  const Poly& poly = st.poly;
  const bool reference = st.settings.options.candidates == CandidateCuts::kReference;
  const SimplifiedPolygon simplified = simplified_polygon(st);
  const CornerPairs s_diagonals = simplified_diagonals(st, simplified, reference);

  FullTriangulation full(poly, st.deleted);
  const CheckedDiagonals checked = check_inside(poly, full, s_diagonals, reference);
  CornerPairs fine;
  for (const auto& [u, w] : fine_edges(poly, full, checked, s_diagonals)) {
    int a = corner_toward(poly, full.set, u, full.set.points[w]);
    int b = corner_toward(poly, full.set, w, full.set.points[u]);
    if (a < 0 || b < 0) continue;
    if (a > b) std::swap(a, b);
    if (!acceptable(st, a, b)) continue;
    fine.emplace_back(a, b);
  }
  return merged_diagonals(poly, checked, std::move(fine));
}

}  // namespace topocut::dude
