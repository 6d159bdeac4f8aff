#pragma once
// A uniform grid over a polygon's edges (internal to the module): "edges near this point", "first
// edge along a ray" for the cut search, and "edges a point may lie on" for splitting along the cuts.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "segmentation/cuts/plane_vectors.h"
#include "topocut/core/geometry.h"
#include "topocut/core/infinity.h"

namespace topocut::cut_search {

using namespace plane;

struct Edge {
  Point2 a, b;
  int ring = 0;
  int index = 0;  // the edge from vertex index to index + 1 of its ring
};

// A uniform grid over the edges, for "edges near this point" and "first edge along this ray".
class EdgeGrid {
 public:
  // margin (less than cell): an edge is also listed in the cells its segment passes within this
  // distance of (0: only those it passes through).
  EdgeGrid(const std::vector<Edge>& edges, double cell, double margin = 0.0) : edges_(edges), cell_(cell) {
    if (edges.empty()) {  // no cell: every query finds nothing
      x0_ = y0_ = 0.0;
      start_.assign(1, 0);
      return;
    }
    x0_ = y0_ = kInfinity;
    double x1 = -kInfinity, y1 = -kInfinity;
    for (const Edge& e : edges) {
      x0_ = std::min({x0_, e.a.x, e.b.x});
      y0_ = std::min({y0_, e.a.y, e.b.y});
      x1 = std::max({x1, e.a.x, e.b.x});
      y1 = std::max({y1, e.a.y, e.b.y});
    }
    x0_ -= cell_;
    y0_ -= cell_;
    nx_ = static_cast<int>((x1 - x0_) / cell_) + 2;
    ny_ = static_cast<int>((y1 - y0_) / cell_) + 2;
    // Compressed rows: count, then fill. An edge goes into every cell its segment passes through (or within margin of).
    std::vector<int> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    auto for_cells = [&](const Edge& e, auto&& f) {
      const int cx0 = column(std::min(e.a.x, e.b.x) - margin), cx1 = column(std::max(e.a.x, e.b.x) + margin);
      const int cy0 = row(std::min(e.a.y, e.b.y) - margin), cy1 = row(std::max(e.a.y, e.b.y) + margin);
      const Point2 d = minus(e.b, e.a);
      const double m = margin > 0.0 ? margin * length(d) : 0.0;  // the corners' cross products are distances times |d|
      for (int cy = cy0; cy <= cy1; ++cy) {
        for (int cx = cx0; cx <= cx1; ++cx) {
          if (cx1 > cx0 && cy1 > cy0) {
            // Skip cells the segment's line misses by more than the margin (all four corners beyond it on one side).
            const double bx = x0_ + cx * cell_, by = y0_ + cy * cell_;
            const double s0 = cross(d, minus({bx, by}, e.a)), s1 = cross(d, minus({bx + cell_, by}, e.a));
            const double s2 = cross(d, minus({bx, by + cell_}, e.a)), s3 = cross(d, minus({bx + cell_, by + cell_}, e.a));
            if ((s0 > m && s1 > m && s2 > m && s3 > m) || (s0 < -m && s1 < -m && s2 < -m && s3 < -m)) continue;
          }
          f(cy * nx_ + cx);
        }
      }
    };
    for (const Edge& e : edges) for_cells(e, [&](int c) { ++count[static_cast<std::size_t>(c) + 1]; });
    for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
    start_ = count;
    items_.resize(static_cast<std::size_t>(count.back()));
    for (std::size_t i = 0; i < edges.size(); ++i)
      for_cells(edges[i], [&](int c) { items_[static_cast<std::size_t>(count[static_cast<std::size_t>(c)]++)] = static_cast<int>(i); });
  }

  // The edges (by index, ascending) registered in the cell of p; none outside the grid.
  std::span<const int> in_cell(const Point2& p) const {
    const int cx = column(p.x), cy = row(p.y);
    if (cx < 0 || cy < 0 || cx >= nx_ || cy >= ny_) return {};
    const std::size_t c = static_cast<std::size_t>(cy) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(cx);
    return {items_.data() + start_[c], items_.data() + start_[c + 1]};
  }

  // Calls f(edge) for the edges registered in the cells around p, ring of cells by ring of cells
  // outward, while keep_going(d) holds for d = the least distance from p to the next ring's cells
  // (an edge in several cells is visited several times).
  template <class F, class G>
  void visit_nearest(const Point2& p, double reach, F&& f, G&& keep_going) const {
    const int cx = column(p.x), cy = row(p.y);
    const int rings = static_cast<int>(std::ceil(reach / cell_)) + 1;
    // Ring k's cells lie k - 1 cells beyond p's cell, and beyond p's distance to the nearest side of
    // its own cell; that less a rounding margin (a point may sit a hair across the side of the cell
    // it was registered in), so that no cell goes unvisited that could hold a nearer point.
    const double bx = x0_ + cx * cell_, by = y0_ + cy * cell_;
    const double inset = std::max(std::min({p.x - bx, bx + cell_ - p.x, p.y - by, by + cell_ - p.y}) - 1e-6 * cell_, 0.0);
    for (int k = 0; k <= rings; ++k) {
      if (k > 0 && !keep_going((k - 1) * cell_ + inset)) return;
      for (int y = cy - k; y <= cy + k; ++y) {
        if (y < 0 || y >= ny_) continue;
        const bool edge_row = y == cy - k || y == cy + k;
        for (int x = cx - k; x <= cx + k; x += edge_row ? 1 : 2 * k) {
          if (x >= 0 && x < nx_) {
            const int c = y * nx_ + x;
            for (int i = start_[static_cast<std::size_t>(c)]; i < start_[static_cast<std::size_t>(c) + 1]; ++i) f(items_[static_cast<std::size_t>(i)]);
          }
          if (k == 0) break;
        }
      }
    }
  }

  // Distance along the ray p + t·u (u unit) to the first edge it meets, t in (0, t_max]; infinity
  // if none.
  double cast(const Point2& p, const Point2& u, double t_max, int* hit_edge = nullptr) const {
    int cx = column(p.x), cy = row(p.y);
    const int step_x = u.x > 0 ? 1 : -1, step_y = u.y > 0 ? 1 : -1;
    const double next_x = x0_ + (cx + (step_x > 0 ? 1 : 0)) * cell_;
    const double next_y = y0_ + (cy + (step_y > 0 ? 1 : 0)) * cell_;
    double t_x = u.x != 0.0 ? (next_x - p.x) / u.x : kInfinity;
    double t_y = u.y != 0.0 ? (next_y - p.y) / u.y : kInfinity;
    const double d_x = u.x != 0.0 ? cell_ / std::abs(u.x) : kInfinity;
    const double d_y = u.y != 0.0 ? cell_ / std::abs(u.y) : kInfinity;
    double best = kInfinity;
    double entry = 0.0;
    while (cx >= 0 && cy >= 0 && cx < nx_ && cy < ny_ && entry <= t_max) {
      const int c = cy * nx_ + cx;
      for (int k = start_[static_cast<std::size_t>(c)]; k < start_[static_cast<std::size_t>(c) + 1]; ++k) {
        const Edge& e = edges_[static_cast<std::size_t>(items_[static_cast<std::size_t>(k)])];
        const Point2 d = minus(e.b, e.a);
        const double denominator = cross(u, d);
        if (denominator == 0.0) continue;
        const Point2 w = minus(e.a, p);
        const double t = cross(w, d) / denominator;
        const double s = cross(w, u) / denominator;
        if (t > 1e-9 && s >= 0.0 && s <= 1.0 && t < best) {
          best = t;
          if (hit_edge) *hit_edge = items_[static_cast<std::size_t>(k)];
        }
      }
      const double exit = std::min(t_x, t_y);
      if (best <= exit) break;
      entry = exit;
      if (t_x < t_y) {
        t_x += d_x;
        cx += step_x;
      } else {
        t_y += d_y;
        cy += step_y;
      }
    }
    return best <= t_max ? best : kInfinity;
  }

 private:
  int column(double x) const { return static_cast<int>(std::floor((x - x0_) / cell_)); }
  int row(double y) const { return static_cast<int>(std::floor((y - y0_) / cell_)); }

  const std::vector<Edge>& edges_;
  double cell_;
  double x0_, y0_;
  int nx_ = 0, ny_ = 0;
  std::vector<int> start_, items_;
};

}  // namespace topocut::cut_search
