#include "topocut/map/free_space_polygons.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {

namespace {

// Labels 4-connected components of a mask and renumbers them 1..N in raster order of their first
// cell, so the result does not depend on the labelling algorithm OpenCV picks.
int raster_ordered_components(const cv::Mat& mask, cv::Mat& labels, std::vector<cv::Point>& first,
                              std::vector<int>& size) {
  cv::Mat raw;
  const int n = cv::connectedComponents(mask, raw, 4, CV_32S);
  std::vector<int> order(static_cast<std::size_t>(n), 0);
  first.assign(static_cast<std::size_t>(n), cv::Point(-1, -1));
  size.assign(static_cast<std::size_t>(n), 0);
  int next = 1;
  for (int r = 0; r < raw.rows; ++r) {
    int* row = raw.ptr<int>(r);
    for (int c = 0; c < raw.cols; ++c) {
      const int l = row[c];
      if (l == 0) continue;
      if (order[static_cast<std::size_t>(l)] == 0) {
        order[static_cast<std::size_t>(l)] = next;
        first[static_cast<std::size_t>(next)] = {c, r};
        ++next;
      }
      row[c] = order[static_cast<std::size_t>(l)];
      ++size[static_cast<std::size_t>(row[c])];
    }
  }
  labels = raw;
  return n - 1;
}

// Follows the pixel-edge boundary of the free region in a padded mask, keeping free cells on the
// right (clockwise around free space as seen in the picture), from corner (x, y) heading (dx, dy).
// Returns the turning corners in grid coordinates of the unpadded image, reversed so that free
// space lies on the left: outer rings counter-clockwise, holes clockwise.
Ring trace_ring(const cv::Mat& padded, int x, int y, int dx, int dy, int height) {
  auto free_at = [&](int column, int row) { return padded.at<unsigned char>(row, column) != 0; };
  const int x0 = x, y0 = y, dx0 = dx, dy0 = dy;
  Ring ring;
  while (true) {
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
    if (ndx != dx || ndy != dy) ring.push_back({x - 1.5, height + 0.5 - y});
    dx = ndx;
    dy = ndy;
    if (x == x0 && y == y0 && dx == dx0 && dy == dy0) break;
  }
  std::reverse(ring.begin(), ring.end());
  return ring;
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
  for (int r = 0; r + 1 < h; ++r) {
    for (int c = 0; c + 1 < w; ++c) {
      check(r, c);
      while (!stack.empty()) {
        const cv::Point b = stack.back();
        stack.pop_back();
        check(b.y, b.x);
      }
    }
  }
  if (removed) *removed = count;
  return f;
}

std::vector<FreeSpaceComponent> trace_components(const cv::Mat& mask) {
  if (mask.empty() || mask.type() != CV_8UC1) throw Error("the free-space mask must be a non-empty 8-bit image");
  const int h = mask.rows;
  cv::Mat padded;
  cv::copyMakeBorder(mask != 0, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));

  cv::Mat free_labels, background_labels;
  std::vector<cv::Point> free_first, background_first;
  std::vector<int> free_size, background_size;
  const int n_free = raster_ordered_components(padded, free_labels, free_first, free_size);
  const int n_background = raster_ordered_components(padded == 0, background_labels, background_first, background_size);

  std::vector<FreeSpaceComponent> components(static_cast<std::size_t>(n_free));
  for (int i = 1; i <= n_free; ++i) {
    const cv::Point p = free_first[static_cast<std::size_t>(i)];
    FreeSpaceComponent& component = components[static_cast<std::size_t>(i - 1)];
    // The first cell's top edge lies on the outer boundary: nothing of the component is above it.
    component.polygon.outer = trace_ring(padded, p.x, p.y, 1, 0, h);
    component.pixel_count = free_size[static_cast<std::size_t>(i)];
    component.first_pixel = {p.x - 1, p.y - 1};
  }
  // Background component 1 contains the padding, i.e. everything outside. Every other one is a
  // hole of the component just above its first cell (that cell is free, or it would belong to
  // the same background component; and it belongs to the enclosing component, since nothing of
  // the hole lies higher up).
  for (int j = 2; j <= n_background; ++j) {
    const cv::Point b = background_first[static_cast<std::size_t>(j)];
    const int owner = free_labels.at<int>(b.y - 1, b.x);
    if (owner <= 0) throw Error("internal: a hole without an enclosing free-space component");
    FreeSpaceComponent& component = components[static_cast<std::size_t>(owner - 1)];
    component.polygon.holes.push_back(trace_ring(padded, b.x + 1, b.y, -1, 0, h));
    component.hole_cells.push_back(background_size[static_cast<std::size_t>(j)]);
  }
  return components;
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

  cv::Mat labels;
  std::vector<cv::Point> first;
  std::vector<int> sizes;
  raster_ordered_components(mask, labels, first, sizes);  // same numbering as trace_components
  std::vector<unsigned char> kept_label(all.size() + 1, 0);
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!keep[i]) {
      ++result.dropped_components;
      continue;
    }
    kept_label[i + 1] = 255;
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
    result.components.push_back(std::move(component));
  }
  result.traced = cv::Mat::zeros(mask.size(), CV_8UC1);
  for (int r = 0; r < labels.rows; ++r) {
    const int* l = labels.ptr<int>(r);
    unsigned char* out = result.traced.ptr<unsigned char>(r);
    for (int c = 0; c < labels.cols; ++c) out[c] = kept_label[static_cast<std::size_t>(l[c])];
  }
  return result;
}

Ring remove_collinear_vertices(const Ring& ring) {
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
      const double cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
      const double dot = (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y);
      if (cross == 0.0 && dot > 0.0) {
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
