#include "topocut/lines/smf.h"

#include <algorithm>
#include <array>
#include <set>
#include <cmath>
#include <limits>

#include "lines/centre_index.h"
#include "lines/common.h"
#include "topocut/core/error.h"

namespace topocut {

namespace {

using Set = std::vector<std::size_t>;  // positions into the valid points, increasing

Moments moments_of(const std::vector<ScanPoint>& points, const Set& set) {
  Moments m;
  for (const std::size_t k : set) m.add(points[k].point);
  return m;
}

// The initial partition of a fuzzy split: at the point farthest from the chord between the set's
// first and last points (the corner of an L-shaped set), or in halves when there is no such point.
std::size_t initial_cut(const std::vector<ScanPoint>& points, const Set& set) {
  const Point2& a = points[set.front()].point;
  const Point2& b = points[set.back()].point;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len = std::hypot(dx, dy);
  double worst = 0.0;
  std::size_t at = set.size() / 2;
  for (std::size_t i = 1; i + 1 < set.size(); ++i) {
    const Point2& p = points[set[i]].point;
    const double d = len > 0.0 ? std::abs(dx * (p.y - a.y) - dy * (p.x - a.x)) / len : distance(a, p);
    if (d > worst) worst = d, at = i;
  }
  return std::clamp<std::size_t>(at, 1, set.size() - 1);  // both parts non-empty
}

// Splits a set in two with fuzzy c-lines (C = 2). Returns the two crisp parts (both non-empty).
std::pair<Set, Set> fuzzy_split(const std::vector<ScanPoint>& points, const Set& set, const SmfOptions& options,
                                detail::SplitBudget& budget) {
  const std::size_t n = set.size();
  const std::size_t cut = initial_cut(points, set);
  Set crisp_a(set.begin(), set.begin() + static_cast<std::ptrdiff_t>(cut));
  Set crisp_b(set.begin() + static_cast<std::ptrdiff_t>(cut), set.end());
  NormalForm na = moments_of(points, crisp_a).normal_form();
  NormalForm nb = moments_of(points, crisp_b).normal_form();

  // With the paper's m = 2 the memberships need no pow: u_a = d_b^2 / (d_a^2 + d_b^2), weight u^2.
  const bool m2 = options.fuzzifier == 2.0;
  const double exponent = 2.0 / (options.fuzzifier - 1.0);
  std::vector<double> u(n, 0.0);  // membership in line a (line b has 1 - u)
  for (std::size_t i = 0; i < n; ++i) u[i] = i < cut ? 1.0 : 0.0;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    budget.spend(n);
    double change = 0.0;
    Moments ma, mb;
    for (std::size_t i = 0; i < n; ++i) {
      const Point2& p = points[set[i]].point;
      const double da = na.distance(p), db = nb.distance(p);
      double ua;
      if (da == 0.0 && db == 0.0) ua = 0.5;
      else if (da == 0.0) ua = 1.0;
      else if (db == 0.0) ua = 0.0;
      else if (m2) ua = db * db / (da * da + db * db);
      else ua = 1.0 / (1.0 + std::pow(da / db, exponent));
      change = std::max(change, std::abs(ua - u[i]));
      u[i] = ua;
      const double ub = 1.0 - ua;
      ma.add(p, m2 ? ua * ua : std::pow(ua, options.fuzzifier));
      mb.add(p, m2 ? ub * ub : std::pow(ub, options.fuzzifier));
    }
    if (ma.n <= 0.0 || mb.n <= 0.0) break;
    na = ma.normal_form();
    nb = mb.normal_form();
    if (change < options.tolerance) break;
  }
  Set a, b;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& p = points[set[i]].point;
    (na.distance(p) <= nb.distance(p) ? a : b).push_back(set[i]);
  }
  // Both lines collapsed onto one: fall back to the initial partition so the split makes progress.
  if (a.empty() || b.empty()) return {std::move(crisp_a), std::move(crisp_b)};
  return {std::move(a), std::move(b)};
}

struct Cluster {
  Set set;
  Moments moments;
  Point2 centre() const { return {moments.sx / moments.n, moments.sy / moments.n}; }
};

// The paper's merge: while some line can be fused with the better (lower fused sigma) of its two
// nearest lines by centre of gravity within sigma_max, the first such line in scan order is fused
// (into the earlier of the two) and the search starts again from the first line. The lines that
// were tried and could not merge are remembered as settled until one of their two nearest changes
// (merged away, moved, or a fused centre comes nearer), so each fusion re-examines only those
// instead of starting over: the same fusions in the same order, in about n log n instead of n^2.
void merge_phase(std::vector<Cluster>& clusters, double sigma_max) {
  const int n = static_cast<int>(clusters.size());
  std::vector<Point2> centres;
  for (const Cluster& c : clusters) centres.push_back(c.centre());
  detail::CentreIndex index(std::move(centres));
  std::vector<char> live(clusters.size(), 1);
  std::vector<std::array<int, 2>> nearest(clusters.size(), {-1, -1});
  std::vector<std::vector<int>> nearest_of(clusters.size());  // who had this one among their two nearest
  std::vector<int> next(clusters.size(), -1), last(clusters.size());  // each live cluster's list of members
  std::set<int> unsettled;
  for (int i = 0; i < n; ++i) unsettled.insert(i), last[i] = i;
  std::vector<int> reached;
  while (!unsettled.empty()) {
    const int i = *unsettled.begin();
    unsettled.erase(unsettled.begin());
    if (!live[i]) continue;
    nearest[i] = index.nearest_two(i);
    int best = -1;
    double best_sigma = std::numeric_limits<double>::infinity();
    for (const int j : nearest[i]) {
      if (j < 0) continue;
      nearest_of[j].push_back(i);
      const double sigma = (clusters[i].moments + clusters[j].moments).sigma();
      if (sigma < best_sigma) best_sigma = sigma, best = j;
    }
    const Point2 centre = clusters[i].centre();
    index.set_reach(i, nearest[i][1] >= 0 ? distance(centre, clusters[nearest[i][1]].centre())
                                          : std::numeric_limits<double>::infinity());
    if (best < 0 || best_sigma > sigma_max) continue;  // settled
    const int keep = std::min(i, best), gone = std::max(i, best);
    Cluster& kept = clusters[keep];
    kept.moments = kept.moments + clusters[gone].moments;
    next[last[keep]] = gone;  // the members join in a list; their points are gathered at the end
    last[keep] = last[gone];
    live[gone] = 0;
    index.remove(gone);
    index.move(keep, kept.centre());
    index.set_reach(keep, -std::numeric_limits<double>::infinity());
    unsettled.insert(keep);
    for (const int changed : {keep, gone}) {
      for (const int c : nearest_of[changed])
        if (live[c] && (nearest[c][0] == changed || nearest[c][1] == changed)) unsettled.insert(c);
      nearest_of[changed].clear();
    }
    reached.clear();
    index.within_reach(kept.centre(), reached);
    for (const int c : reached) unsettled.insert(c);
  }
  // Each point's line, then the points in order: every set increasing, in one pass over the points.
  std::vector<Cluster> merged;
  std::vector<int> owner;
  for (int i = 0; i < n; ++i) {
    if (!live[i]) continue;
    for (int member = i; member >= 0; member = next[member])
      for (const std::size_t k : clusters[member].set) {
        if (k >= owner.size()) owner.resize(k + 1, -1);
        owner[k] = static_cast<int>(merged.size());
      }
    merged.push_back({{}, clusters[i].moments});
  }
  for (std::size_t k = 0; k < owner.size(); ++k)
    if (owner[k] >= 0) merged[static_cast<std::size_t>(owner[k])].set.push_back(k);
  clusters = std::move(merged);
}

}  // namespace

std::vector<Line> extract_lines_smf(const Scan& scan, const SmfOptions& options) {
  detail::require_positive(options.sigma_max, "sigma_max");
  if (!std::isfinite(options.fuzzifier) || options.fuzzifier <= 1.0)
    throw Error("the SMF fuzzifier m must be greater than 1");
  if (options.max_iterations < 1) throw Error("the SMF clustering needs at least one iteration");
  const std::vector<ScanPoint> points = detail::prepared_points(scan);

  std::vector<Cluster> clusters;
  std::vector<Set> stack;
  detail::SplitBudget budget("SMF");
  const std::vector<PointRun> runs = split_at_breakpoints(scan, points, options.breakpoints);
  for (const PointRun& run : runs) {
    Set set(run.size());
    for (std::size_t k = 0; k < run.size(); ++k) set[k] = run.first + k;
    stack.push_back(std::move(set));
    // Depth-first, first part first: clusters come out roughly in scan order.
    while (!stack.empty()) {
      Set s = std::move(stack.back());
      stack.pop_back();
      budget.spend(s.size());
      const Moments m = moments_of(points, s);
      if (s.size() <= 2 || m.sigma() <= options.sigma_max) {
        clusters.push_back({std::move(s), m});
        continue;
      }
      auto [a, b] = fuzzy_split(points, s, options, budget);
      stack.push_back(std::move(b));
      stack.push_back(std::move(a));
    }
  }
  if (options.merge) merge_phase(clusters, options.sigma_max);

  // Ours, not the paper's: a set is accepted as soon as sigma <= sigma_max, so a few points of the
  // neighbouring wall can stay in it (and skew it). As in the sequential methods, points move to the
  // line of a scan neighbour that they fit better.
  {
    std::vector<int> labels(points.size(), -1);
    std::vector<Moments> moments;
    for (std::size_t c = 0; c < clusters.size(); ++c) {
      for (const std::size_t k : clusters[c].set) labels[k] = static_cast<int>(c);
      moments.push_back(clusters[c].moments);
    }
    std::vector<bool> joined(points.size(), false);
    for (const PointRun& run : runs)
      for (std::size_t k = run.first; k < run.last; ++k) joined[k] = true;
    detail::refine_labels(points, joined, labels, moments);
    for (Cluster& c : clusters) c.set.clear();
    for (std::size_t k = 0; k < points.size(); ++k)
      if (labels[k] >= 0) clusters[static_cast<std::size_t>(labels[k])].set.push_back(k);
  }

  std::vector<Line> lines;
  for (const Cluster& c : clusters) {
    if (c.set.size() < std::max<std::size_t>(options.min_points, 2)) continue;
    lines.push_back(detail::line_from_positions(points, c.set));
  }
  std::sort(lines.begin(), lines.end(),
            [](const Line& a, const Line& b) { return a.support.front() < b.support.front(); });
  return lines;
}

}  // namespace topocut
