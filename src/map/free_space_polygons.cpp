#include "topocut/map/free_space_polygons.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>
#include <cstdint>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "map/byte_scan.h"
#include "topocut/core/error.h"

namespace topocut {

namespace {

// Pixel-edge boundary tracing with bookkeeping for a single raster scan (a pixel-edge variant of
// Suzuki and Abe's border following). Corners (x, y) are the top-left corners of cells (x, y),
// x in 0..w, y in 0..h; outside the image is not free.
class Tracer {
 public:
  explicit Tracer(const cv::Mat& mask) : mask_(mask), w_(mask.cols), h_(mask.rows) {
    horizontal_.assign((static_cast<std::size_t>(h_ + 1) * w_ + 63) / 64, 0);
    vertical_.resize(static_cast<std::size_t>(h_));
  }

  bool free_at(int column, int row) const {
    return column >= 0 && row >= 0 && column < w_ && row < h_ && mask_.ptr<unsigned char>(row)[column] != 0;
  }
  bool visited(int boundary, int column) const {
    const std::size_t i = static_cast<std::size_t>(boundary) * w_ + column;
    return (horizontal_[i / 64] >> (i % 64)) & 1;
  }

  // Follows the boundary from corner (x, y) heading (dx, dy), free cells on the right in the
  // picture (y down), marking every horizontal edge visited and recording the ring of every
  // vertical one. Returns the turning corners in grid coordinates, reversed so that free space lies
  // on the left: outer rings counter-clockwise, holes clockwise.
  Ring trace(int x, int y, int dx, int dy, int ring_id) {
    const int x0 = x, y0 = y, dx0 = dx, dy0 = dy;
    Ring ring;
    while (true) {
      if (dy == 0) {
        const std::size_t i = static_cast<std::size_t>(y) * w_ + std::min(x, x + dx);
        horizontal_[i / 64] |= std::uint64_t{1} << (i % 64);
      } else {
        vertical_[static_cast<std::size_t>(std::min(y, y + dy))].push_back({x, ring_id});
      }
      x += dx;
      y += dy;
      const int rx = -dy, ry = dx;  // right-hand side of the heading, in image coordinates
      // The two cells ahead of the corner: right and left of the heading (offsets are exact halves).
      const bool ahead_right = free_at(x + (dx + rx - 1) / 2, y + (dy + ry - 1) / 2);
      const bool ahead_left = free_at(x + (dx - rx - 1) / 2, y + (dy - ry - 1) / 2);
      int ndx = dx, ndy = dy;
      if (!ahead_right) {
        ndx = rx;
        ndy = ry;
      } else if (ahead_left) {
        ndx = dy;
        ndy = -dx;
      }
      if (ndx != dx || ndy != dy) ring.push_back({x - 0.5, h_ - 0.5 - y});
      dx = ndx;
      dy = ndy;
      if (x == x0 && y == y0 && dx == dx0 && dy == dy0) break;
    }
    std::reverse(ring.begin(), ring.end());
    return ring;
  }

  // The ring of the nearest vertical boundary edge left of cell (column, row) on that row, where
  // the cells change from !free_side to free_side (column excluded); -1 if the row has none.
  int ring_left_of(int column, int row, bool free_side) const {
    for (int c = column; c >= 0; --c) {
      if (free_at(c - 1, row) != free_side) {
        for (const auto& [x, ring] : vertical_[static_cast<std::size_t>(row)])
          if (x == c) return ring;
        return -1;
      }
    }
    return -1;
  }

 private:
  const cv::Mat& mask_;
  int w_, h_;
  std::vector<std::uint64_t> horizontal_;  // (h + 1) x w bits: boundary edges already traced
  std::vector<std::vector<std::pair<int, int>>> vertical_;  // per row: (x, ring id) of traced vertical edges
};


// Every ring of a mask in discovery order (raster order of its top edge), with what it is and
// where it belongs.
struct TracedRings {
  struct RingInfo {
    int component = -1;  // the free component it bounds
    int hole = -1;       // index into that component's holes, or -1 for its outer ring
  };
  std::vector<RingInfo> rings;
  std::vector<FreeSpaceComponent> components;  // polygons and first pixels only, no cell counts yet
  std::vector<int> parent_hole_ring;           // per component: the hole ring it lies in, -1 outside
  std::vector<std::vector<int>> hole_rings;    // per component: ring id of each hole
};

// One scan over the horizontal edges, boundary row by boundary row: the first untraced edge with
// free space below is the top of a new component's first cell (its outer ring); one with free
// space above is the top of a hole's first cell. Each ring is traced once, when first met, so
// components and holes come out in raster order. Rows are compared eight cells at a time.
TracedRings trace_rings(const cv::Mat& mask) {
  const int h = mask.rows, w = mask.cols;
  Tracer tracer(mask);
  TracedRings t;
  const std::vector<unsigned char> nothing(static_cast<std::size_t>(w), 0);
  for (int y = 0; y <= h; ++y) {
    const unsigned char* above = y > 0 ? mask.ptr<unsigned char>(y - 1) : nothing.data();
    const unsigned char* below = y < h ? mask.ptr<unsigned char>(y) : nothing.data();
    for (int c = first_difference(above, below, 0, w); c < w; c = first_difference(above, below, c + 1, w)) {
      const bool up = above[c] != 0, down = below[c] != 0;
      if (up == down || tracer.visited(y, c)) continue;
      const int id = static_cast<int>(t.rings.size());
      if (down) {
        // A new component; it lies in the region of the non-free cell above it.
        FreeSpaceComponent component;
        component.first_pixel = {c, y};
        component.polygon.outer = tracer.trace(c, y, 1, 0, id);
        int parent = -1;
        if (y > 0) {
          const int ring = tracer.ring_left_of(c, y - 1, false);
          if (ring >= 0) {
            const TracedRings::RingInfo& info = t.rings[static_cast<std::size_t>(ring)];
            parent = info.hole >= 0 ? ring : t.parent_hole_ring[static_cast<std::size_t>(info.component)];
          }
        }
        t.rings.push_back({static_cast<int>(t.components.size()), -1});
        t.components.push_back(std::move(component));
        t.parent_hole_ring.push_back(parent);
        t.hole_rings.emplace_back();
      } else {
        // A hole of the component that holds the free cell above it.
        const int ring = tracer.ring_left_of(c, y - 1, true);
        if (ring < 0) throw Error("internal: a hole without an enclosing free-space component");
        const int owner = t.rings[static_cast<std::size_t>(ring)].component;
        FreeSpaceComponent& component = t.components[static_cast<std::size_t>(owner)];
        t.rings.push_back({owner, static_cast<int>(component.polygon.holes.size())});
        component.polygon.holes.push_back(tracer.trace(c + 1, y, -1, 0, id));
        t.hole_rings[static_cast<std::size_t>(owner)].push_back(id);
      }
    }
  }
  return t;
}

// Cell counts from the rings' areas (pixel-edge rings enclose exactly their cells): a component
// is its outer ring minus its holes; a hole's own cells are its ring minus the islands in it.
void count_cells(TracedRings& t) {
  std::vector<double> ring_area(t.rings.size(), 0.0);
  for (std::size_t k = 0; k < t.rings.size(); ++k) {
    const FreeSpaceComponent& component = t.components[static_cast<std::size_t>(t.rings[k].component)];
    const Ring& ring = t.rings[k].hole < 0 ? component.polygon.outer
                                           : component.polygon.holes[static_cast<std::size_t>(t.rings[k].hole)];
    ring_area[k] = std::abs(signed_area(ring));
  }
  std::vector<double> island_area(t.rings.size(), 0.0);
  for (std::size_t i = 0; i < t.components.size(); ++i) {
    if (t.parent_hole_ring[i] >= 0)
      island_area[static_cast<std::size_t>(t.parent_hole_ring[i])] += std::abs(signed_area(t.components[i].polygon.outer));
  }
  for (std::size_t i = 0; i < t.components.size(); ++i) {
    FreeSpaceComponent& component = t.components[i];
    double cells = std::abs(signed_area(component.polygon.outer));
    component.hole_cells.clear();
    for (const int ring : t.hole_rings[i]) {
      cells -= ring_area[static_cast<std::size_t>(ring)];
      component.hole_cells.push_back(static_cast<int>(std::lround(ring_area[static_cast<std::size_t>(ring)] -
                                                                  island_area[static_cast<std::size_t>(ring)])));
    }
    component.pixel_count = static_cast<int>(std::lround(cells));
  }
}

}  // namespace

cv::Mat remove_diagonal_pinches(const cv::Mat& free_mask, int* removed) {
  if (free_mask.empty() || free_mask.type() != CV_8UC1) throw Error("the free-space mask must be a non-empty 8-bit image");
  cv::Mat f = free_mask != 0;
  const int h = f.rows, w = f.cols;
  int count = 0;
  auto at = [&](int r, int c) -> unsigned char& { return f.at<unsigned char>(r, c); };
  auto is_free = [&](int r, int c) { return r >= 0 && r < h && c >= 0 && c < w && at(r, c) != 0; };
  auto free_neighbours = [&](int r, int c) {
    int n = 0;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc)
        if ((dr || dc) && is_free(r + dr, c + dc)) ++n;
    return n;
  };
  std::vector<cv::Point> stack;  // top-left corners (c, r) of 2x2 blocks to check
  auto check = [&](int r, int c) {
    if (r < 0 || c < 0 || r + 1 >= h || c + 1 >= w) return;
    const bool a = at(r, c), b = at(r, c + 1), d = at(r + 1, c), e = at(r + 1, c + 1);
    if (a != e || b != d || a == b) return;
    // Checkerboard: the free diagonal is (a, e) or (b, d).
    cv::Point p = a ? cv::Point(c, r) : cv::Point(c + 1, r);
    cv::Point q = a ? cv::Point(c + 1, r + 1) : cv::Point(c, r + 1);
    const cv::Point drop = free_neighbours(q.y, q.x) < free_neighbours(p.y, p.x) ? q : p;
    at(drop.y, drop.x) = 0;
    ++count;
    for (int br = drop.y - 1; br <= drop.y; ++br)
      for (int bc = drop.x - 1; bc <= drop.x; ++bc) stack.push_back({bc, br});
  };
  auto check_and_repair = [&](int r, int c) {
    check(r, c);
    while (!stack.empty()) {
      const cv::Point b = stack.back();
      stack.pop_back();
      check(b.y, b.x);
    }
  };
  for (int r = 0; r + 1 < h; ++r) {
    const unsigned char* upper = f.ptr<unsigned char>(r);
    const unsigned char* lower = f.ptr<unsigned char>(r + 1);
    // A checkerboard block needs the two rows to differ in its first column: the blocks between such
    // columns are passed over (the rows are read again after every repair).
    for (int c = first_difference(upper, lower, 0, w - 1); c + 1 < w; c = first_difference(upper, lower, c + 1, w - 1))
      check_and_repair(r, c);
  }
  if (removed) *removed = count;
  return f;
}

std::vector<FreeSpaceComponent> trace_components(const cv::Mat& mask_in) {
  if (mask_in.empty() || mask_in.type() != CV_8UC1) throw Error("the free-space mask must be a non-empty 8-bit image");
  const cv::Mat mask = mask_in.isContinuous() ? mask_in : mask_in.clone();
  TracedRings traced = trace_rings(mask);
  count_cells(traced);
  return std::move(traced.components);
}

FreeSpacePolygons free_space_polygons(const cv::Mat& free_mask, double resolution, const ContourOptions& options) {
  if (!std::isfinite(resolution) || resolution <= 0.0) throw Error("the map resolution must be a positive number");
  if (!std::isfinite(options.min_component_area) || options.min_component_area < 0.0)
    throw Error("the minimum component area must be a finite, non-negative number of square metres");
  if (!std::isfinite(options.min_hole_area) || options.min_hole_area < 0.0)
    throw Error("the minimum hole area must be a finite, non-negative number of square metres");
  FreeSpacePolygons result;
  const cv::Mat mask = remove_diagonal_pinches(free_mask, &result.pinch_cells);
  std::vector<FreeSpaceComponent> all = trace_components(mask);

  const double cell_area = resolution * resolution;
  std::vector<bool> keep(all.size(), false);
  std::size_t largest = 0;
  bool any = false;
  for (std::size_t i = 0; i < all.size(); ++i) {
    keep[i] = all[i].pixel_count * cell_area >= options.min_component_area;
    any = any || keep[i];
    if (all[i].pixel_count > all[largest].pixel_count) largest = i;
  }
  if (!any && !all.empty()) keep[largest] = true;

  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!keep[i]) {
      ++result.dropped_components;
      continue;
    }
    FreeSpaceComponent component = std::move(all[i]);
    std::vector<Ring> holes;
    std::vector<int> hole_cells;
    for (std::size_t k = 0; k < component.polygon.holes.size(); ++k) {
      Ring& hole = component.polygon.holes[k];
      const double enclosed = std::abs(signed_area(hole));
      const bool has_islands = enclosed > component.hole_cells[k];
      if (!has_islands && enclosed * cell_area < options.min_hole_area) {
        ++result.dropped_holes;
        continue;
      }
      holes.push_back(std::move(hole));
      hole_cells.push_back(component.hole_cells[k]);
    }
    component.polygon.holes = std::move(holes);
    component.hole_cells = std::move(hole_cells);
    result.kept_cells += component.pixel_count;
    result.components.push_back(std::move(component));
  }
  return result;
}

Ring remove_collinear_vertices(const Ring& ring, const std::function<bool(const Point2&)>& keep) {
  Ring out;
  out.reserve(ring.size());
  for (const Point2& p : ring)
    if (out.empty() || !(out.back() == p)) out.push_back(p);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    Ring next;
    next.reserve(out.size());
    const std::size_t n = out.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point2& a = out[(i + n - 1) % n];
      const Point2& b = out[i];
      const Point2& c = out[(i + 1) % n];
      if (cross(b - a, c - b) == 0.0 && dot(b - a, c - b) > 0.0 && !(keep && keep(b))) {
        changed = true;
        continue;
      }
      next.push_back(b);
    }
    out = std::move(next);
  }
  return out;
}

}  // namespace topocut
