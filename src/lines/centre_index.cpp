#include "lines/centre_index.h"

#include <algorithm>
#include <cmath>

#include "topocut/core/infinity.h"

namespace topocut::detail {

namespace {

constexpr int kLeafSize = 8;
// Box distances are compared with this slack, so that rounding never prunes a centre at the same
// distance (a tie that the lower id wins).
constexpr double kSlack = 1e-12;

}  // namespace

CentreIndex::CentreIndex(std::vector<Point2> centres)
    : centre_(std::move(centres)),
      reach_(centre_.size(), -kInfinity),
      live_(centre_.size(), 1),
      leaf_of_(centre_.size(), -1),
      live_count_(static_cast<int>(centre_.size())) {
  rebuild();
}

void CentreIndex::rebuild() {
  std::vector<int> ids;
  for (int id = 0; id < static_cast<int>(centre_.size()); ++id)
    if (live_[id]) ids.push_back(id);
  nodes_.clear();
  changes_ = 0;
  if (!ids.empty()) build(ids.begin(), ids.end(), -1);
}

int CentreIndex::build(std::vector<int>::iterator first, std::vector<int>::iterator last, int parent) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Node node;
  node.parent = parent;
  node.min_x = node.min_y = kInfinity;
  node.max_x = node.max_y = node.max_reach = -kInfinity;
  for (auto it = first; it != last; ++it) {
    const Point2& c = centre_[*it];
    node.min_x = std::min(node.min_x, c.x), node.max_x = std::max(node.max_x, c.x);
    node.min_y = std::min(node.min_y, c.y), node.max_y = std::max(node.max_y, c.y);
    node.max_reach = std::max(node.max_reach, reach_[*it]);
  }
  node.live = static_cast<int>(last - first);
  if (last - first > kLeafSize) {
    node.by_x = node.max_x - node.min_x >= node.max_y - node.min_y;
    const auto mid = first + (last - first) / 2;
    const auto coordinate = [&](int id) { return node.by_x ? centre_[id].x : centre_[id].y; };
    std::nth_element(first, mid, last, [&](int a, int b) { return coordinate(a) < coordinate(b); });
    node.split = coordinate(*mid);
    node.left = build(first, mid, index);
    node.right = build(mid, last, index);
  } else {
    node.items.assign(first, last);
    for (auto it = first; it != last; ++it) leaf_of_[*it] = index;
  }
  nodes_[index] = std::move(node);
  return index;
}

// Takes id's entry out of the live counts on the way to the root (the entry itself stays listed).
void CentreIndex::unlist(int id) {
  for (int node = leaf_of_[id]; node >= 0; node = nodes_[node].parent) --nodes_[node].live;
  leaf_of_[id] = -1;
}

// Into the leaf whose region holds the centre; the boxes and reach bounds on the way grow to cover it.
void CentreIndex::insert(int id) {
  const Point2& c = centre_[id];
  int at = 0;
  while (true) {
    Node& node = nodes_[at];
    node.min_x = std::min(node.min_x, c.x), node.max_x = std::max(node.max_x, c.x);
    node.min_y = std::min(node.min_y, c.y), node.max_y = std::max(node.max_y, c.y);
    node.max_reach = std::max(node.max_reach, reach_[id]);
    ++node.live;
    if (node.left < 0) break;
    at = (node.by_x ? c.x : c.y) < node.split ? node.left : node.right;
  }
  std::vector<int>& items = nodes_[at].items;
  if (std::find(items.begin(), items.end(), id) == items.end()) items.push_back(id);  // listed once
  leaf_of_[id] = at;
}

// The squared distance from p to the node's box, shrunk by the slack.
double CentreIndex::box_distance(const Node& node, const Point2& p) const {
  const double dx = std::max({node.min_x - p.x, 0.0, p.x - node.max_x});
  const double dy = std::max({node.min_y - p.y, 0.0, p.y - node.max_y});
  return (dx * dx + dy * dy) * (1.0 - kSlack);
}

void CentreIndex::offer(int id, int candidate, std::array<int, 2>& best, std::array<double, 2>& best_d) const {
  if (candidate == id) return;
  const double d = distance(centre_[id], centre_[candidate]);
  const auto before = [&](int k) { return d < best_d[k] || (d == best_d[k] && candidate < best[k]); };
  if (before(0)) {
    best[1] = best[0], best_d[1] = best_d[0];
    best[0] = candidate, best_d[0] = d;
  } else if (before(1)) {
    best[1] = candidate, best_d[1] = d;
  }
}

std::array<int, 2> CentreIndex::nearest_two(int id) const {
  std::array<int, 2> best = {-1, -1};
  std::array<double, 2> best_d = {kInfinity, kInfinity};
  if (nodes_.empty()) return best;
  const Point2& p = centre_[id];
  std::vector<std::pair<int, double>> stack = {{0, 0.0}};  // node, squared box distance
  while (!stack.empty()) {
    const auto [at, box] = stack.back();
    stack.pop_back();
    const Node& node = nodes_[at];
    if (node.live == 0 || box > best_d[1] * best_d[1]) continue;
    if (node.left < 0) {
      for (const int item : node.items)
        if (listed(item, at)) offer(id, item, best, best_d);
      continue;
    }
    // The nearer child last, so that it is searched first.
    const double left = box_distance(nodes_[node.left], p), right = box_distance(nodes_[node.right], p);
    if (left <= right) {
      stack.push_back({node.right, right});
      stack.push_back({node.left, left});
    } else {
      stack.push_back({node.left, left});
      stack.push_back({node.right, right});
    }
  }
  return best;
}

void CentreIndex::set_reach(int id, double reach) {
  reach_[id] = reach;
  if (!live_[id]) return;
  for (int node = leaf_of_[id]; node >= 0 && nodes_[node].max_reach < reach; node = nodes_[node].parent)
    nodes_[node].max_reach = reach;
}

void CentreIndex::remove(int id) {
  if (!live_[id]) return;
  unlist(id);
  live_[id] = 0;
  --live_count_;
  if (++changes_ > 2 * live_count_ + kLeafSize) rebuild();
}

void CentreIndex::move(int id, const Point2& centre) {
  centre_[id] = centre;
  if (++changes_ > 2 * live_count_ + kLeafSize) {
    rebuild();
  } else {
    unlist(id);  // its old entry stays in its old leaf, skipped: leaf_of_ no longer names that leaf
    insert(id);
  }
}

void CentreIndex::within_reach(const Point2& p, std::vector<int>& out) const {
  if (nodes_.empty()) return;
  std::vector<int> stack = {0};
  while (!stack.empty()) {
    const int at = stack.back();
    const Node& node = nodes_[at];
    stack.pop_back();
    if (node.live == 0 || node.max_reach < 0 || box_distance(node, p) > node.max_reach * node.max_reach) continue;
    if (node.left >= 0) {
      stack.push_back(node.left);
      stack.push_back(node.right);
      continue;
    }
    for (const int id : node.items)
      if (listed(id, at) && distance(centre_[id], p) <= reach_[id]) out.push_back(id);
  }
}

}  // namespace topocut::detail
