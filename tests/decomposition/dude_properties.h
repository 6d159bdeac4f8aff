#pragma once
// Invariants every decomposition must satisfy (dude-algorithm.md §10), checked with exact predicates.
#include <gtest/gtest.h>

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/cgal_geometry.h"
#include "topocut/decomposition/decompose.h"

namespace topocut::test_props {

using P = cgal::Point;

inline std::vector<P> pts(const Ring& r) {
  std::vector<P> out;
  for (const Point2& p : r) out.push_back(cgal::to_cgal(p));
  return out;
}

// -1 outside, 0 on the boundary, 1 inside (holes subtract).
inline int side(const std::vector<std::vector<P>>& rings, const P& q) {
  int result = 1;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    const auto s = CGAL::bounded_side_2(rings[i].begin(), rings[i].end(), q, cgal::Kernel());
    if (s == CGAL::ON_BOUNDARY) return 0;
    const bool in = s == CGAL::ON_BOUNDED_SIDE;
    if (i == 0 && !in) return -1;
    if (i > 0 && in) result = -1;
  }
  return result;
}

inline std::vector<std::vector<P>> rings_of(const PolygonWithHoles& p) {
  std::vector<std::vector<P>> r{pts(p.outer)};
  for (const Ring& h : p.holes) r.push_back(pts(h));
  return r;
}

// True when segments ab and cd share a point other than a common end point.
inline bool cross(const P& a, const P& b, const P& c, const P& d) {
  const bool shared_a = a == c || a == d, shared_b = b == c || b == d;
  if (shared_a && shared_b) return true;
  if (shared_a || shared_b) {
    const P& s = shared_a ? a : b;
    const P& far = shared_a ? b : a;
    const P& other = (c == s) ? d : c;
    return CGAL::orientation(s, far, other) == CGAL::COLLINEAR && CGAL::angle(other, s, far) == CGAL::ACUTE;
  }
  return CGAL::do_intersect(cgal::Segment(a, b), cgal::Segment(c, d));
}

// Same vertex set (holes are compared as sets: the decomposition may start or orient them differently).
inline bool same_ring(const Ring& a, const Ring& b) {
  std::vector<std::pair<double, double>> x, y;
  for (const Point2& p : a) x.emplace_back(p.x, p.y);
  for (const Point2& p : b) y.emplace_back(p.x, p.y);
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  return x == y;
}

// Shoelace sum relative to the first vertex: exact enough far from the origin, unlike the plain sum.
inline double area_of(const Ring& r) {
  double twice = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point2& p = r[i];
    const Point2& q = r[(i + 1) % r.size()];
    twice += (p.x - r[0].x) * (q.y - r[0].y) - (q.x - r[0].x) * (p.y - r[0].y);
  }
  return 0.5 * twice;
}
inline double area_of(const PolygonWithHoles& p) {
  double a = std::abs(area_of(p.outer));
  for (const Ring& h : p.holes) a -= std::abs(area_of(h));
  return a;
}

// Checks §10.3 (tiling), §10.4 (cut validity), orientation, vertices from the input.
inline void expect_valid(const PolygonWithHoles& input_any, const Decomposition& d, const std::string& what,
                         int samples = 300) {
  PolygonWithHoles input = input_any;  // orientation does not matter below
  SCOPED_TRACE(what);
  // Orientation and areas.
  double total = 0;
  for (const PolygonWithHoles& piece : d.pieces) {
    EXPECT_GT(area_of(piece.outer), 0);
    for (const Ring& h : piece.holes) EXPECT_LT(area_of(h), 0);
    total += area_of(piece);
  }
  double expected = area_of(input);
  for (const Ring& h : d.absorbed_holes) expected += std::abs(area_of(h));
  EXPECT_LT(std::abs(total - expected), 1e-9 * expected) << total << " vs " << expected;

  // Every vertex of a piece or cut is an input vertex.
  std::set<std::pair<double, double>> vertices;
  for (const Point2& p : input.outer) vertices.insert({p.x, p.y});
  for (const Ring& h : input.holes) {
    for (const Point2& p : h) vertices.insert({p.x, p.y});
  }
  for (const PolygonWithHoles& piece : d.pieces) {
    for (const Point2& p : piece.outer) EXPECT_TRUE(vertices.count({p.x, p.y})) << p.x << "," << p.y;
    for (const Ring& h : piece.holes) {
      for (const Point2& p : h) EXPECT_TRUE(vertices.count({p.x, p.y}));
    }
  }

  // Remaining (not absorbed) rings of the input, for the cut checks.
  std::vector<std::vector<P>> kept{pts(input.outer)};
  for (const Ring& h : input.holes) {
    bool absorbed = false;
    for (const Ring& a : d.absorbed_holes) absorbed = absorbed || same_ring(a, h);
    if (!absorbed) kept.push_back(pts(h));
  }
  for (std::size_t i = 0; i < d.cuts.size(); ++i) {
    const Cut& cut = d.cuts[i];
    EXPECT_TRUE(vertices.count({cut.segment.a.x, cut.segment.a.y}));
    EXPECT_TRUE(vertices.count({cut.segment.b.x, cut.segment.b.y}));
    const P a = cgal::to_cgal(cut.segment.a), b = cgal::to_cgal(cut.segment.b);
    EXPECT_NE(a, b);
    bool crosses = false;
    for (const auto& ring : kept) {
      for (std::size_t k = 0; k < ring.size() && !crosses; ++k) {
        crosses = cross(a, b, ring[k], ring[(k + 1) % ring.size()]);
      }
    }
    EXPECT_FALSE(crosses) << "cut " << i << " meets the boundary";
    const P mid((a.x() + b.x()) / 2, (a.y() + b.y()) / 2);
    EXPECT_EQ(side(kept, mid), 1) << "cut " << i << " is not inside";
    for (std::size_t j = 0; j < i; ++j) {
      const P c = cgal::to_cgal(d.cuts[j].segment.a), e = cgal::to_cgal(d.cuts[j].segment.b);
      EXPECT_FALSE(cross(a, b, c, e)) << "cuts " << j << " and " << i << " cross";
    }
  }

  // Sampled points: inside the input (or an absorbed hole) means inside exactly one piece.
  std::vector<std::vector<std::vector<P>>> pieces;
  std::vector<CGAL::Bbox_2> boxes;
  for (const PolygonWithHoles& piece : d.pieces) {
    pieces.push_back(rings_of(piece));
    boxes.push_back(CGAL::bbox_2(pieces.back()[0].begin(), pieces.back()[0].end()));
  }
  const auto in_rings = rings_of(input);
  std::vector<std::vector<P>> absorbed;
  for (const Ring& h : d.absorbed_holes) absorbed.push_back(pts(h));
  const CGAL::Bbox_2 box = CGAL::bbox_2(in_rings[0].begin(), in_rings[0].end());
  std::mt19937 rng(static_cast<unsigned>(input.outer.size() * 7919 + d.pieces.size()));
  std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax());
  int checked = 0;
  for (int s = 0; s < samples; ++s) {
    const P q(ux(rng), uy(rng));
    const int si = side(in_rings, q);
    if (si == 0) continue;
    bool in_absorbed = false;
    bool on = false;
    for (const auto& h : absorbed) {
      const auto bs = CGAL::bounded_side_2(h.begin(), h.end(), q, cgal::Kernel());
      on = on || bs == CGAL::ON_BOUNDARY;
      in_absorbed = in_absorbed || bs == CGAL::ON_BOUNDED_SIDE;
    }
    if (on) continue;
    int count = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (!CGAL::do_overlap(boxes[i], q.bbox())) continue;
      const int sp = side(pieces[i], q);
      if (sp == 0) {
        on = true;
        break;
      }
      count += sp == 1;
    }
    if (on) continue;
    ++checked;
    EXPECT_EQ(count, (si == 1 || in_absorbed) ? 1 : 0) << "sample " << q;
    if (count != ((si == 1 || in_absorbed) ? 1 : 0)) break;
  }
  EXPECT_GT(checked, samples / 4);
}

// Canonical form: pieces as rings starting at their smallest vertex, sorted; cuts as sorted pairs.
struct Canonical {
  std::vector<std::vector<std::vector<std::pair<double, double>>>> pieces;
  std::vector<std::pair<std::pair<double, double>, std::pair<double, double>>> cuts;
  bool operator==(const Canonical&) const = default;
};

template <class F>
Canonical canonical(const Decomposition& d, F back) {
  Canonical c;
  auto ring = [&](const Ring& r) {
    std::vector<std::pair<double, double>> v;
    for (const Point2& p : r) {
      const Point2 q = back(p);
      v.emplace_back(q.x, q.y);
    }
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    return v;
  };
  for (const PolygonWithHoles& p : d.pieces) {
    std::vector<std::vector<std::pair<double, double>>> rings{ring(p.outer)};
    std::vector<std::vector<std::pair<double, double>>> holes;
    for (const Ring& h : p.holes) holes.push_back(ring(h));
    std::sort(holes.begin(), holes.end());
    rings.insert(rings.end(), holes.begin(), holes.end());
    c.pieces.push_back(std::move(rings));
  }
  std::sort(c.pieces.begin(), c.pieces.end());
  for (const Cut& cut : d.cuts) {
    const Point2 a = back(cut.segment.a), b = back(cut.segment.b);
    std::pair<double, double> x{a.x, a.y}, y{b.x, b.y};
    if (y < x) std::swap(x, y);
    c.cuts.push_back({x, y});
  }
  std::sort(c.cuts.begin(), c.cuts.end());
  return c;
}

inline Canonical canonical(const Decomposition& d) {
  return canonical(d, [](const Point2& p) { return p; });
}

inline bool identical(const Decomposition& x, const Decomposition& y) {
  if (x.pieces != y.pieces || x.cuts.size() != y.cuts.size() || x.rounds != y.rounds) return false;
  if (x.absorbed_holes != y.absorbed_holes || x.pocket_minima.size() != y.pocket_minima.size()) return false;
  for (std::size_t i = 0; i < x.cuts.size(); ++i) {
    if (!(x.cuts[i].segment == y.cuts[i].segment) || x.cuts[i].pass != y.cuts[i].pass) return false;
  }
  for (std::size_t i = 0; i < x.pocket_minima.size(); ++i) {
    const auto& a = x.pocket_minima[i];
    const auto& b = y.pocket_minima[i];
    if (!(a.vertex == b.vertex) || a.concavity != b.concavity || a.pass != b.pass || a.on_hole != b.on_hole) return false;
  }
  return true;
}

}  // namespace topocut::test_props
