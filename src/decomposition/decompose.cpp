// §1 decompose(): validate, then run DuDe passes on every piece until no pass produces a cut.
#include "topocut/decomposition/decompose.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "decomposition/dude.h"
#include "decomposition/validate.h"
#include "topocut/core/error.h"

namespace topocut {

namespace {

using dude::Poly;
using dude::Pt;

Point2 to_point(const Pt& p) { return {p.x(), p.y()}; }

// Removes the slits of a ring (an edge u->v also traversed as v->u, §7.1): each slit splits the ring
// into two closed rings. Reasons with vertex ids only. The first edge whose reverse ran earlier is
// found through the ring's edges sorted by their ends (the earliest position among equal ones), not a
// hash map with an allocation per edge.
void unslit(const std::vector<int>& ring, const std::vector<int>& vid_of, std::vector<std::vector<int>>& out) {
  const int n = static_cast<int>(ring.size());
  auto key = [&](int from, int to) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(vid_of[from])) << 32) |
           static_cast<std::uint32_t>(vid_of[to]);
  };
  std::vector<std::pair<std::uint64_t, int>> edges(static_cast<std::size_t>(n));  // (from vid, to vid), position
  for (int i = 0; i < n; ++i) edges[static_cast<std::size_t>(i)] = {key(ring[i], ring[(i + 1) % n]), i};
  std::sort(edges.begin(), edges.end());
  for (int i = 0; i < n; ++i) {
    const int a = ring[i], b = ring[(i + 1) % n];
    const auto reverse = std::lower_bound(edges.begin(), edges.end(), std::pair{key(b, a), 0});
    if (reverse != edges.end() && reverse->first == key(b, a) && reverse->second < i) {
      const int j = reverse->second;  // edge j: b -> a, earlier in the ring
      std::vector<int> inner, outer;
      for (int k = j + 1; k <= i; ++k) inner.push_back(ring[k]);  // a(j+1) .. a(i): from b's successor to a
      // inner runs ring[j+1] .. ring[i]; ring[j+1] == a and ring[i] == a as points: drop the last copy.
      inner.pop_back();
      for (int k = i + 1; k < n; ++k) outer.push_back(ring[k]);
      for (int k = 0; k <= j; ++k) outer.push_back(ring[k]);
      // outer runs ring[i+1] (== b) .. ring[j] (== b): drop the last copy.
      outer.pop_back();
      if (inner.size() >= 3) unslit(inner, vid_of, out);
      if (outer.size() >= 3) unslit(outer, vid_of, out);
      return;
    }
  }
  out.push_back(ring);
}

double ring_area2(const Poly& poly, const std::vector<int>& ring) {
  double twice = 0.0;
  const Pt& o = poly.pt[ring[0]];
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Pt& p = poly.pt[ring[i]];
    const Pt& q = poly.pt[ring[(i + 1) % ring.size()]];
    twice += (p.x() - o.x()) * (q.y() - o.y()) - (q.x() - o.x()) * (p.y() - o.y());
  }
  return twice;
}

void emit(const Poly& piece, bool restore_holes, std::vector<PolygonWithHoles>& out) {
  auto to_ring = [&](const std::vector<int>& corners) {
    Ring ring;
    ring.reserve(corners.size());
    for (int c : corners) ring.push_back(to_point(piece.pt[c]));
    return ring;
  };
  std::vector<std::vector<int>> rings;
  for (int r = 0; r < piece.rings(); ++r) {
    std::vector<int> ring;
    for (int c = piece.ring_start[r]; c < piece.ring_start[r + 1]; ++c) ring.push_back(c);
    if (restore_holes) {
      unslit(ring, piece.vid, rings);
    } else {
      rings.push_back(std::move(ring));
    }
  }
  PolygonWithHoles result;
  std::vector<std::vector<int>> extra_outers;
  bool have_outer = false;
  for (const auto& ring : rings) {
    const double a2 = ring_area2(piece, ring);
    if (a2 > 0 && !have_outer) {
      result.outer = to_ring(ring);
      have_outer = true;
    } else if (a2 > 0) {
      extra_outers.push_back(ring);  // cannot happen for a connected piece; kept rather than lost
    } else if (a2 < 0) {
      result.holes.push_back(to_ring(ring));
    }
  }
  out.push_back(std::move(result));
  for (const auto& ring : extra_outers) out.push_back({to_ring(ring), {}});
}

}  // namespace

Decomposition decompose(const PolygonWithHoles& polygon, const DecompositionOptions& options) {
  if (!(options.tau > 0.0) || !std::isfinite(options.tau)) throw Error("tau must be a positive finite number");
  if (options.max_rounds < 1) throw Error("max_rounds must be at least 1");
  const PolygonWithHoles clean = dude::clean_and_validate(polygon);

  Poly root;
  int next_vid = 0;
  auto add = [&](const Ring& ring) {
    std::vector<Pt> pts;
    std::vector<int> vids;
    for (const Point2& p : ring) {
      pts.emplace_back(p.x, p.y);
      vids.push_back(next_vid++);
    }
    root.add_ring(pts, vids);
  };
  add(clean.outer);
  for (const Ring& hole : clean.holes) add(hole);

  dude::Settings settings;
  settings.options = options;
  settings.tau = options.tau;

  Decomposition result;
  std::vector<Poly> todo{std::move(root)};
  std::vector<Poly> done;
  for (int round = 0; !todo.empty(); ++round) {
    if (round >= options.max_rounds) {
      result.complete = false;
      for (Poly& p : todo) done.push_back(std::move(p));
      break;
    }
    result.rounds = round + 1;
    std::vector<Poly> next;
    for (Poly& piece : todo) {
      const dude::PassResult pass = dude::dude_pass(piece, settings, true, 0);
      for (const auto& [c, concavity] : pass.pms) {
        result.pocket_minima.push_back({to_point(piece.pt[c]), concavity, round, piece.ring[c] != 0});
      }
      for (int h : pass.deleted_holes) {
        Ring ring;
        for (int c = piece.ring_start[h]; c < piece.ring_start[h + 1]; ++c) ring.push_back(to_point(piece.pt[c]));
        result.absorbed_holes.push_back(std::move(ring));
      }
      for (const auto& [a, b] : pass.cuts) {
        result.cuts.push_back({{to_point(piece.pt[a]), to_point(piece.pt[b])}, round});
      }
      std::vector<Poly> parts = dude::split(piece, pass.cuts, pass.deleted_holes);
      if (pass.cuts.empty()) {
        done.insert(done.end(), std::make_move_iterator(parts.begin()), std::make_move_iterator(parts.end()));
      } else {
        next.insert(next.end(), std::make_move_iterator(parts.begin()), std::make_move_iterator(parts.end()));
      }
    }
    todo = std::move(next);
  }
  for (const Poly& piece : done) emit(piece, options.restore_holes, result.pieces);
  return result;
}

}  // namespace topocut
