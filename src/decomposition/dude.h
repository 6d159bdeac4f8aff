#pragma once
// Internals of the dual-space decomposition (see ../shared/design/dude-algorithm.md, cited as §n).
//
// Everything works on *corners*: a polygon is a list of rings, each a cyclic list of corners, and a
// corner is one visit of the boundary to a point. After a cut merges a hole into the outer ring the
// ring visits the cut's end points twice (a keyhole), so one point may own several corners; vertex
// ids (`vid`, the index of the input vertex) name points, corner indices name visits. Decisions are
// made on indices and exact predicates, never on coordinate equality.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <utility>
#include <vector>

#include "topocut/decomposition/decompose.h"

namespace topocut::dude {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Pt = K::Point_2;

// A polygon as rings of corners. Ring 0 is the outer ring (counter-clockwise), the others are holes
// (clockwise). Corners are numbered ring after ring, each ring in boundary order.
struct Poly {
  std::vector<Pt> pt;          // per corner
  std::vector<int> vid;        // per corner: the input vertex it visits
  std::vector<int> ring;       // per corner: its ring
  std::vector<int> ring_start; // size rings+1: ring r holds corners [ring_start[r], ring_start[r+1])

  int corners() const { return static_cast<int>(pt.size()); }
  int rings() const { return static_cast<int>(ring_start.size()) - 1; }
  int ring_size(int r) const { return ring_start[r + 1] - ring_start[r]; }
  int next(int c) const {
    const int r = ring[c];
    return c + 1 < ring_start[r + 1] ? c + 1 : ring_start[r];
  }
  int prev(int c) const {
    const int r = ring[c];
    return c > ring_start[r] ? c - 1 : ring_start[r + 1] - 1;
  }
  // Forward distance from corner a to corner b along their common ring.
  int offset(int a, int b) const {
    const int n = ring_size(ring[a]);
    return ((b - a) % n + n) % n;
  }

  // Appends a ring given as (point, vid) lists.
  void add_ring(const std::vector<Pt>& points, const std::vector<int>& vids);
};

// Options plus the derived constants of one run.
struct Settings {
  DecompositionOptions options;
  double tau = 1.0;
  int max_depth = 48;  // recursion cap for the dual passes (each level works on a strictly smaller polygon)
};

struct PassResult {
  std::vector<std::pair<int, int>> cuts;          // corner pairs, first < second, non-crossing
  std::vector<int> deleted_holes;                 // rings judged "noise" (§4.2)
  std::vector<std::pair<int, double>> pms;        // pocket minima (corner, concavity)
};

// One DuDe pass (§1 dude_pass). `top` enables hole deletion and the final cut filters (§6.5).
PassResult dude_pass(const Poly& poly, const Settings& settings, bool top, int depth);

// Splits poly along non-crossing interior cuts (corner pairs); deleted holes are left out.
// Returns the pieces, each an outer ring followed by its holes.
std::vector<Poly> split(const Poly& poly, const std::vector<std::pair<int, int>>& cuts,
                        const std::vector<int>& deleted_holes);

// --- geometry on points -----------------------------------------------------------------------

inline double sq(double x) { return x * x; }
inline double dist(const Pt& a, const Pt& b) { return std::sqrt(sq(a.x() - b.x()) + sq(a.y() - b.y())); }

// Distance from p to the closed segment ab.
double dseg(const Pt& p, const Pt& a, const Pt& b);
// Distance from p to the line through a and b (to a when a == b).
double dline(const Pt& p, const Pt& a, const Pt& b);
// The point of segment ab nearest to p.
Pt project_on_segment(const Pt& p, const Pt& a, const Pt& b);

// Exact clockwise angle class of ray v->q measured from ray v->r:
// 0 same direction, 1 in (0, pi), 2 exactly pi, 3 in (pi, 2 pi).
int cw_class(const Pt& v, const Pt& r, const Pt& q);
// Exact comparison of the clockwise angles from ray v->r to v->a and to v->b: -1, 0, 1.
int cw_compare(const Pt& v, const Pt& r, const Pt& a, const Pt& b);

// True when q lies strictly inside the interior wedge of corner c (swept clockwise from the ray to
// its predecessor to the ray to its successor).
bool in_wedge(const Poly& poly, int c, const Pt& q);
// Interior wedge test with explicit neighbours.
bool in_wedge(const Pt& pred, const Pt& v, const Pt& succ, const Pt& q);

// §0: a corner is reflex when the boundary does not turn left there (collinear counts as reflex).
bool is_reflex(const Poly& poly, int c);

// Douglas-Peucker simplification of an open chain (corner indices) with tolerance t; returns the
// positions (into chain) that are kept, always including both ends. A vertex is kept when its
// distance to its current chord is >= t: the distance to the chord's line, or with
// `segment_distance` to the chord itself. Ties go to the later vertex of the chain.
std::vector<int> approx(const Poly& poly, const std::vector<int>& chain, double t, bool segment_distance = false);

// Convex hull (strictly convex vertices, counter-clockwise) of the given corners; duplicate points
// are represented by the first corner given for them.
std::vector<int> hull_of(const Poly& poly, const std::vector<int>& corners);

// Twice the signed area of the closed chain a -> next -> ... -> b -> a along a's ring.
double chain_area2(const Poly& poly, int a, int b);

}  // namespace topocut::dude
