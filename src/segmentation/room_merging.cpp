#include "topocut/segmentation/room_merging.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "topocut/core/error.h"
#include "topocut/map/free_space_polygons.h"

namespace topocut {

namespace {

using Key = std::tuple<double, double, double, double>;  // directed edge (a.x, a.y, b.x, b.y)

Key edge_key(const Point2& a, const Point2& b) { return {a.x, a.y, b.x, b.y}; }

double perimeter(const PolygonWithHoles& polygon) {
  double length = perimeter(polygon.outer);
  for (const Ring& hole : polygon.holes) length += perimeter(hole);
  return length;
}

// Where the line p + t·u (u a unit vector) crosses the rings of one piece, as parameters t; the
// crossing rule is half-open on the side of the line (as the rasterizer's), so a vertex on the line
// is counted once and the even-odd pairing of the sorted values gives the piece's chords.
void add_crossings(const Ring& ring, const Point2& p, const Point2& u, std::vector<double>& ts) {
  const Point2 n{-u.y, u.x};
  const std::size_t count = ring.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % count];
    const double sa = (a.x - p.x) * n.x + (a.y - p.y) * n.y;
    const double sb = (b.x - p.x) * n.x + (b.y - p.y) * n.y;
    if ((sa > 0.0) == (sb > 0.0)) continue;
    const double ta = (a.x - p.x) * u.x + (a.y - p.y) * u.y;
    const double tb = (b.x - p.x) * u.x + (b.y - p.y) * u.y;
    ts.push_back(ta + (tb - ta) * sa / (sa - sb));
  }
}

// The pieces and cuts of one component, with the rooms formed so far (union-find over pieces).
class Merger {
 public:
  Merger(const PolygonWithHoles& polygon, const PieceSet& set, double resolution, const RoomMergeOptions& options)
      : set_(set), resolution_(resolution), options_(options), parent_(set.pieces.size()) {
    std::iota(parent_.begin(), parent_.end(), 0);
    members_.resize(set.pieces.size());
    for (std::size_t i = 0; i < set.pieces.size(); ++i) members_[i] = {static_cast<int>(i)};
    boxes_.reserve(set.pieces.size());
    for (const PolygonWithHoles& piece : set.pieces) {
      boxes_.push_back(bounding_box(piece.outer));
      areas_.push_back(area(piece) * resolution * resolution);
      perimeters_.push_back(perimeter(piece) * resolution);
    }
    find_cut_sides();
    mark_furniture_cuts(polygon);
  }

  void merge_non_doors() {
    // Greedy: the most clearly non-door-like cut first, then the scores next to the merged room
    // change (the merged room is wider or longer than its parts), so they are measured again.
    // Scores are cached and measured again only for the cuts of a room that just grew.
    std::vector<double> score(sides_.size(), 0.0);
    std::vector<bool> fresh(sides_.size(), false);
    while (true) {
      int best = -1;
      double best_score = 0.0;
      for (std::size_t k = 0; k < sides_.size(); ++k) {
        const Side& s = sides_[k];
        if (s.left < 0 || root(s.left) == root(s.right) || blocked_[k] || s.door) continue;
        if (!fresh[k]) {
          score[k] = door_score(static_cast<int>(k));
          fresh[k] = true;
        }
        if (score[k] >= options_.door_ratio && (best < 0 || score[k] > best_score)) {
          best = static_cast<int>(k);
          best_score = score[k];
        }
      }
      if (best < 0) return;
      const Side& chosen = sides_[static_cast<std::size_t>(best)];
      if (!unite(chosen.left, chosen.right)) {
        blocked_[static_cast<std::size_t>(best)] = true;
        continue;
      }
      const int grown = root(chosen.left);
      for (std::size_t k = 0; k < sides_.size(); ++k) {
        const Side& s = sides_[k];
        if (s.left >= 0 && (root(s.left) == grown || root(s.right) == grown)) fresh[k] = false;
      }
    }
  }

  void fold_small_rooms() {
    while (true) {
      // Smallest offending room first: it is the least likely to be a room of its own.
      int victim = -1;
      double victim_area = 0.0;
      for (std::size_t i = 0; i < parent_.size(); ++i) {
        if (root(static_cast<int>(i)) != static_cast<int>(i)) continue;
        const double a = room_area(static_cast<int>(i));
        const bool small = a < options_.min_room_area;
        const bool thin = (options_.min_room_width > 0.0 && room_width(static_cast<int>(i)) < options_.min_room_width) ||
                          (options_.min_room_thickness > 0.0 && room_thickness(static_cast<int>(i)) < options_.min_room_thickness);
        if ((small || thin) && (victim < 0 || a < victim_area) && !stuck_[i]) {
          victim = static_cast<int>(i);
          victim_area = a;
        }
      }
      if (victim < 0) return;
      // The neighbour with the longest shared cut length.
      std::map<int, double> shared;
      for (std::size_t k = 0; k < sides_.size(); ++k) {
        const Side& s = sides_[k];
        if (s.left < 0 || blocked_[k]) continue;
        const int a = root(s.left), b = root(s.right);
        if (a == b || (a != victim && b != victim)) continue;
        shared[a == victim ? b : a] += s.length;
      }
      int into = -1;
      double longest = 0.0;
      for (const auto& [room, length] : shared) {
        if (length > longest) {
          into = room;
          longest = length;
        }
      }
      if (into < 0 || !unite(victim, into)) stuck_[static_cast<std::size_t>(victim)] = true;
    }
  }

  PieceSet result() {
    // Rooms in the order of their first piece; the cuts between two rooms in input order.
    std::vector<int> order;
    std::vector<std::vector<int>> members(parent_.size());
    for (std::size_t i = 0; i < parent_.size(); ++i) {
      const int r = root(static_cast<int>(i));
      if (members[static_cast<std::size_t>(r)].empty()) order.push_back(r);
      members[static_cast<std::size_t>(r)].push_back(static_cast<int>(i));
    }
    // Each merged room's polygon is the union of its pieces. If that fails (pieces that do not
    // meet along whole edges, which DuDe's never do), the room stays as its pieces.
    std::map<int, PolygonWithHoles> unions;
    std::set<int> broken;
    for (const int r : order) {
      const std::vector<int>& m = members[static_cast<std::size_t>(r)];
      if (m.size() < 2) continue;
      std::vector<PolygonWithHoles> parts;
      for (const int i : m) parts.push_back(set_.pieces[static_cast<std::size_t>(i)]);
      try {
        unions[r] = union_of_pieces(parts);
      } catch (const Error&) {
        broken.insert(r);
      }
    }
    PieceSet out;
    std::set<std::pair<double, double>> ends;  // end points of the cuts that stay
    for (std::size_t k = 0; k < sides_.size(); ++k) {
      const Side& s = sides_[k];
      if (s.left < 0 || (root(s.left) == root(s.right) && !broken.count(root(s.left)))) continue;
      out.cuts.push_back(set_.cuts[k]);
      if (s.door) out.doors.push_back(set_.cuts[k]);
      if (s.wall_line) out.wall_lines.push_back(set_.cuts[k]);
      ends.insert({set_.cuts[k].a.x, set_.cuts[k].a.y});
      ends.insert({set_.cuts[k].b.x, set_.cuts[k].b.y});
    }
    for (const int r : order) {
      const std::vector<int>& m = members[static_cast<std::size_t>(r)];
      if (m.size() == 1 || broken.count(r)) {
        for (const int i : m) out.pieces.push_back(set_.pieces[static_cast<std::size_t>(i)]);
        continue;
      }
      // Where a removed cut met a straight wall the union goes straight on; such vertices are
      // dropped unless a remaining cut ends there (the cut must stay an edge of both rooms).
      PolygonWithHoles room = unions.at(r);
      auto tidy = [&](Ring& ring) {
        Ring kept = remove_collinear_vertices(ring, [&](const Point2& p) { return ends.count({p.x, p.y}) > 0; });
        if (kept.size() >= 3) ring = std::move(kept);
      };
      tidy(room.outer);
      for (Ring& hole : room.holes) tidy(hole);
      out.pieces.push_back(std::move(room));
    }
    return out;
  }

 private:
  struct Side {
    int left = -1, right = -1;  // pieces left and right of the cut (a -> b); -1: not a cut between two pieces
    double length = 0.0;        // metres
    bool door = false;          // found by the door detector: never merged as "not a door"
    bool furniture = false;     // ends on a furniture-sized obstacle: no room boundary
    bool wall_line = false;     // continues a wall across the free space
  };

  // Cuts with an end point on a small obstacle (a hole whose bounding box is at most
  // options_.furniture_size a side) separate no rooms: a room does not end at a table.
  void mark_furniture_cuts(const PolygonWithHoles& polygon) {
    if (options_.furniture_size <= 0.0) return;
    const double limit = options_.furniture_size / resolution_;
    const double near = 1.5;  // cells: the pieces come from the polygon simplified by about a cell
    for (const Ring& hole : polygon.holes) {
      const Box box = bounding_box(hole);
      if (box.x1 - box.x0 > limit || box.y1 - box.y0 > limit) continue;
      for (std::size_t k = 0; k < sides_.size(); ++k) {
        if (sides_[k].left < 0 || sides_[k].furniture) continue;
        for (const Point2& end : {set_.cuts[k].a, set_.cuts[k].b}) {
          if (end.x < box.x0 - near || end.x > box.x1 + near || end.y < box.y0 - near || end.y > box.y1 + near) continue;
          for (std::size_t i = 0; i < hole.size() && !sides_[k].furniture; ++i)
            sides_[k].furniture = distance_to_segment(end, {hole[i], hole[(i + 1) % hole.size()]}) <= near;
        }
      }
    }
  }

  void find_cut_sides() {
    std::map<Key, int> owner;
    for (std::size_t i = 0; i < set_.pieces.size(); ++i) {
      auto add_ring = [&](const Ring& ring) {
        for (std::size_t k = 0; k < ring.size(); ++k)
          owner.emplace(edge_key(ring[k], ring[(k + 1) % ring.size()]), static_cast<int>(i));
      };
      add_ring(set_.pieces[i].outer);
      for (const Ring& hole : set_.pieces[i].holes) add_ring(hole);
    }
    sides_.resize(set_.cuts.size());
    blocked_.assign(set_.cuts.size(), false);
    stuck_.assign(set_.pieces.size(), false);
    for (std::size_t k = 0; k < set_.cuts.size(); ++k) {
      const Segment2& c = set_.cuts[k];
      const auto left = owner.find(edge_key(c.a, c.b));
      const auto right = owner.find(edge_key(c.b, c.a));
      if (left == owner.end() || right == owner.end() || left->second == right->second) continue;
      const bool door = std::find(set_.doors.begin(), set_.doors.end(), c) != set_.doors.end();
      sides_[k] = {left->second, right->second, distance(c.a, c.b) * resolution_, door};
      sides_[k].wall_line = std::find(set_.wall_lines.begin(), set_.wall_lines.end(), c) != set_.wall_lines.end();
    }
  }

  int root(int i) {
    while (parent_[static_cast<std::size_t>(i)] != i) {
      parent_[static_cast<std::size_t>(i)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(i)])];
      i = parent_[static_cast<std::size_t>(i)];
    }
    return i;
  }

  // Merges the rooms of pieces a and b (their polygon is made once, in result()).
  bool unite(int a, int b) {
    int ra = root(a), rb = root(b);
    if (ra == rb) return true;
    if (rb < ra) std::swap(ra, rb);  // the room keeps its first piece as root
    parent_[static_cast<std::size_t>(rb)] = ra;
    std::vector<int>& into = members_[static_cast<std::size_t>(ra)];
    std::vector<int>& from = members_[static_cast<std::size_t>(rb)];
    into.insert(into.end(), from.begin(), from.end());
    from.clear();
    area_sum_[ra] = room_area(ra) + room_area(rb);
    area_sum_.erase(rb);
    return true;
  }

  double room_area(int r) {
    const auto it = area_sum_.find(r);
    return it != area_sum_.end() ? it->second : areas_[static_cast<std::size_t>(r)];
  }

  // Length of the chord of room r along the line through p with direction u (unit), around p; 0 if
  // p is not inside the room. The room's pieces are intersected one by one and their chords joined.
  double chord(int r, const Point2& p, const Point2& u) {
    std::vector<std::pair<double, double>> spans;
    std::vector<double> ts;
    const Point2 n{-u.y, u.x};
    for (const int member : members_[static_cast<std::size_t>(r)]) {
      const std::size_t i = static_cast<std::size_t>(member);
      const Box& b = boxes_[i];
      const double s[4] = {(b.x0 - p.x) * n.x + (b.y0 - p.y) * n.y, (b.x1 - p.x) * n.x + (b.y0 - p.y) * n.y,
                           (b.x0 - p.x) * n.x + (b.y1 - p.y) * n.y, (b.x1 - p.x) * n.x + (b.y1 - p.y) * n.y};
      if (std::min({s[0], s[1], s[2], s[3]}) > 0.0 || std::max({s[0], s[1], s[2], s[3]}) <= 0.0) continue;
      ts.clear();
      add_crossings(set_.pieces[i].outer, p, u, ts);
      for (const Ring& hole : set_.pieces[i].holes) add_crossings(hole, p, u, ts);
      std::sort(ts.begin(), ts.end());
      for (std::size_t k = 0; k + 1 < ts.size(); k += 2) spans.emplace_back(ts[k], ts[k + 1]);
    }
    std::sort(spans.begin(), spans.end());
    // Join touching spans (pieces of one room share their cuts), keep the one around t = 0.
    const double touch = 1e-9;
    double lo = 0.0, hi = 0.0;
    bool open = false;
    for (const auto& [a, b] : spans) {
      if (open && a <= hi + touch) {
        hi = std::max(hi, b);
        continue;
      }
      if (open && lo <= 0.0 && hi >= 0.0) return hi - lo;
      lo = a;
      hi = b;
      open = true;
    }
    if (open && lo <= 0.0 && hi >= 0.0) return hi - lo;
    return 0.0;
  }

  // Cut k's direction (unit, a -> b), its normal into the left or right side, and its middle.
  struct CutFrame {
    Point2 u, n, mid;
  };
  CutFrame cut_frame(int k, bool left) const {
    const Segment2& c = set_.cuts[static_cast<std::size_t>(k)];
    const double length = distance(c.a, c.b);
    const Point2 u{(c.b.x - c.a.x) / length, (c.b.y - c.a.y) / length};
    return {u, left ? Point2{-u.y, u.x} : Point2{u.y, -u.x}, {(c.a.x + c.b.x) / 2.0, (c.a.y + c.b.y) / 2.0}};
  }

  // Width of room r beside cut k (cells): the longest chord parallel to the cut within the sampling
  // depth on r's side.
  double side_width(int k, int r, bool left) {
    const auto [u, n, mid] = cut_frame(k, left);
    const double depth = std::max(options_.width_depth / resolution_, 1.0);
    const int samples = 8;
    double widest = 0.0;
    for (int s = 1; s <= samples; ++s) {
      const double d = depth * s / samples;
      const double w = chord(r, {mid.x + d * n.x, mid.y + d * n.y}, u);
      if (w <= 0.0) break;
      widest = std::max(widest, w);
    }
    return widest * resolution_;
  }

  // A room that opens onto a much wider, deep space (RoomMergeOptions::step_ratio): kept apart.
  bool is_width_step(int k, double width_left, double width_right) {
    if (options_.step_ratio <= 0.0) return false;
    const Side& s = sides_[static_cast<std::size_t>(k)];
    const bool left_narrow = width_left <= width_right;
    const int wide_room = root(left_narrow ? s.right : s.left);
    // A wall line is the narrow room's wall drawn on: the wider side need only reach deeper than
    // the narrow room is wide (step_wall_line_depth times), not step_min_wide_depth; an L-shaped
    // corridor's corner is as deep as the corridor is wide, so it still merges.
    return std::min(width_left, width_right) < options_.step_ratio * std::max(width_left, width_right) &&
           std::min(room_area(root(s.left)), room_area(root(s.right))) >= options_.step_min_area &&
           side_depth(k, wide_room, !left_narrow) >= (s.wall_line ? options_.step_wall_line_depth * std::min(width_left, width_right)
                                                                   : options_.step_min_wide_depth);
  }

  // Depth of room r behind cut k (metres): its chord along the cut's normal through the cut's middle.
  double side_depth(int k, int r, bool left) {
    const auto [u, n, mid] = cut_frame(k, left);
    return chord(r, {mid.x + 0.5 * n.x, mid.y + 0.5 * n.y}, n) * resolution_;
  }

  // Cut length over the width of the narrower side: >= door_ratio means "not a door"; infinite for a
  // cut that ends on furniture, 0 for a width step.
  double door_score(int k) {
    const Side& s = sides_[static_cast<std::size_t>(k)];
    if (s.furniture) return std::numeric_limits<double>::infinity();
    const double wl = side_width(k, root(s.left), true), wr = side_width(k, root(s.right), false);
    const double narrow = std::min(wl, wr);
    if (narrow <= 0.0) return std::numeric_limits<double>::infinity();
    if (is_width_step(k, wl, wr)) return 0.0;
    return s.length / narrow;
  }

  // 2 area / perimeter of room r (metres): the width of a long strip, half the side of a square.
  double room_thickness(int r) {
    double length = 0.0;
    for (const int member : members_[static_cast<std::size_t>(r)]) length += perimeters_[static_cast<std::size_t>(member)];
    for (const Side& s : sides_) {
      if (s.left >= 0 && root(s.left) == r && root(s.right) == r) length -= 2.0 * s.length;
    }
    return length > 0.0 ? 2.0 * room_area(r) / length : 0.0;
  }

  // Widest chord of room r along any of its cuts (metres).
  double room_width(int r) {
    double widest = 0.0;
    for (std::size_t k = 0; k < sides_.size(); ++k) {
      const Side& s = sides_[k];
      if (s.left < 0) continue;
      const int a = root(s.left), b = root(s.right);
      if (a == b) continue;
      if (a == r) widest = std::max(widest, side_width(static_cast<int>(k), r, true));
      if (b == r) widest = std::max(widest, side_width(static_cast<int>(k), r, false));
    }
    return widest;
  }

  const PieceSet& set_;
  double resolution_;
  RoomMergeOptions options_;
  std::vector<int> parent_;
  std::vector<std::vector<int>> members_;  // room root -> its pieces
  std::vector<Box> boxes_;
  std::vector<double> areas_;  // m² per piece
  std::vector<double> perimeters_;  // m per piece
  std::vector<Side> sides_;
  std::vector<bool> blocked_, stuck_;
  std::map<int, double> area_sum_;          // room root -> area (m², rooms of 2+ pieces)
};

double turn(const Point2& a, const Point2& b, const Point2& c) {
  const double dx = b.x - a.x, dy = b.y - a.y, ex = c.x - b.x, ey = c.y - b.y;
  return std::atan2(dx * ey - dy * ex, dx * ex + dy * ey);
}

}  // namespace

void validate(const RoomMergeOptions& options) {
  auto finite_non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!std::isfinite(options.door_ratio) || options.door_ratio <= 0.0)
    throw Error("the door ratio of room merging must be a positive number");
  if (!finite_non_negative(options.width_depth) || !finite_non_negative(options.min_room_area) ||
      !finite_non_negative(options.min_room_width) || !finite_non_negative(options.min_room_thickness) ||
      !finite_non_negative(options.furniture_size))
    throw Error("the room merging depth, minimum room area, width and thickness and the furniture size must be non-negative numbers");
  if (!finite_non_negative(options.step_ratio) || options.step_ratio >= 1.0 || !finite_non_negative(options.step_min_area) ||
      !finite_non_negative(options.step_min_wide_depth) || !finite_non_negative(options.step_wall_line_depth))
    throw Error("the width-step ratio must lie in [0, 1) and its area and depth must be non-negative numbers");
}

PolygonWithHoles union_of_pieces(const std::vector<PolygonWithHoles>& pieces) {
  // Directed edges; an edge met in the other direction too is interior and cancels.
  std::map<Key, int> pending;
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
  // Remaining edges by start point, in a deterministic order.
  std::map<std::pair<double, double>, std::vector<int>> out;
  std::vector<bool> used(edges.size(), true);
  for (const auto& [key, index] : pending) {
    const auto& e = edges[static_cast<std::size_t>(index)];
    out[{e.first.x, e.first.y}].push_back(index);
    used[static_cast<std::size_t>(index)] = false;
  }
  std::vector<Ring> rings;
  for (const auto& [key, first] : pending) {
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
      const auto it = out.find({b.x, b.y});
      int next = -1;
      double best = std::numeric_limits<double>::infinity();
      if (it != out.end()) {
        for (const int candidate : it->second) {
          if (used[static_cast<std::size_t>(candidate)] && candidate != first) continue;
          const double t = turn(a, b, edges[static_cast<std::size_t>(candidate)].second);
          if (t < best) {
            best = t;
            next = candidate;
          }
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

PieceSet merge_rooms(const FreeSpaceComponent& component, const PieceSet& pieces, double resolution,
                     const RoomMergeOptions& options) {
  validate(options);
  if (!std::isfinite(resolution) || resolution <= 0.0) throw Error("the map resolution must be a positive number");
  if (!options.enabled || pieces.pieces.size() < 2) return pieces;
  Merger merger(component.polygon, pieces, resolution, options);
  merger.merge_non_doors();
  merger.fold_small_rooms();
  return merger.result();
}

}  // namespace topocut
