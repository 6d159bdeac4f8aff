// §5.4-6.4: cut sets per pocket minimum, their weights, and the selection of the cuts of a pass.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "decomposition/pass_state.h"

namespace topocut::dude {

namespace {

enum class SetType { kSinglePm, kSingleTip, kDoublePmPm, kDoublePmTip, kDoubleTipTip };

struct CutSet {
  int pm = -1;
  int nd = 0;
  int d[2] = {-1, -1};  // diagonal indices, d[0] < d[1] for doubles
  SetType type = SetType::kSingleTip;
  int rs = 1;
  int res[3] = {-1, -1, -1};  // pocket minima this set resolves (its own first)
  int nres = 0;
  double length = 0.0;
  double weight = 0.0;

  std::uint64_t key() const {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(d[0])) << 32) |
           static_cast<std::uint32_t>(nd == 2 ? d[1] : -1);
  }
  bool has(int diag) const { return d[0] == diag || (nd == 2 && d[1] == diag); }
};

class CutSetBuilder {
 public:
  CutSetBuilder(const PassState& st, const std::vector<std::pair<int, int>>& diagonals)
      : st_(st), poly_(st.poly), diagonals_(diagonals), at_(st.poly.corners()) {
    for (int i = 0; i < static_cast<int>(diagonals.size()); ++i) {
      at_[diagonals[i].first].push_back(i);
      at_[diagonals[i].second].push_back(i);
    }
  }

  int other(int diag, int v) const {
    return diagonals_[diag].first == v ? diagonals_[diag].second : diagonals_[diag].first;
  }
  double length(int diag) const { return dist(poly_.pt[diagonals_[diag].first], poly_.pt[diagonals_[diag].second]); }
  int pre(int v) const { return st_.dpre[v] >= 0 ? st_.dpre[v] : poly_.prev(v); }
  int nxt(int v) const { return st_.dnext[v] >= 0 ? st_.dnext[v] : poly_.next(v); }
  const Pt& p(int c) const { return poly_.pt[c]; }

  // §5.3 last filter: the diagonal lies in the wedge between the simplified neighbours.
  bool in_s_wedge(int v, int o) const {
    const Pt& a = p(pre(v));
    if (cw_class(p(v), a, p(o)) == 0) return false;
    return cw_compare(p(v), a, p(o), p(nxt(v))) <= 0;
  }
  // A sub-angle at v from ray v->a clockwise to ray v->b is fine when it is below pi, or when the
  // residual concavity of v with respect to segment ab is at most tau (§5.4).
  bool sub_ok(int v, int a, int b) const {
    return cw_class(p(v), p(a), p(b)) == 1 || dseg(p(v), p(a), p(b)) <= st_.tau();
  }
  bool resolves_single(int v, int o) const {
    return in_s_wedge(v, o) && sub_ok(v, pre(v), o) && sub_ok(v, o, nxt(v));
  }
  double c(int v) const { return st_.pm[v] ? st_.concavity[v] : 0.0; }

  // Builds the kept cut sets of pocket minimum v (§5.5) and appends them to `out`.
  void build(int v, std::vector<CutSet>& out) const {
    std::vector<int> cand;
    for (int d : at_[v]) {
      if (in_s_wedge(v, other(d, v))) cand.push_back(d);
    }
    if (cand.empty()) return;
    const Pt& ref = p(pre(v));
    std::sort(cand.begin(), cand.end(), [&](int x, int y) {
      const int cmp = cw_compare(p(v), ref, p(other(x, v)), p(other(y, v)));
      return cmp != 0 ? cmp < 0 : x < y;
    });
    const int n = static_cast<int>(cand.size());
    std::vector<char> first(n), last(n), single(n);
    for (int i = 0; i < n; ++i) {
      const int o = other(cand[i], v);
      first[i] = sub_ok(v, pre(v), o);
      last[i] = sub_ok(v, o, nxt(v));
      single[i] = first[i] && last[i];
    }
    std::vector<CutSet> singles_pm, doubles_pm_pm, doubles_pm_tip_rs2;
    CutSet best_single_tip, best_pm_tip, best_tip_tip;
    best_single_tip.pm = best_pm_tip.pm = best_tip_tip.pm = -1;

    for (int i = 0; i < n; ++i) {
      if (!single[i]) continue;
      CutSet s = make({cand[i]}, v);
      if (s.type == SetType::kSinglePm) {
        singles_pm.push_back(s);
      } else if (best_single_tip.pm < 0 || s.length < best_single_tip.length) {
        best_single_tip = s;
      }
    }
    for (int i = 0; i < n; ++i) {
      if (single[i] || !first[i]) continue;
      for (int j = i + 1; j < n; ++j) {
        if (single[j] || !last[j]) continue;
        if (!sub_ok(v, other(cand[i], v), other(cand[j], v))) continue;
        CutSet s = make({std::min(cand[i], cand[j]), std::max(cand[i], cand[j])}, v);
        switch (s.type) {
          case SetType::kDoublePmPm:
            doubles_pm_pm.push_back(s);
            break;
          case SetType::kDoublePmTip:
            if (s.rs == 2) {
              doubles_pm_tip_rs2.push_back(s);
            } else if (best_pm_tip.pm < 0 || s.length < best_pm_tip.length) {
              best_pm_tip = s;
            }
            break;
          default:
            if (best_tip_tip.pm < 0 || s.length < best_tip_tip.length) best_tip_tip = s;
        }
      }
    }
    const std::size_t before = out.size();
    out.insert(out.end(), singles_pm.begin(), singles_pm.end());
    if (best_single_tip.pm >= 0) out.push_back(best_single_tip);
    out.insert(out.end(), doubles_pm_pm.begin(), doubles_pm_pm.end());
    out.insert(out.end(), doubles_pm_tip_rs2.begin(), doubles_pm_tip_rs2.end());
    if (best_pm_tip.pm >= 0) out.push_back(best_pm_tip);
    if (best_tip_tip.pm >= 0) out.push_back(best_tip_tip);
    if (out.size() > before) return;

    // §5.5.4 fallback: the best single diagonal, weighted with one less resolved vertex.
    CutSet best;
    for (int i = 0; i < n; ++i) {
      CutSet s = make({cand[i]}, v, 1);
      if (best.pm < 0 || s.weight > best.weight) best = s;
    }
    out.push_back(best);
  }

 private:
  CutSet make(std::initializer_list<int> diags, int v, int rs_reduction = 0) const {
    CutSet s;
    s.pm = v;
    for (int d : diags) {
      s.d[s.nd++] = d;
      s.length += length(d);
    }
    s.res[s.nres++] = v;
    int pm_ends = 0;
    bool resolved[2] = {false, false};
    for (int i = 0; i < s.nd; ++i) {
      const int o = other(s.d[i], v);
      if (!st_.pm[o]) continue;
      ++pm_ends;
      resolved[i] = resolves_single(o, v);
      if (resolved[i]) s.res[s.nres++] = o;
    }
    s.rs = s.nres - rs_reduction;
    if (s.nd == 1) {
      s.type = pm_ends ? SetType::kSinglePm : SetType::kSingleTip;
    } else {
      s.type = pm_ends == 2 ? SetType::kDoublePmPm : pm_ends == 1 ? SetType::kDoublePmTip : SetType::kDoubleTipTip;
    }
    // §5.6 weights: resolved concavity per unit cut length, half credit for touched minima.
    const double cv = c(v);
    double w = 0.0;
    if (s.nd == 1) {
      const int o = other(s.d[0], v);
      if (s.rs == 2) {
        w = cv + c(o);
      } else if (s.rs == 1) {
        w = cv + 0.5 * c(o);
      } else {
        w = 0.5 * cv + 0.5 * c(o);
      }
    } else {
      const int o1 = other(s.d[0], v), o2 = other(s.d[1], v);
      if (s.rs == 3) {
        w = 2 * cv + c(o1) + c(o2);
      } else if (s.rs == 2) {
        const int res = resolved[0] ? o1 : o2;
        const int oth = resolved[0] ? o2 : o1;
        w = cv + c(res) + (s.type == SetType::kDoublePmPm ? 0.5 * c(oth) : 0.0);
      } else {
        w = cv + 0.5 * c(o1) + 0.5 * c(o2);
      }
    }
    s.weight = s.length > 0 ? w / s.length : 0.0;
    if (rs_reduction) s.nres = 1;  // a fallback set does not really resolve anything but its minimum's claim
    return s;
  }

  const PassState& st_;
  const Poly& poly_;
  const std::vector<std::pair<int, int>>& diagonals_;
  std::vector<std::vector<int>> at_;
};

class Selector {
 public:
  Selector(const CutSetBuilder& b, const std::vector<std::pair<int, int>>& diagonals, std::vector<CutSet> sets)
      : b_(b), diagonals_(diagonals), sets_(std::move(sets)) {
    for (const CutSet& s : sets_) own_[s.pm].insert(s.key());
  }

  // §6.1 conflict relation.
  bool conflict(const CutSet& x, const CutSet& y) const {
    if (x.pm == y.pm) return true;
    if (x.nd == 2 && y.nd == 2) return false;
    if (x.nd == 1 && y.nd == 1 && x.d[0] == y.d[0]) return false;
    if (x.nd == 1 && y.has(x.d[0])) return false;
    if (y.nd == 1 && x.has(y.d[0])) return false;
    return claims(y, x.pm) || claims(x, y.pm);
  }

  // Greedy selection (§6.4).
  std::vector<int> greedy() const {
    const int m = static_cast<int>(sets_.size());
    std::vector<int> order(m);
    for (int i = 0; i < m; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int i, int j) { return better(i, j); });
    std::vector<int> chosen;
    std::unordered_map<int, std::vector<int>> by_vertex;  // accepted sets by their minimum and diagonal ends
    auto conflicts_with_chosen = [&](int i) {
      const CutSet& x = sets_[i];
      std::vector<int> near;
      auto gather = [&](int v) {
        const auto it = by_vertex.find(v);
        if (it != by_vertex.end()) near.insert(near.end(), it->second.begin(), it->second.end());
      };
      gather(x.pm);
      for (int k = 0; k < x.nd; ++k) {
        gather(diagonals_[x.d[k]].first);
        gather(diagonals_[x.d[k]].second);
      }
      for (int j : near) {
        if (conflict(x, sets_[j])) return true;
      }
      return false;
    };
    auto accept = [&](int i) {
      chosen.push_back(i);
      const CutSet& x = sets_[i];
      std::vector<int> vs{x.pm};
      for (int k = 0; k < x.nd; ++k) {
        vs.push_back(diagonals_[x.d[k]].first);
        vs.push_back(diagonals_[x.d[k]].second);
      }
      std::sort(vs.begin(), vs.end());
      vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
      for (int v : vs) by_vertex[v].push_back(i);
    };
    for (int i : order) {
      if (!conflicts_with_chosen(i)) accept(i);
    }
    // Step 3: minima left unresolved get their best set when it fits.
    std::unordered_map<int, int> resolvers;
    for (int i : chosen) {
      for (int k = 0; k < sets_[i].nres; ++k) ++resolvers[sets_[i].res[k]];
    }
    for (int i : order) {
      const CutSet& x = sets_[i];
      if (resolvers[x.pm] > 0) continue;
      if (best_of_pm(x.pm) != i) continue;
      if (conflicts_with_chosen(i)) continue;
      accept(i);
      for (int k = 0; k < x.nres; ++k) ++resolvers[x.res[k]];
    }
    // Step 4: drop sets made redundant by others, lowest weight first.
    std::vector<int> by_weight = chosen;
    std::sort(by_weight.begin(), by_weight.end(), [&](int i, int j) { return better(j, i); });
    std::vector<char> dropped(m, 0);
    for (int i : by_weight) {
      const CutSet& x = sets_[i];
      bool redundant = x.nres > 0;
      for (int k = 0; k < x.nres; ++k) redundant = redundant && resolvers[x.res[k]] >= 2;
      if (!redundant) continue;
      dropped[i] = 1;
      for (int k = 0; k < x.nres; ++k) --resolvers[x.res[k]];
    }
    std::vector<int> result;
    for (int i : chosen) {
      if (!dropped[i]) result.push_back(i);
    }
    return result;
  }

  // The reference's knapsack-like DP (§6.2) followed by its pruning (§6.3).
  std::vector<int> reference() const {
    const int m = static_cast<int>(sets_.size());
    if (m == 0) return {};
    std::unordered_set<int> distinct;
    for (const CutSet& s : sets_) {
      for (int k = 0; k < s.nd; ++k) distinct.insert(s.d[k]);
    }
    const int n_max = static_cast<int>(distinct.size());
    struct Cell {
      std::vector<int> items;
      double score = 0.0;
    };
    auto diagonal_count = [&](const std::vector<int>& items) {
      std::vector<int> ds;
      for (int i : items) {
        for (int k = 0; k < sets_[i].nd; ++k) ds.push_back(sets_[i].d[k]);
      }
      std::sort(ds.begin(), ds.end());
      return static_cast<int>(std::unique(ds.begin(), ds.end()) - ds.begin());
    };
    auto insert = [&](const Cell& cell, int x) {
      Cell out;
      for (int i : cell.items) {
        if (!conflict(sets_[i], sets_[x])) {
          out.items.push_back(i);
          out.score += sets_[i].weight;
        }
      }
      out.items.push_back(x);
      out.score += sets_[x].weight;
      return out;
    };
    // Only rows n, n-1 and n-2 are ever read (a cut set has at most two diagonals).
    std::vector<std::vector<Cell>> rows(3, std::vector<Cell>(m));
    auto row = [&](int n) -> std::vector<Cell>& { return rows[((n % 3) + 3) % 3]; };
    const Cell empty;
    std::vector<double> final_scores;
    int last = 0;
    for (int n = 1; n <= n_max; ++n) {
      std::vector<Cell>& t = row(n);
      for (Cell& c : t) c = Cell();
      for (int it = 0;; ++it) {
        bool changed = false;
        for (int x = 0; x < m; ++x) {
          if (x == 0 && it == 0) {
            t[0] = sets_[0].nd <= n ? insert(empty, 0) : Cell();
            continue;
          }
          const int q = x > 0 ? x - 1 : m - 1;
          Cell candidate;
          bool have = false;
          for (int k = n; k >= std::max(0, n - sets_[x].nd); --k) {
            const Cell& base = k == 0 ? empty : row(k)[q];
            Cell s = insert(base, x);
            if (diagonal_count(s.items) <= n && (!have || s.score > candidate.score)) {
              candidate = std::move(s);
              have = true;
            }
          }
          const Cell skip = t[q];
          Cell next = (!have || skip.score > candidate.score) ? skip : candidate;
          if (next.score != t[x].score) changed = true;
          t[x] = std::move(next);
        }
        if (!changed && it + 1 >= 3) break;
        if (it > 50) break;  // the sweep is a heuristic fix point; never loop forever
      }
      final_scores.push_back(t[m - 1].score);
      last = n;
      const int f = static_cast<int>(final_scores.size());
      if (n >= 3 && final_scores[f - 1] == final_scores[f - 2] && final_scores[f - 2] == final_scores[f - 3]) break;
    }
    std::vector<int> picked = row(last)[m - 1].items;
    return prune(picked);
  }

  const CutSet& set(int i) const { return sets_[i]; }

 private:
  // True when one of y's diagonals ends at x and y is also one of x's own candidate sets (§6.1.5).
  bool claims(const CutSet& y, int x) const {
    bool ends_at_x = false;
    for (int k = 0; k < y.nd; ++k) {
      ends_at_x = ends_at_x || diagonals_[y.d[k]].first == x || diagonals_[y.d[k]].second == x;
    }
    if (!ends_at_x) return false;
    const auto it = own_.find(x);
    return it != own_.end() && it->second.count(y.key()) > 0;
  }

  // Order of preference: weight, then shorter cuts, then geometry (points), then indices.
  bool better(int i, int j) const {
    const CutSet& x = sets_[i];
    const CutSet& y = sets_[j];
    if (x.weight != y.weight) return x.weight > y.weight;
    if (x.length != y.length) return x.length < y.length;
    const Pt& px = b_.p(x.pm);
    const Pt& py = b_.p(y.pm);
    if (px != py) return px < py;
    for (int k = 0; k < std::min(x.nd, y.nd); ++k) {
      const Pt& ox = b_.p(b_.other(x.d[k], x.pm));
      const Pt& oy = b_.p(b_.other(y.d[k], y.pm));
      if (ox != oy) return ox < oy;
    }
    return i < j;
  }

  int best_of_pm(int v) const {
    int best = -1;
    for (int i = 0; i < static_cast<int>(sets_.size()); ++i) {
      if (sets_[i].pm == v && (best < 0 || better(i, best))) best = i;
    }
    return best;
  }

  std::vector<int> prune(std::vector<int> picked) const {
    // 1. duplicates
    std::sort(picked.begin(), picked.end());
    std::vector<int> unique;
    std::unordered_set<std::uint64_t> keys;
    for (int i : picked) {
      if (keys.insert(sets_[i].key()).second) unique.push_back(i);
    }
    // 2. resolvers per minimum
    std::unordered_map<int, std::vector<int>> resolvers;
    std::vector<int> minima;
    for (const CutSet& s : sets_) minima.push_back(s.pm);
    std::sort(minima.begin(), minima.end());
    minima.erase(std::unique(minima.begin(), minima.end()), minima.end());
    for (int i : unique) {
      for (int k = 0; k < sets_[i].nres; ++k) resolvers[sets_[i].res[k]].push_back(i);
    }
    enum Flag { kNone, kKeep, kRemoved };
    std::unordered_map<int, Flag> flag;
    for (int i : unique) flag[i] = kNone;
    for (const auto& [v, list] : resolvers) {
      if (list.size() == 1) flag[list[0]] = kKeep;
    }
    auto can_remove = [&](int i) {
      for (int k = 0; k < sets_[i].nres; ++k) {
        int alive = 0;
        for (int j : resolvers[sets_[i].res[k]]) alive += flag[j] != kRemoved;
        if (alive < 2) return false;
      }
      return true;
    };
    std::vector<int> missing;
    for (int v : minima) {
      const auto it = resolvers.find(v);
      if (it == resolvers.end() || it->second.empty()) {
        const int best = best_of_pm(v);
        if (best >= 0) missing.push_back(best);
        continue;
      }
      if (it->second.size() < 2) continue;
      std::vector<int> r, c;
      for (int j : it->second) {
        if (flag[j] != kRemoved) r.push_back(j);
        if (flag[j] == kNone) c.push_back(j);
      }
      if (r.size() <= 1 || c.empty()) continue;
      if (r.size() > c.size()) {
        for (int j : c) {
          if (can_remove(j)) flag[j] = kRemoved;
        }
      } else {
        const int best = *std::min_element(c.begin(), c.end(), [&](int x, int y) { return better(x, y); });
        flag[best] = kKeep;
        for (int j : c) {
          if (j != best && can_remove(j)) flag[j] = kRemoved;
        }
      }
    }
    std::vector<int> result;
    for (int i : unique) {
      if (flag[i] == kKeep) result.push_back(i);
    }
    result.insert(result.end(), missing.begin(), missing.end());
    return result;
  }

  const CutSetBuilder& b_;
  const std::vector<std::pair<int, int>>& diagonals_;
  std::vector<CutSet> sets_;
  std::unordered_map<int, std::unordered_set<std::uint64_t>> own_;
};

}  // namespace

std::vector<std::pair<int, int>> select_cuts(const PassState& st, const std::vector<std::pair<int, int>>& diagonals) {
  CutSetBuilder builder(st, diagonals);
  std::vector<CutSet> sets;
  for (int v = 0; v < st.poly.corners(); ++v) {
    if (st.pm[v]) builder.build(v, sets);
  }
  if (sets.empty()) return {};
  const bool reference = st.settings.options.selection == CutSelection::kReference &&
                         static_cast<int>(sets.size()) <= st.settings.options.reference_selection_limit;
  Selector selector(builder, diagonals, std::move(sets));
  const std::vector<int> chosen = reference ? selector.reference() : selector.greedy();
  std::vector<int> diags;
  for (int i : chosen) {
    const CutSet& s = selector.set(i);
    for (int k = 0; k < s.nd; ++k) diags.push_back(s.d[k]);
  }
  std::sort(diags.begin(), diags.end());
  diags.erase(std::unique(diags.begin(), diags.end()), diags.end());
  std::vector<std::pair<int, int>> cuts;
  for (int d : diags) cuts.push_back(diagonals[d]);
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

}  // namespace topocut::dude
