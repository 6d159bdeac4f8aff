#include "topocut/segmentation/polygon_split.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <utility>

#include "topocut/core/error.h"
#include "topocut/core/infinity.h"
#include "segmentation/cuts/edge_grid.h"
#include "segmentation/cuts/plane_vectors.h"

namespace topocut {

using namespace plane;

namespace {

// A polygon's rings as one graph: directed half-edges between distinct vertices.
struct HalfEdge {
  int from, to, twin;
};
struct HalfEdgeGraph {
  std::vector<Point2> vertices;
  std::vector<HalfEdge> half;
  // Per vertex v: its half-edges, in insertion order, are out_edges[out_start[v] .. out_start[v + 1]).
  std::vector<int> out_start, out_edges;
};

// Per point of the sequence, the number of the distinct point it is (points equal when their
// coordinates compare equal), numbered by first appearance; first_points gets each distinct point
// as it first appears. By sorting, not hashing: no allocation per point.
std::vector<int> numbered_by_first_appearance(const std::vector<Point2>& points, std::vector<Point2>& first_points) {
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const Point2& p = points[static_cast<std::size_t>(a)];
    const Point2& q = points[static_cast<std::size_t>(b)];
    return p.x != q.x ? p.x < q.x : p.y < q.y;
  };
  std::stable_sort(order.begin(), order.end(), less);
  std::vector<int> first(points.size());  // per point: the first index of an equal point
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int i = order[k];
    first[static_cast<std::size_t>(i)] = k > 0 && !less(order[k - 1], i) ? first[static_cast<std::size_t>(order[k - 1])] : i;
  }
  std::vector<int> id(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (first[i] == static_cast<int>(i)) {
      id[i] = static_cast<int>(first_points.size());
      first_points.push_back(points[i]);
    } else {
      id[i] = id[static_cast<std::size_t>(first[i])];
    }
  }
  return id;
}

// Far more than the rounding of a distance, far less than a cell: the box tests below never drop an
// edge within a chord end's distance (1e-6) of it.
constexpr double kNearBox = 1e-3;

// The rings' edges, numbered ring by ring in ring order.
std::vector<cut_search::Edge> ring_edges(const std::vector<Ring>& rings) {
  std::vector<cut_search::Edge> edges;
  for (std::size_t r = 0; r < rings.size(); ++r)
    for (std::size_t i = 0; i < rings[r].size(); ++i)
      edges.push_back({rings[r][i], rings[r][(i + 1) % rings[r].size()], static_cast<int>(r), static_cast<int>(i)});
  return edges;
}

// A grid cell for the edges: about a cell per edge, at least 16 map cells a side, so that the grid's
// memory is the polygon's, not its box's.
double edge_cell(const std::vector<cut_search::Edge>& edges) {
  Box all;
  for (const cut_search::Edge& e : edges)
    all = {std::min({all.x0, e.a.x, e.b.x}), std::min({all.y0, e.a.y, e.b.y}), std::max({all.x1, e.a.x, e.b.x}),
           std::max({all.y1, e.a.y, e.b.y})};
  return std::max(16.0, std::sqrt((all.x1 - all.x0) * (all.y1 - all.y0) / static_cast<double>(std::max<std::size_t>(edges.size(), 1))));
}

// The rings with every chord end point that is not a vertex inserted as a vertex of the edge it
// lies on (in order along the edge), so chords meet the rings only at vertices. Throws if a chord
// end lies on no edge.
std::vector<Ring> rings_with_chord_ends(const PolygonWithHoles& polygon, const std::vector<Segment2>& chords) {
  std::vector<Ring> rings{polygon.outer};
  for (const Ring& hole : polygon.holes) rings.push_back(hole);
  // Each edge in the cells its segment passes within kNearBox of: the edges a chord end may lie on.
  const std::vector<cut_search::Edge> edges = ring_edges(rings);
  const cut_search::EdgeGrid grid(edges, edge_cell(edges), kNearBox);
  // The chord ends, sorted, each marked once it is a vertex (of the rings, or inserted below): only
  // these are ever asked about, so the rings' vertices are looked up among them, not all hashed.
  using Key = std::pair<double, double>;
  std::vector<Key> ends;
  for (const Segment2& chord : chords)
    for (const Point2& p : {chord.a, chord.b}) ends.emplace_back(p.x, p.y);
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  std::vector<char> is_vertex(ends.size(), 0);
  auto end_index = [&ends](const Point2& p) -> std::ptrdiff_t {
    const auto it = std::lower_bound(ends.begin(), ends.end(), Key{p.x, p.y});
    return it != ends.end() && *it == Key{p.x, p.y} ? it - ends.begin() : -1;
  };
  for (const Ring& ring : rings)
    for (const Point2& p : ring)
      if (const std::ptrdiff_t at = end_index(p); at >= 0) is_vertex[static_cast<std::size_t>(at)] = 1;
  std::map<std::pair<int, int>, std::vector<std::pair<double, Point2>>> inserts;  // (ring, edge) -> (t, point)
  for (const Segment2& chord : chords) {
    for (const Point2& p : {chord.a, chord.b}) {
      const std::size_t at = static_cast<std::size_t>(end_index(p));  // every chord end is among the ends
      if (is_vertex[at]) continue;
      int best_ring = -1, best_edge = -1;
      double best = 1e-6, best_t = 0.0;
      // The edges near p in ring and edge order, as the scan of every edge met them.
      for (const int id : grid.in_cell(p)) {
        const cut_search::Edge& edge = edges[static_cast<std::size_t>(id)];
        const Segment2 e{edge.a, edge.b};
        // An edge whose box is far from p is not within best of it: skip the exact distance.
        if (p.x < std::min(e.a.x, e.b.x) - kNearBox || p.x > std::max(e.a.x, e.b.x) + kNearBox ||
            p.y < std::min(e.a.y, e.b.y) - kNearBox || p.y > std::max(e.a.y, e.b.y) + kNearBox)
          continue;
        const double d = distance_to_segment(p, e);
        if (d < best) {
          best = d;
          best_ring = edge.ring;
          best_edge = edge.index;
          const Point2 v = minus(e.b, e.a);
          best_t = dot(minus(p, e.a), v) / dot(v, v);
        }
      }
      if (best_ring < 0) throw Error("a cut end point is not on the polygon's boundary");
      inserts[{best_ring, best_edge}].emplace_back(best_t, p);
      is_vertex[at] = 1;
    }
  }
  for (std::size_t r = 0; r < rings.size(); ++r) {
    bool any = false;
    for (const auto& [key, list] : inserts) any = any || key.first == static_cast<int>(r);
    if (!any) continue;
    Ring out;
    for (std::size_t i = 0; i < rings[r].size(); ++i) {
      out.push_back(rings[r][i]);
      const auto it = inserts.find({static_cast<int>(r), static_cast<int>(i)});
      if (it == inserts.end()) continue;
      std::vector<std::pair<double, Point2>> list = it->second;
      std::sort(list.begin(), list.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      for (const auto& [t, p] : list) out.push_back(p);
    }
    rings[r] = std::move(out);
  }
  return rings;
}

// Half-edges: ring edges (free space on their left) and both directions of every chord, with
// vertices numbered by first appearance so that the walk below is deterministic.
HalfEdgeGraph half_edge_graph(const std::vector<Ring>& rings, const std::vector<Segment2>& chords) {
  HalfEdgeGraph g;
  // The points in the order the edges meet them first: the rings' vertices, then the chords' ends.
  std::vector<Point2> points;
  for (const Ring& ring : rings) points.insert(points.end(), ring.begin(), ring.end());
  for (const Segment2& chord : chords) {
    points.push_back(chord.a);
    points.push_back(chord.b);
  }
  const std::vector<int> id = numbered_by_first_appearance(points, g.vertices);
  std::size_t at = 0;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) g.half.push_back({id[at + i], id[at + (i + 1) % ring.size()], -1});
    at += ring.size();
  }
  for (std::size_t j = 0; j < chords.size(); ++j, at += 2) {
    const int a = id[at], b = id[at + 1];
    const int k = static_cast<int>(g.half.size());
    g.half.push_back({a, b, k + 1});
    g.half.push_back({b, a, k});
  }
  g.out_start.assign(g.vertices.size() + 1, 0);
  for (const HalfEdge& h : g.half) ++g.out_start[static_cast<std::size_t>(h.from) + 1];
  for (std::size_t v = 1; v < g.out_start.size(); ++v) g.out_start[v] += g.out_start[v - 1];
  g.out_edges.resize(g.half.size());
  std::vector<int> fill(g.out_start.begin(), g.out_start.end() - 1);
  for (std::size_t k = 0; k < g.half.size(); ++k)
    g.out_edges[static_cast<std::size_t>(fill[static_cast<std::size_t>(g.half[k].from)]++)] = static_cast<int>(k);
  return g;
}

// The faces on the left of the half-edges, each half-edge in exactly one: cycles of half-edge
// indices. Throws if a walk does not close (a cut leaves the polygon).
std::vector<std::vector<int>> face_cycles(const HalfEdgeGraph& g) {
  // At each vertex leave along the edge that turns most to the left (never straight back along
  // the chord just walked, unless it is the only way on).
  auto next_of = [&](int k) {
    const HalfEdge& h = g.half[static_cast<std::size_t>(k)];
    int best = -1;
    double best_turn = -kInfinity;
    for (int e = g.out_start[static_cast<std::size_t>(h.to)]; e < g.out_start[static_cast<std::size_t>(h.to) + 1]; ++e) {
      const int o = g.out_edges[static_cast<std::size_t>(e)];
      if (o == h.twin) continue;
      const double t = turn_angle(g.vertices[static_cast<std::size_t>(h.from)], g.vertices[static_cast<std::size_t>(h.to)],
                                  g.vertices[static_cast<std::size_t>(g.half[static_cast<std::size_t>(o)].to)]);
      if (t > best_turn) {
        best_turn = t;
        best = o;
      }
    }
    return best >= 0 ? best : h.twin;
  };
  std::vector<std::vector<int>> cycles;
  std::vector<bool> used(g.half.size(), false);
  for (std::size_t start = 0; start < g.half.size(); ++start) {
    if (used[start]) continue;
    std::vector<int> cycle;
    int k = static_cast<int>(start);
    while (k >= 0 && !used[static_cast<std::size_t>(k)]) {
      used[static_cast<std::size_t>(k)] = true;
      cycle.push_back(k);
      k = next_of(k);
    }
    if (k != static_cast<int>(start)) throw Error("the cuts do not split the polygon into faces (a cut leaves the polygon?)");
    cycles.push_back(std::move(cycle));
  }
  return cycles;
}

// Per chord (in the graph's order, after the ring edges): does it separate two faces? A chord
// between two rings that no other chord completes has the same face on both of its sides.
std::vector<bool> chords_separating(const HalfEdgeGraph& g, const std::vector<std::vector<int>>& cycles, std::size_t chords) {
  std::vector<int> face(g.half.size(), -1);
  for (std::size_t f = 0; f < cycles.size(); ++f)
    for (const int k : cycles[f]) face[static_cast<std::size_t>(k)] = static_cast<int>(f);
  const std::size_t first = g.half.size() - 2 * chords;
  std::vector<bool> separating(chords);
  for (std::size_t j = 0; j < chords; ++j) separating[j] = face[first + 2 * j] != face[first + 2 * j + 1];
  return separating;
}

// The faces as rings: counter-clockwise cycles are the parts' outer rings, clockwise ones their
// holes.
void trace_faces(const HalfEdgeGraph& g, const std::vector<std::vector<int>>& cycles, std::vector<Ring>& outers,
                 std::vector<Ring>& holes) {
  for (const std::vector<int>& ks : cycles) {
    Ring cycle;
    for (const int k : ks) cycle.push_back(g.vertices[static_cast<std::size_t>(g.half[static_cast<std::size_t>(k)].from)]);
    const double a = signed_area(cycle);
    if (a > 0.0) {
      outers.push_back(std::move(cycle));
    } else if (a < 0.0) {
      holes.push_back(std::move(cycle));
    }
  }
}

// The parts' outer rings by their boxes in a uniform grid (about one cell a part): the parts whose
// box holds a point, in the order of the parts, without looking at every part.
class PartBoxes {
 public:
  explicit PartBoxes(const std::vector<PolygonWithHoles>& parts) {
    for (const PolygonWithHoles& part : parts) boxes_.push_back(bounding_box(part.outer));
    if (boxes_.empty()) return;
    all_ = boxes_.front();
    for (const Box& b : boxes_) all_ = {std::min(all_.x0, b.x0), std::min(all_.y0, b.y0), std::max(all_.x1, b.x1), std::max(all_.y1, b.y1)};
    side_ = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(boxes_.size())))));
    cell_w_ = std::max((all_.x1 - all_.x0) / side_, 1e-9);
    cell_h_ = std::max((all_.y1 - all_.y0) / side_, 1e-9);
    cells_.resize(static_cast<std::size_t>(side_) * side_);
    for (std::size_t i = 0; i < boxes_.size(); ++i)
      for (int y = row(boxes_[i].y0); y <= row(boxes_[i].y1); ++y)
        for (int x = column(boxes_[i].x0); x <= column(boxes_[i].x1); ++x)
          cells_[static_cast<std::size_t>(y) * side_ + x].push_back(static_cast<int>(i));
  }

  // The parts whose box holds p, in ascending order.
  std::vector<int> holding(const Point2& p) const {
    std::vector<int> out;
    if (boxes_.empty() || p.x < all_.x0 || p.x > all_.x1 || p.y < all_.y0 || p.y > all_.y1) return out;
    for (const int i : cells_[static_cast<std::size_t>(row(p.y)) * side_ + column(p.x)]) {
      const Box& b = boxes_[static_cast<std::size_t>(i)];
      if (p.x >= b.x0 && p.x <= b.x1 && p.y >= b.y0 && p.y <= b.y1) out.push_back(i);
    }
    return out;
  }

 private:
  int column(double x) const { return std::clamp(static_cast<int>(std::floor((x - all_.x0) / cell_w_)), 0, side_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>(std::floor((y - all_.y0) / cell_h_)), 0, side_ - 1); }

  std::vector<Box> boxes_;
  Box all_{};
  int side_ = 1;
  double cell_w_ = 1.0, cell_h_ = 1.0;
  std::vector<std::vector<int>> cells_;
};

// Every hole goes to the smallest part whose outer ring contains a point just left of the hole's
// first edge: the part that owns it, even when parts nest. Only the parts whose box holds the point
// can contain it.
std::vector<PolygonWithHoles> parts_with_holes(std::vector<Ring>& outers, std::vector<Ring>& holes) {
  std::vector<PolygonWithHoles> parts;
  for (Ring& outer : outers) parts.push_back({std::move(outer), {}});
  const PartBoxes boxes(parts);
  for (Ring& hole : holes) {
    const Point2 d = minus(hole[1], hole[0]);
    const double l = length(d);
    const double e = 1e-4 * std::min(1.0, l);
    const Point2 p{(hole[0].x + hole[1].x) / 2.0 - d.y / l * e, (hole[0].y + hole[1].y) / 2.0 + d.x / l * e};
    int owner = -1;
    double owner_area = kInfinity;
    for (const int k : boxes.holding(p)) {
      const std::size_t i = static_cast<std::size_t>(k);
      if (!in_ring(parts[i].outer, p)) continue;
      const double a = signed_area(parts[i].outer);
      if (a < owner_area) {
        owner_area = a;
        owner = static_cast<int>(i);
      }
    }
    if (owner < 0) throw Error("internal: a hole outside every part after splitting");
    parts[static_cast<std::size_t>(owner)].holes.push_back(std::move(hole));
  }
  return parts;
}

std::vector<Segment2> only_separating(const std::vector<Segment2>& chords, const std::vector<bool>& separating) {
  std::vector<Segment2> out;
  for (std::size_t j = 0; j < chords.size(); ++j)
    if (separating[j]) out.push_back(chords[j]);
  return out;
}

}  // namespace

std::vector<Segment2> separating_chords(const PolygonWithHoles& polygon, const std::vector<Segment2>& chords) {
  if (chords.empty()) return {};
  const HalfEdgeGraph graph = half_edge_graph(rings_with_chord_ends(polygon, chords), chords);
  return only_separating(chords, chords_separating(graph, face_cycles(graph), chords.size()));
}

std::vector<PolygonWithHoles> split_polygon(const PolygonWithHoles& polygon, const std::vector<Segment2>& chords) {
  if (chords.empty()) return {polygon};
  HalfEdgeGraph graph = half_edge_graph(rings_with_chord_ends(polygon, chords), chords);
  std::vector<std::vector<int>> cycles = face_cycles(graph);
  const std::vector<bool> separating = chords_separating(graph, cycles, chords.size());
  if (std::find(separating.begin(), separating.end(), false) != separating.end()) {
    // A lone chord between two rings would leave a part touching itself along it: drop it.
    const std::vector<Segment2> kept = only_separating(chords, separating);
    if (kept.empty()) return {polygon};
    graph = half_edge_graph(rings_with_chord_ends(polygon, kept), kept);
    cycles = face_cycles(graph);
  }
  std::vector<Ring> outers, holes;
  trace_faces(graph, cycles, outers, holes);
  return parts_with_holes(outers, holes);
}

}  // namespace topocut
