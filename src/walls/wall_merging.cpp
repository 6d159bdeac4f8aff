#include "topocut/walls/wall_merging.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>

#include "topocut/core/error.h"

namespace topocut {

namespace {

// Zeroth, first and second moments of a set of segments, each a uniform mass along its length.
struct Moments {
  double w = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, syy = 0.0;

  void add_segment(const Point2& a, const Point2& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double length = std::hypot(dx, dy);
    const double mx = 0.5 * (a.x + b.x), my = 0.5 * (a.y + b.y);
    w += length;
    sx += length * mx;
    sy += length * my;
    sxx += length * (mx * mx + dx * dx / 12.0);
    sxy += length * (mx * my + dx * dy / 12.0);
    syy += length * (my * my + dy * dy / 12.0);
  }
  void add(const Moments& o) {
    w += o.w;
    sx += o.sx;
    sy += o.sy;
    sxx += o.sxx;
    sxy += o.sxy;
    syy += o.syy;
  }
};

// A line through centre c with unit direction u.
struct FittedLine {
  Point2 c;
  Point2 u;
  double along(const Point2& p) const { return dot(p - c, u); }
  double across(const Point2& p) const { return std::abs(cross(u, p - c)); }
  Point2 at(double t) const { return c + t * u; }
};

FittedLine fit(const Moments& m) {
  FittedLine line;
  line.c = {m.sx / m.w, m.sy / m.w};
  // Centred second moments; the principal axis is the total-least-squares direction.
  const double cxx = m.sxx / m.w - line.c.x * line.c.x;
  const double cxy = m.sxy / m.w - line.c.x * line.c.y;
  const double cyy = m.syy / m.w - line.c.y * line.c.y;
  const double angle = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
  line.u = {std::cos(angle), std::sin(angle)};
  return line;
}

// A wall in the making (or, between rounds, a finished wall taken as one item).
struct Item {
  Moments moments;
  FittedLine line;
  Point2 first, last;        // the extent's end points on the item's line
  std::vector<int> members;  // input segment indices
  double length() const { return distance(first, last); }
};

// Spatial hash of wall extents: cell → wall ids (a wall may appear more than once in a cell).
class WallIndex {
 public:
  explicit WallIndex(double cell) : cell_(cell) {}

  void insert(int id, const Point2& a, const Point2& b, double reach) {
    visit(a, b, reach, [&](std::uint64_t key) {
      auto& ids = cells_[key];
      if (ids.empty() || ids.back() != id) ids.push_back(id);
    });
  }
  template <class F>
  void candidates(const Point2& a, const Point2& b, F&& f) const {
    visit(a, b, 0.0, [&](std::uint64_t key) {
      const auto found = cells_.find(key);
      if (found != cells_.end())
        for (int id : found->second) f(id);
    });
  }

 private:
  static std::uint64_t key(std::int64_t cx, std::int64_t cy) {
    return (static_cast<std::uint64_t>(cx) << 32) ^ static_cast<std::uint64_t>(cy & 0xffffffff);
  }
  // Calls f for the cells within `reach` of the segment (each cell once per call).
  template <class F>
  void visit(const Point2& a, const Point2& b, double reach, F&& f) const {
    const double length = distance(a, b);
    const int steps = std::max(1, static_cast<int>(std::ceil(length / (0.5 * cell_))));
    scratch_.clear();
    for (int s = 0; s <= steps; ++s) {
      const double t = static_cast<double>(s) / steps;
      const Point2 q = a + t * (b - a);
      const auto x0 = static_cast<std::int64_t>(std::floor((q.x - reach) / cell_));
      const auto x1 = static_cast<std::int64_t>(std::floor((q.x + reach) / cell_));
      const auto y0 = static_cast<std::int64_t>(std::floor((q.y - reach) / cell_));
      const auto y1 = static_cast<std::int64_t>(std::floor((q.y + reach) / cell_));
      for (auto cx = x0; cx <= x1; ++cx)
        for (auto cy = y0; cy <= y1; ++cy) scratch_.push_back(key(cx, cy));
    }
    std::sort(scratch_.begin(), scratch_.end());
    scratch_.erase(std::unique(scratch_.begin(), scratch_.end()), scratch_.end());
    const std::vector<std::uint64_t> keys = scratch_;  // f may re-enter visit
    for (std::uint64_t k : keys) f(k);
  }

  double cell_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
  mutable std::vector<std::uint64_t> scratch_;
};

// How far `shorter` lies from `longer`, or a negative value if they must not merge.
double mismatch(const Item& shorter, const Item& longer, const WallMergeOptions& options) {
  const double da = longer.line.across(shorter.first);
  const double db = longer.line.across(shorter.last);
  if (da > options.distance_tolerance || db > options.distance_tolerance) return -1.0;
  if (shorter.length() >= options.short_length) {
    const double cosine = std::abs(dot(shorter.line.u, longer.line.u));
    if (cosine < std::cos(options.angle_tolerance)) return -1.0;
  }
  const double s0 = longer.line.along(shorter.first), s1 = longer.line.along(shorter.last);
  const double t0 = longer.line.along(longer.first), t1 = longer.line.along(longer.last);
  const double gap = std::max({std::min(s0, s1) - std::max(t0, t1), std::min(t0, t1) - std::max(s0, s1), 0.0});
  if (gap > options.gap_tolerance) return -1.0;
  return std::max(da, db);
}

// The extent of the members' end points along the item's line.
void update_extent(Item& item, std::span<const WallSegment> segments) {
  double lo = INFINITY, hi = -INFINITY;
  for (int m : item.members) {
    for (const Point2& p : {segments[static_cast<size_t>(m)].segment.a, segments[static_cast<size_t>(m)].segment.b}) {
      const double t = item.line.along(p);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
  }
  item.first = item.line.at(lo);
  item.last = item.line.at(hi);
}

// One greedy pass: items longest first; each joins the best compatible cluster or starts one.
std::vector<Item> merge_pass(std::vector<Item> items, std::span<const WallSegment> segments,
                             const WallMergeOptions& options) {
  std::vector<size_t> order(items.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return items[a].moments.w > items[b].moments.w; });
  const double reach = std::max(options.distance_tolerance, options.gap_tolerance);
  WallIndex index(options.index_cell);
  std::vector<Item> clusters;
  std::vector<int> stamp;
  int query = 0;
  for (size_t i : order) {
    Item& item = items[i];
    ++query;
    int best = -1;
    double best_score = INFINITY;
    index.candidates(item.first, item.last, [&](int id) {
      if (stamp[static_cast<size_t>(id)] == query) return;
      stamp[static_cast<size_t>(id)] = query;
      const Item& cluster = clusters[static_cast<size_t>(id)];
      const bool item_shorter = item.length() <= cluster.length();
      const double score = item_shorter ? mismatch(item, cluster, options) : mismatch(cluster, item, options);
      if (score >= 0.0 && (score < best_score || (score == best_score && id < best))) {
        best = id;
        best_score = score;
      }
    });
    if (best < 0) {
      best = static_cast<int>(clusters.size());
      clusters.push_back(std::move(item));
      stamp.push_back(0);
    } else {
      Item& cluster = clusters[static_cast<size_t>(best)];
      cluster.moments.add(item.moments);
      cluster.line = fit(cluster.moments);
      cluster.members.insert(cluster.members.end(), item.members.begin(), item.members.end());
      // Keep the extent on the refitted line: the old extremes and the item's, projected.
      double lo = INFINITY, hi = -INFINITY;
      for (const Point2& p : {cluster.first, cluster.last, item.first, item.last}) {
        lo = std::min(lo, cluster.line.along(p));
        hi = std::max(hi, cluster.line.along(p));
      }
      cluster.first = cluster.line.at(lo);
      cluster.last = cluster.line.at(hi);
    }
    const Item& grown = clusters[static_cast<size_t>(best)];
    index.insert(best, grown.first, grown.last, reach);
  }
  for (Item& cluster : clusters) {
    std::sort(cluster.members.begin(), cluster.members.end());
    update_extent(cluster, segments);
  }
  return clusters;
}

}  // namespace

void validate(const WallMergeOptions& o) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!non_negative(o.angle_tolerance) || o.angle_tolerance >= M_PI / 2)
    throw Error("the wall angle tolerance must lie in [0, π/2) radians, got " + std::to_string(o.angle_tolerance));
  if (!non_negative(o.distance_tolerance)) throw Error("the wall distance tolerance must be a non-negative number of metres");
  if (!non_negative(o.gap_tolerance)) throw Error("the wall gap tolerance must be a non-negative number of metres");
  if (!non_negative(o.short_length)) throw Error("the short-segment length must be a non-negative number of metres");
  if (o.max_rounds < 0) throw Error("the number of wall merge rounds must not be negative");
  if (!positive(o.index_cell)) throw Error("the wall index cell must be a positive number of metres");
}

std::vector<Wall> merge_wall_segments(std::span<const WallSegment> segments, const WallMergeOptions& options) {
  validate(options);
  std::vector<Item> items;
  items.reserve(segments.size());
  for (size_t i = 0; i < segments.size(); ++i) {
    const Segment2& s = segments[i].segment;
    if (!std::isfinite(s.a.x) || !std::isfinite(s.a.y) || !std::isfinite(s.b.x) || !std::isfinite(s.b.y)) continue;
    if (s.a == s.b) continue;
    Item item;
    item.moments.add_segment(s.a, s.b);
    item.line = fit(item.moments);
    item.first = s.a;
    item.last = s.b;
    item.members = {static_cast<int>(i)};
    items.push_back(std::move(item));
  }
  items = merge_pass(std::move(items), segments, options);
  for (int round = 0; round < options.max_rounds; ++round) {
    const size_t before = items.size();
    items = merge_pass(std::move(items), segments, options);
    if (items.size() == before) break;
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.members.front() < b.members.front(); });
  std::vector<Wall> walls;
  walls.reserve(items.size());
  for (Item& item : items) {
    Wall wall;
    wall.segment = {item.first, item.last};
    wall.weight = item.moments.w;
    wall.observations = static_cast<int>(item.members.size());
    wall.members = std::move(item.members);
    walls.push_back(std::move(wall));
  }
  return walls;
}

}  // namespace topocut
