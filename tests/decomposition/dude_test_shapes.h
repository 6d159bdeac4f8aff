#pragma once
// Input generators for the decomposition property tests: floor-plan rasters (rooms, walls, doors,
// furniture, optional pixel noise) traced along pixel edges, star polygons, and similarity
// transforms. Deterministic for a given seed.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut::test_shapes {

// A binary raster in y-up cell coordinates: cell (x, y) covers [x, x+1] x [y, y+1].
struct Grid {
  int w = 0, h = 0;
  std::vector<std::uint8_t> cells;  // 1 = free
  Grid(int width, int height) : w(width), h(height), cells(static_cast<std::size_t>(width) * height, 0) {}
  bool free(int x, int y) const { return x >= 0 && y >= 0 && x < w && y < h && cells[y * w + x]; }
  void set(int x, int y, bool f) {
    if (x >= 0 && y >= 0 && x < w && y < h) cells[y * w + x] = f ? 1 : 0;
  }
  void fill(int x0, int y0, int x1, int y1, bool f) {  // half-open box
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) set(x, y, f);
    }
  }
};

inline int uniform(std::mt19937& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
inline double uniform_real(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Splits the free box [x0,x1) x [y0,y1) by walls with one door each, down to rooms of min_room.
inline void split_rooms(Grid& g, std::mt19937& rng, int x0, int y0, int x1, int y1, int wall, int min_room,
                        std::vector<std::array<int, 4>>& rooms) {
  const int wdt = x1 - x0, hgt = y1 - y0;
  const bool can_x = wdt >= 2 * min_room + wall;
  const bool can_y = hgt >= 2 * min_room + wall;
  if ((!can_x && !can_y) || (wdt < 3 * min_room && hgt < 3 * min_room && uniform(rng, 0, 3) == 0)) {
    rooms.push_back({x0, y0, x1, y1});
    return;
  }
  const bool vertical = can_x && (!can_y || (wdt >= hgt ? uniform(rng, 0, 4) > 0 : uniform(rng, 0, 4) == 0));
  if (vertical) {
    const int at = uniform(rng, x0 + min_room, x1 - min_room - wall);
    g.fill(at, y0, at + wall, y1, false);
    const int door = std::min(uniform(rng, 4, 9), hgt - 2);
    const int d0 = uniform(rng, y0 + 1, y1 - door - 1);
    g.fill(at, d0, at + wall, d0 + door, true);
    split_rooms(g, rng, x0, y0, at, y1, wall, min_room, rooms);
    split_rooms(g, rng, at + wall, y0, x1, y1, wall, min_room, rooms);
  } else {
    const int at = uniform(rng, y0 + min_room, y1 - min_room - wall);
    g.fill(x0, at, x1, at + wall, false);
    const int door = std::min(uniform(rng, 4, 9), wdt - 2);
    const int d0 = uniform(rng, x0 + 1, x1 - door - 1);
    g.fill(d0, at, d0 + door, at + wall, true);
    split_rooms(g, rng, x0, y0, x1, at, wall, min_room, rooms);
    split_rooms(g, rng, x0, at + wall, x1, y1, wall, min_room, rooms);
  }
}

// Removes diagonal-only contacts (2x2 checkerboards) so that traced rings are simple and disjoint.
inline void remove_pinches(Grid& g) {
  for (bool changed = true; changed;) {
    changed = false;
    for (int y = 0; y + 1 < g.h; ++y) {
      for (int x = 0; x + 1 < g.w; ++x) {
        const bool a = g.free(x, y), b = g.free(x + 1, y), c = g.free(x, y + 1), d = g.free(x + 1, y + 1);
        if (a && d && !b && !c) {
          g.set(x, y, false);
          changed = true;
        } else if (b && c && !a && !d) {
          g.set(x + 1, y, false);
          changed = true;
        }
      }
    }
  }
}

// Keeps only the largest 4-connected free component.
inline void keep_largest_component(Grid& g) {
  std::vector<int> label(g.cells.size(), -1);
  std::vector<int> sizes;
  std::vector<int> stack;
  for (int i = 0; i < static_cast<int>(g.cells.size()); ++i) {
    if (!g.cells[i] || label[i] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    sizes.push_back(0);
    stack.push_back(i);
    label[i] = id;
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      ++sizes[id];
      const int x = k % g.w, y = k / g.w;
      const int nb[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
      for (const auto& n : nb) {
        if (!g.free(n[0], n[1])) continue;
        const int j = n[1] * g.w + n[0];
        if (label[j] < 0) {
          label[j] = id;
          stack.push_back(j);
        }
      }
    }
  }
  if (sizes.empty()) return;
  const int best = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for (std::size_t i = 0; i < g.cells.size(); ++i) g.cells[i] = label[i] == best ? 1 : 0;
}

// Traces the free region along pixel edges (free on the left): one counter-clockwise outer ring and
// clockwise holes, with collinear runs merged. Expects one component without pinches.
inline PolygonWithHoles trace(const Grid& g) {
  std::map<std::pair<int, int>, std::pair<int, int>> next;  // edge start -> end
  for (int y = 0; y < g.h; ++y) {
    for (int x = 0; x < g.w; ++x) {
      if (!g.free(x, y)) continue;
      if (!g.free(x, y - 1)) next[{x, y}] = {x + 1, y};
      if (!g.free(x + 1, y)) next[{x + 1, y}] = {x + 1, y + 1};
      if (!g.free(x, y + 1)) next[{x + 1, y + 1}] = {x, y + 1};
      if (!g.free(x - 1, y)) next[{x, y + 1}] = {x, y};
    }
  }
  std::vector<Ring> rings;
  while (!next.empty()) {
    std::vector<std::pair<int, int>> cycle;
    auto start = next.begin()->first;
    auto p = start;
    do {
      cycle.push_back(p);
      const auto it = next.find(p);
      const auto q = it->second;
      next.erase(it);
      p = q;
    } while (p != start);
    Ring ring;
    const std::size_t n = cycle.size();
    for (std::size_t i = 0; i < n; ++i) {
      const auto& a = cycle[(i + n - 1) % n];
      const auto& b = cycle[i];
      const auto& c = cycle[(i + 1) % n];
      const bool straight = (b.first - a.first) * (c.second - b.second) - (b.second - a.second) * (c.first - b.first) == 0;
      if (!straight) ring.push_back({static_cast<double>(b.first), static_cast<double>(b.second)});
    }
    rings.push_back(std::move(ring));
  }
  PolygonWithHoles result;
  for (Ring& r : rings) {
    if (signed_area(r) > 0) {
      result.outer = std::move(r);
    } else {
      result.holes.push_back(std::move(r));
    }
  }
  return result;
}

struct PlanOptions {
  int width = 120, height = 80;
  int wall = 3;
  int min_room = 14;
  int furniture = 6;   // furniture blocks to try
  int noise = 0;       // wall-adjacent free pixels turned into obstacles
  int dents = 0;       // wall pixels next to free space turned free
};

// A random floor plan raster, traced.
inline PolygonWithHoles floor_plan(unsigned seed, const PlanOptions& o) {
  std::mt19937 rng(seed);
  Grid g(o.width, o.height);
  const int b = 2;
  g.fill(b, b, o.width - b, o.height - b, true);
  std::vector<std::array<int, 4>> rooms;
  split_rooms(g, rng, b, b, o.width - b, o.height - b, o.wall, o.min_room, rooms);
  for (int i = 0; i < o.furniture && !rooms.empty(); ++i) {
    const auto& r = rooms[uniform(rng, 0, static_cast<int>(rooms.size()) - 1)];
    const int fw = uniform(rng, 2, 9), fh = uniform(rng, 2, 9);
    if (r[2] - r[0] < fw + 4 || r[3] - r[1] < fh + 4) continue;
    const int x = uniform(rng, r[0] + 2, r[2] - fw - 2), y = uniform(rng, r[1] + 2, r[3] - fh - 2);
    g.fill(x, y, x + fw, y + fh, false);
  }
  auto near_other = [&](int x, int y, bool want_free) {
    return g.free(x + 1, y) == want_free || g.free(x - 1, y) == want_free || g.free(x, y + 1) == want_free ||
           g.free(x, y - 1) == want_free;
  };
  for (int i = 0, tries = 0; i < o.noise && tries < 100 * o.noise; ++tries) {
    const int x = uniform(rng, 1, o.width - 2), y = uniform(rng, 1, o.height - 2);
    if (g.free(x, y) && near_other(x, y, false)) {
      g.set(x, y, false);
      ++i;
    }
  }
  for (int i = 0, tries = 0; i < o.dents && tries < 100 * o.dents; ++tries) {
    const int x = uniform(rng, b + 1, o.width - b - 2), y = uniform(rng, b + 1, o.height - b - 2);
    if (!g.free(x, y) && near_other(x, y, true)) {
      g.set(x, y, true);
      ++i;
    }
  }
  remove_pinches(g);
  keep_largest_component(g);
  return trace(g);
}

// A star-shaped polygon around the origin with n vertices; spiky ones alternate long and short rays.
inline PolygonWithHoles star(unsigned seed, int n, double r_min, double r_max, bool spiky) {
  std::mt19937 rng(seed);
  std::vector<double> angles(n);
  const double step = 2 * M_PI / n;
  for (int i = 0; i < n; ++i) angles[i] = (i + uniform_real(rng, 0.05, 0.95)) * step;
  PolygonWithHoles p;
  for (int i = 0; i < n; ++i) {
    double r = uniform_real(rng, r_min, r_max);
    if (spiky) r = i % 2 == 0 ? uniform_real(rng, 0.7 * r_max, r_max) : uniform_real(rng, r_min, 0.4 * r_max);
    p.outer.push_back({r * std::cos(angles[i]), r * std::sin(angles[i])});
  }
  return p;
}

// A random convex polygon (hull of points on an ellipse), counter-clockwise.
inline PolygonWithHoles convex(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::vector<double> angles(n);
  for (double& a : angles) a = uniform_real(rng, 0, 2 * M_PI);
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  const double a = uniform_real(rng, 5, 50), b = uniform_real(rng, 5, 50);
  PolygonWithHoles p;
  for (double t : angles) p.outer.push_back({a * std::cos(t), b * std::sin(t)});
  return p;
}

template <class F>
PolygonWithHoles map_points(const PolygonWithHoles& p, F f) {
  PolygonWithHoles q;
  for (const Point2& v : p.outer) q.outer.push_back(f(v));
  for (const Ring& h : p.holes) {
    Ring r;
    for (const Point2& v : h) r.push_back(f(v));
    q.holes.push_back(std::move(r));
  }
  return q;
}

// Every ring reversed and started at a different vertex.
inline PolygonWithHoles reoriented(const PolygonWithHoles& p, int shift) {
  auto redo = [&](const Ring& r) {
    Ring out(r.rbegin(), r.rend());
    std::rotate(out.begin(), out.begin() + (shift % static_cast<int>(out.size())), out.end());
    return out;
  };
  PolygonWithHoles q;
  q.outer = redo(p.outer);
  for (const Ring& h : p.holes) q.holes.push_back(redo(h));
  return q;
}

}  // namespace topocut::test_shapes
