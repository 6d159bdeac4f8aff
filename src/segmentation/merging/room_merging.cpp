#include "topocut/segmentation/room_merging.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <queue>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "segmentation/merging/room_graph.h"
#include "topocut/core/error.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/segmentation/merge_model.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace topocut {

namespace {

using Key = std::tuple<double, double, double, double>;  // directed edge (a.x, a.y, b.x, b.y)

Key edge_key(const Point2& a, const Point2& b) { return {a.x, a.y, b.x, b.y}; }

// A directed edge's hash from its coordinates' bits, 0.0 and -0.0 (equal keys) alike.
struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = 0;
    for (const double v : {std::get<0>(k), std::get<1>(k), std::get<2>(k), std::get<3>(k)}) {
      const std::uint64_t bits = v == 0.0 ? 0 : std::bit_cast<std::uint64_t>(v);
      h = (h ^ bits) * 0x9e3779b97f4a7c15ULL;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h);
  }
};

// A cut's priority as the merging takes them: the highest first, the lowest cut among equal ones;
// stamp tells a priority measured again from the one queued before.
struct QueuedCut {
  double priority;
  std::size_t k;
  unsigned stamp;
};

struct TakenLater {
  bool operator()(const QueuedCut& a, const QueuedCut& b) const {
    return a.priority < b.priority || (a.priority == b.priority && a.k > b.k);
  }
};

// Merges across the cut of highest priority(k) (std::nullopt: cut k is not to be taken) while there
// is one; the priorities of the grown room's cuts are measured again, in cut order. The cuts wait in a
// queue (priorities measured before the room beside them grew, and cuts inside one room, are dropped
// as they come up), so that a merge costs the grown room's cuts, not a look at every cut of the
// component; the merges are those of taking the best of all cuts each time, ties to the lowest cut.
template <class Priority>
void merge_best_first(RoomGraph& g, const Priority& priority) {
  const std::size_t n = g.sides().size();
  std::vector<unsigned> stamp(n, 0);
  std::priority_queue<QueuedCut, std::vector<QueuedCut>, TakenLater> queue;
  auto measure = [&](std::size_t k) {
    ++stamp[k];
    if (const std::optional<double> p = priority(k)) queue.push({*p, k, stamp[k]});
  };
  for (std::size_t k = 0; k < n; ++k)
    if (g.separates(k)) measure(k);
  while (!queue.empty()) {
    const QueuedCut best = queue.top();
    queue.pop();
    if (best.stamp != stamp[best.k] || !g.separates(best.k)) continue;
    const RoomGraph::Side& chosen = g.sides()[best.k];
    g.unite(chosen.left, chosen.right);
    for (const std::size_t k : g.room_sides(g.root(chosen.left)))
      if (g.separates(k)) measure(k);
  }
}

// Widest chord of room r along any of its cuts (metres).
double room_width(RoomGraph& g, int r, double depth) {
  double widest = 0.0;
  for (const std::size_t k : g.room_sides(r)) {
    if (!g.separates(k)) continue;
    const RoomGraph::Side& s = g.sides()[k];
    if (g.root(s.left) == r) widest = std::max(widest, g.side_width(k, r, true, depth));
    if (g.root(s.right) == r) widest = std::max(widest, g.side_width(k, r, false, depth));
  }
  return widest;
}

// The room that room r shares the longest cuts with (-1: none), lengths summed in cut order.
int longest_shared_neighbour(RoomGraph& g, int r) {
  std::map<int, double> shared;
  for (const std::size_t k : g.room_sides(r)) {
    const RoomGraph::Side& s = g.sides()[k];
    if (!g.separates(k)) continue;
    const int a = g.root(s.left), b = g.root(s.right);
    shared[a == r ? b : a] += s.length;
  }
  int into = -1;
  double longest = 0.0;
  for (const auto& [room, length] : shared) {
    if (length > longest) {
      into = room;
      longest = length;
    }
  }
  return into;
}

// The verdict of the first criterion that does not abstain; none: the rooms stay apart.
MergeVerdict first_verdict(MergeCandidate& candidate, const std::vector<const MergeCriterion*>& criteria) {
  for (const MergeCriterion* criterion : criteria) {
    const MergeVerdict verdict = (*criterion)(candidate);
    if (verdict.kind != MergeVerdict::kAbstain) return verdict;
  }
  return MergeVerdict::keep();
}

}  // namespace

void merge_by_criteria(ComponentMerge& merge) {
  RoomGraph& g = merge.graph;
  merge_best_first(g, [&](std::size_t k) -> std::optional<double> {
    MergeCandidate candidate(g, k, merge.options);
    const MergeVerdict verdict = first_verdict(candidate, merge.criteria);
    if (merge.trace && merge.options.learned) {
      const RoomGraph::Side& s = g.sides()[k];
      merge.trace->push_back({candidate.features(), g.members(g.root(s.left)), g.members(g.root(s.right)), verdict.score});
    }
    if (verdict.kind == MergeVerdict::kMerge) return verdict.score;
    return std::nullopt;
  });
}


namespace {

// Folds every room that folds(r) says is no room into the room into(r) names (-1: none, the room
// stays), the smallest first (the least likely to be a room of its own), ties to the lowest room.
// folds(r) is asked again of a room only after it or a room beside it grew (its measures change only
// then). The rooms to fold wait in a set ordered as that choice, so that a fold costs the grown room's
// neighbours, not a look at every room of the component (quadratic on a large floor).
template <class Folds, class Into>
void fold_rooms(RoomGraph& g, const Folds& folds, const Into& into) {
  std::set<std::pair<double, int>> waiting;                     // (area, room): the rooms to fold
  std::vector<std::optional<double>> queued(g.piece_count());  // the area a room waits with
  auto leave = [&](int r) {
    std::optional<double>& area = queued[static_cast<std::size_t>(r)];
    if (area) waiting.erase({*area, r});
    area.reset();
  };
  auto ask = [&](int r) {
    leave(r);
    if (!folds(r)) return;
    const double area = g.room_area(r);
    waiting.insert({area, r});
    queued[static_cast<std::size_t>(r)] = area;
  };
  for (std::size_t i = 0; i < g.piece_count(); ++i)
    if (g.root(static_cast<int>(i)) == static_cast<int>(i)) ask(static_cast<int>(i));
  std::vector<int> beside;
  while (!waiting.empty()) {
    const int victim = waiting.begin()->second;
    const int target = into(victim);
    leave(victim);  // a room that cannot fold waits again only once a room beside it grows
    if (target < 0) continue;
    leave(target);
    g.unite(victim, target);
    const int grown = g.root(victim);
    beside.assign(1, grown);
    for (const std::size_t k : g.room_sides(grown)) {
      const RoomGraph::Side& s = g.sides()[k];
      for (const int piece : {s.left, s.right}) beside.push_back(g.root(piece));
    }
    std::sort(beside.begin(), beside.end());
    beside.erase(std::unique(beside.begin(), beside.end()), beside.end());
    for (const int r : beside) ask(r);
  }
}

template <class Folds>
void fold_rooms(RoomGraph& g, const Folds& folds) {
  fold_rooms(g, folds, [&g](int r) { return longest_shared_neighbour(g, r); });
}

// The rooms beside room r with the length of the cuts r shares with each, door rules' cuts left out
// when skip_doors (a door or a room's open front stays a boundary), and the longest of those cuts.
struct Shared {
  double length = 0.0;
  std::size_t longest = 0;
};
std::map<int, Shared> shared_cuts(RoomGraph& g, int r, bool skip_doors) {
  std::map<int, Shared> shared;
  for (const std::size_t k : g.room_sides(r)) {
    const RoomGraph::Side& s = g.sides()[k];
    if (!g.separates(k) || (skip_doors && is_door_rule(s.rule))) continue;
    const int a = g.root(s.left), b = g.root(s.right);
    Shared& with = shared[a == r ? b : a];
    if (with.length == 0.0 || s.length > g.sides()[with.longest].length) with.longest = k;
    with.length += s.length;
  }
  return shared;
}

// Whether the model leans towards one room across cut k (at least RoomMergeOptions::hang_probability)
// without reaching its threshold: above it, the cut stands because a criterion before the model kept
// it, and that stays.
bool hangs_across(RoomGraph& g, std::size_t k, const RoomMergeOptions& options) {
  const double p = merge_probability(*options.model, merge_features(g, k, options));
  return p >= options.hang_probability && p <= options.model->threshold;
}

// The room that room r is a bay of (-1: none): a room at least bay_area_ratio^-1 times r's area whose
// cuts to r, door rules' left out, are at least bay_share of r's outline, the longest share first,
// when the model leans towards one room across the longest of them.
int bay_of(RoomGraph& g, int r, const RoomMergeOptions& options) {
  const double perimeter = g.room_perimeter(r), area = g.room_area(r);
  int into = -1;
  double longest = 0.0;
  for (const auto& [room, with] : shared_cuts(g, r, true)) {
    if (with.length < options.bay_share * perimeter || with.length <= longest) continue;
    if (area > options.bay_area_ratio * g.room_area(room) || !hangs_across(g, with.longest, options)) continue;
    into = room;
    longest = with.length;
  }
  return into;
}

// The room that room r is a fragment of (-1: none): r smaller than fragment_area and bounded more by
// never-seen cells than by walls, the room it shares the longest cuts with, when the model leans
// towards one room across the longest of them.
int fragment_of(RoomGraph& g, int r, const RoomMergeOptions& options) {
  if (g.room_area(r) >= options.fragment_area || g.unknown_share(r) <= g.wall_share(r) || !g.walls_seen()) return -1;
  int into = -1;
  Shared best;
  for (const auto& [room, with] : shared_cuts(g, r, false)) {
    if (with.length > best.length) std::tie(into, best) = std::pair{room, with};
  }
  if (into < 0 || g.sides()[best.longest].length >= options.fragment_gap) return -1;
  return hangs_across(g, best.longest, options) ? into : -1;
}

}  // namespace

void fold_small_rooms(ComponentMerge& merge) {
  RoomGraph& g = merge.graph;
  const RoomMergeOptions& options = merge.options;
  // One thickness per criterion: the hand rules fold thin rooms, learned merging only slivers.
  const double thickness = options.learned ? options.sliver_thickness : options.min_room_thickness;
  fold_rooms(g, [&](int r) {
    return g.room_area(r) < options.min_room_area ||
           (options.min_room_width > 0.0 && room_width(g, r, options.door_like.width_depth) < options.min_room_width) ||
           (thickness > 0.0 && g.room_thickness(r) < thickness);
  });
}

void fold_fragments(ComponentMerge& merge) {
  RoomGraph& g = merge.graph;
  const RoomMergeOptions& options = merge.options;
  if (options.fragment_area <= 0.0 || !options.learned) return;
  fold_rooms(g, [&](int r) { return fragment_of(g, r, options) >= 0; }, [&](int r) { return fragment_of(g, r, options); });
}

void fold_bays(ComponentMerge& merge) {
  RoomGraph& g = merge.graph;
  const RoomMergeOptions& options = merge.options;
  if (options.bay_share <= 0.0 || !options.learned) return;
  fold_rooms(g, [&](int r) { return bay_of(g, r, options) >= 0; }, [&](int r) { return bay_of(g, r, options); });
}

namespace {

double turn(const Point2& a, const Point2& b, const Point2& c) {
  const double dx = b.x - a.x, dy = b.y - a.y, ex = c.x - b.x, ey = c.y - b.y;
  return std::atan2(dx * ey - dy * ex, dx * ex + dy * ey);
}

}  // namespace

void validate(const RoomMergeOptions& options) {
  check_option_rows(room_merge_option_rows(), options);  // each number's range is its row's (the model was checked when made)
}

PolygonWithHoles union_of_pieces(const std::vector<PolygonWithHoles>& pieces) {
  // Directed edges; an edge met in the other direction too is interior and cancels. Hashed, then
  // sorted once: a tree of the edges cost more than the rest of the union on real maps' rooms.
  std::unordered_map<Key, int, KeyHash> pending;
  std::size_t vertices = 0;
  for (const PolygonWithHoles& piece : pieces) {
    vertices += piece.outer.size();
    for (const Ring& hole : piece.holes) vertices += hole.size();
  }
  pending.reserve(vertices);
  std::vector<std::pair<Point2, Point2>> edges;
  auto add_ring = [&](const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point2& a = ring[k];
      const Point2& b = ring[(k + 1) % ring.size()];
      if (a == b) continue;
      const auto reverse = pending.find(edge_key(b, a));
      if (reverse != pending.end()) {
        pending.erase(reverse);
        continue;
      }
      pending.emplace(edge_key(a, b), static_cast<int>(edges.size()));
      edges.emplace_back(a, b);
    }
  };
  for (const PolygonWithHoles& piece : pieces) {
    add_ring(piece.outer);
    for (const Ring& hole : piece.holes) add_ring(hole);
  }
  // The remaining edges in the order of their keys, and by start point (in that order among equal
  // ones): the order the walk below takes them in.
  std::vector<std::pair<Key, int>> remaining(pending.begin(), pending.end());
  std::sort(remaining.begin(), remaining.end());  // the keys differ: by key
  using Start = std::pair<std::pair<double, double>, int>;
  std::vector<Start> out;
  std::vector<bool> used(edges.size(), true);
  for (const auto& [key, index] : remaining) {
    const auto& e = edges[static_cast<std::size_t>(index)];
    out.push_back({{e.first.x, e.first.y}, index});
    used[static_cast<std::size_t>(index)] = false;
  }
  const auto by_point = [](const Start& a, const Start& b) { return a.first < b.first; };
  std::stable_sort(out.begin(), out.end(), by_point);
  std::vector<Ring> rings;
  for (const auto& [key, first] : remaining) {
    if (used[static_cast<std::size_t>(first)]) continue;
    Ring ring;
    int e = first;
    used[static_cast<std::size_t>(e)] = true;
    const std::size_t limit = edges.size() + 1;
    while (true) {
      const auto& [a, b] = edges[static_cast<std::size_t>(e)];
      ring.push_back(a);
      if (ring.size() > limit) throw Error("internal: the pieces' edges do not close into rings");
      // Leave b along the unused edge that turns most to the right (holes touching the outer ring
      // at a vertex stay separate rings); closing the ring is one of the choices.
      const auto [from, to] = std::equal_range(out.begin(), out.end(), Start{{b.x, b.y}, 0}, by_point);
      int next = -1;
      double best = std::numeric_limits<double>::infinity();
      for (auto it = from; it != to; ++it) {
        const int candidate = it->second;
        if (used[static_cast<std::size_t>(candidate)] && candidate != first) continue;
        const double t = turn(a, b, edges[static_cast<std::size_t>(candidate)].second);
        if (t < best) {
          best = t;
          next = candidate;
        }
      }
      if (next < 0) throw Error("the pieces do not meet along whole edges: their union is not a polygon");
      if (next == first) break;
      used[static_cast<std::size_t>(next)] = true;
      e = next;
    }
    if (ring.size() >= 3 && signed_area(ring) != 0.0) rings.push_back(std::move(ring));
  }
  PolygonWithHoles result;
  int outers = 0;
  for (Ring& ring : rings) {
    if (signed_area(ring) > 0.0) {
      result.outer = std::move(ring);
      ++outers;
    } else {
      result.holes.push_back(std::move(ring));
    }
  }
  if (outers != 1) throw Error("the pieces do not form one connected region (" + std::to_string(outers) + " outer rings)");
  return result;
}

PieceSet merge_rooms(const FreeSpaceComponent& component, const PieceSet& pieces, const cv::Mat& cells, double resolution,
                     const SegmentOptions& options, const std::vector<SegmentationRule>& rules, std::vector<MergeStep>* trace) {
  // options.merge is not validated here: with the learned model that walks every tree (0.46 M
  // instructions), once per component and per redecomposition; where the options enter does it.
  if (!std::isfinite(resolution) || resolution <= 0.0) throw Error("the map resolution must be a positive number");
  std::vector<const SegmentationRule*> steps;
  std::vector<const MergeCriterion*> criteria;
  for (const SegmentationRule& rule : rules) {
    if (!row_is_on(rule, RuleStage::kMerge, options)) continue;
    if (rule.on_component) steps.push_back(&rule);
    if (rule.judge) criteria.push_back(&rule.judge);
  }
  if (steps.empty() || pieces.pieces.size() < 2) return pieces;
  RoomGraph graph(component.polygon, pieces, cells, resolution, options.merge.furniture_size);
  ComponentMerge merge{graph, options.merge, std::move(criteria), trace};
  for (const SegmentationRule* step : steps) {
    note_rule_run(*step);
    step->on_component(merge);
  }
  return graph.result();
}

PieceSet merge_rooms(const FreeSpaceComponent& component, const PieceSet& pieces, const cv::Mat& cells, double resolution,
                     const RoomMergeOptions& options, std::vector<MergeStep>* trace) {
  validate(options);
  SegmentOptions all;
  all.merge = options;
  return merge_rooms(component, pieces, cells, resolution, all, segmentation_rules(), trace);
}

}  // namespace topocut
