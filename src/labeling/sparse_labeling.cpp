#include "topocut/labeling/sparse_labeling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {

namespace {

constexpr double kMaxCellsPerAxis = 1 << 30;  // cell coordinates must fit comfortably in int32
constexpr double kMaxRasterCells = 1 << 28;   // 256 Mi cells: the raster method refuses larger boxes
// The cell comparisons of the sparse labelling (a few seconds of work at 10^9).
constexpr double kMaxCellPairs = 1e9;

void validate_options(const LabelingOptions& options) {
  if (!std::isfinite(options.cell_size) || options.cell_size <= 0.0)
    throw Error("the labeling cell size must be a positive number of metres, got " + std::to_string(options.cell_size));
  if (options.dilation < 0 || options.dilation > 1000)
    throw Error("the number of dilation iterations must be between 0 and 1000, got " + std::to_string(options.dilation));
  if (options.connectivity != 4 && options.connectivity != 8)
    throw Error("the labeling connectivity must be 4 or 8, got " + std::to_string(options.connectivity));
}

struct Cells {
  std::vector<int> point_cell;                 // per input point: index into cells, -1 if not finite
  std::vector<std::pair<int, int>> cells;      // distinct occupied cells (column, row), sorted
  int columns = 0;                             // extent of the occupied cells
  int rows = 0;
};

// Rasterizes the finite points into cells relative to their bounding box.
Cells rasterize(std::span<const Point2> points, double cell_size) {
  Cells out;
  out.point_cell.assign(points.size(), -1);
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  for (const Point2& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    min_x = std::min(min_x, p.x);
    min_y = std::min(min_y, p.y);
    max_x = std::max(max_x, p.x);
    max_y = std::max(max_y, p.y);
  }
  if (!(min_x <= max_x)) return out;  // no finite point
  if ((max_x - min_x) / cell_size >= kMaxCellsPerAxis || (max_y - min_y) / cell_size >= kMaxCellsPerAxis)
    throw Error("the points span too many cells to label (" + std::to_string(max_x - min_x) + " m by " +
                std::to_string(max_y - min_y) + " m at " + std::to_string(cell_size) + " m per cell)");
  // Sort (cell key, point) pairs so equal cells are adjacent and cells come in a fixed order.
  std::vector<std::pair<std::uint64_t, int>> keyed;
  keyed.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Point2& p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    const auto cx = static_cast<std::uint64_t>(std::floor((p.x - min_x) / cell_size));
    const auto cy = static_cast<std::uint64_t>(std::floor((p.y - min_y) / cell_size));
    keyed.emplace_back((cx << 32) | cy, static_cast<int>(i));
  }
  std::sort(keyed.begin(), keyed.end());
  std::uint64_t previous = ~std::uint64_t{0};
  for (const auto& [key, index] : keyed) {
    if (key != previous) {
      const int cx = static_cast<int>(key >> 32);
      const int cy = static_cast<int>(key & 0xffffffffu);
      out.cells.emplace_back(cx, cy);
      out.columns = std::max(out.columns, cx + 1);
      out.rows = std::max(out.rows, cy + 1);
      previous = key;
    }
    out.point_cell[static_cast<size_t>(index)] = static_cast<int>(out.cells.size()) - 1;
  }
  return out;
}

// Numbers the groups of cells (given per cell as any group id) by the first point that lies in
// them, and fills the result.
Labeling number_by_first_point(const Cells& cells, const std::vector<int>& cell_group, int group_count) {
  Labeling result;
  result.labels.assign(cells.point_cell.size(), -1);
  std::vector<int> segment_of_group(static_cast<size_t>(group_count), -1);
  for (size_t i = 0; i < cells.point_cell.size(); ++i) {
    const int cell = cells.point_cell[i];
    if (cell < 0) continue;
    int& segment = segment_of_group[static_cast<size_t>(cell_group[static_cast<size_t>(cell)])];
    if (segment < 0) {
      segment = static_cast<int>(result.segments.size());
      result.segments.emplace_back();
    }
    result.labels[i] = segment;
    result.segments[static_cast<size_t>(segment)].push_back(static_cast<int>(i));
  }
  return result;
}

// True if two cells, dilated `k` times by the element, overlap or touch under the connectivity.
// The dilated cell is an L1 diamond (cross) or an L∞ square (square) of radius k; two such shapes
// meet when the offset lies in their Minkowski sum grown by one connectivity step.
bool cells_join(int dx, int dy, int k, StructuringElement element, int connectivity) {
  const int ax = std::abs(dx);
  const int ay = std::abs(dy);
  if (element == StructuringElement::kSquare) {
    if (connectivity == 8) return std::max(ax, ay) <= 2 * k + 1;
    return std::max(ax, ay) <= 2 * k + 1 && std::min(ax, ay) <= 2 * k;
  }
  if (connectivity == 4) return ax + ay <= 2 * k + 1;
  return ax + ay <= 2 * k + 1 || (ax + ay == 2 * k + 2 && ax >= 1 && ay >= 1);
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<size_t>(i)] != i) {
    parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
    i = parent[static_cast<size_t>(i)];
  }
  return i;
}

void unite(std::vector<int>& parent, int a, int b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a == b) return;
  if (a < b) std::swap(a, b);
  parent[static_cast<size_t>(a)] = b;  // the smaller index is the root: deterministic
}

// The forward neighbours of a bucket (itself excluded): each unordered pair of buckets once.
constexpr int kForward[4][2] = {{0, 1}, {1, -1}, {1, 0}, {1, 1}};

std::uint64_t neighbour_key(std::uint64_t key, const int offset[2]) {
  return (((key >> 32) + static_cast<std::uint64_t>(offset[0])) << 32) |
         ((key & 0xffffffffu) + static_cast<std::uint64_t>(static_cast<std::int64_t>(offset[1])));
}

// Every cell is compared with every cell of its bucket and of the neighbouring buckets, so a large
// dilation (buckets of 2k + 2 cells a side) makes the work grow with the square of the cells: it is
// counted before any is done and refused beyond kMaxCellPairs.
void check_pair_tests(const std::vector<std::uint64_t>& keys, const std::vector<int>& start, const LabelingOptions& options) {
  double pairs = 0.0;
  for (std::size_t b = 0; b < keys.size(); ++b) {
    const double size = start[b + 1] - start[b];
    pairs += size * (size - 1) / 2;
    for (const auto& offset : kForward) {
      if (offset[1] < 0 && (keys[b] & 0xffffffffu) == 0) continue;
      const auto found = std::lower_bound(keys.begin(), keys.end(), neighbour_key(keys[b], offset));
      if (found != keys.end() && *found == neighbour_key(keys[b], offset)) {
        const std::size_t other = static_cast<std::size_t>(found - keys.begin());
        pairs += size * (start[other + 1] - start[other]);
      }
    }
  }
  if (pairs > kMaxCellPairs) {
    std::ostringstream text;
    text << "labelling these points with a dilation of " << options.dilation << " at " << options.cell_size
         << " m per cell compares " << pairs << " pairs of cells, more than the limit of " << kMaxCellPairs
         << ": use a smaller dilation or a larger cell size";
    throw Error(text.str());
  }
}

Labeling label_sparse(const Cells& cells, const LabelingOptions& options) {
  const int k = options.dilation;
  // No two joined cells are more than 2k+1 apart along an axis, so buckets of side 2k+2 need only
  // their neighbouring buckets searched.
  const std::uint64_t side = static_cast<std::uint64_t>(2 * k + 2);
  const size_t n = cells.cells.size();
  std::vector<std::pair<std::uint64_t, int>> bucketed(n);
  for (size_t i = 0; i < n; ++i) {
    const auto bx = static_cast<std::uint64_t>(cells.cells[i].first) / side;
    const auto by = static_cast<std::uint64_t>(cells.cells[i].second) / side;
    bucketed[i] = {(bx << 32) | by, static_cast<int>(i)};
  }
  std::sort(bucketed.begin(), bucketed.end());
  std::vector<std::uint64_t> bucket_keys;
  std::vector<int> bucket_start;
  for (size_t i = 0; i < n; ++i) {
    if (i == 0 || bucketed[i].first != bucketed[i - 1].first) {
      bucket_keys.push_back(bucketed[i].first);
      bucket_start.push_back(static_cast<int>(i));
    }
  }
  bucket_start.push_back(static_cast<int>(n));

  check_pair_tests(bucket_keys, bucket_start, options);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto join_ranges = [&](int a_begin, int a_end, int b_begin, int b_end, bool same) {
    for (int a = a_begin; a < a_end; ++a) {
      const auto& ca = cells.cells[static_cast<size_t>(bucketed[static_cast<size_t>(a)].second)];
      for (int b = same ? a + 1 : b_begin; b < b_end; ++b) {
        const auto& cb = cells.cells[static_cast<size_t>(bucketed[static_cast<size_t>(b)].second)];
        if (cells_join(cb.first - ca.first, cb.second - ca.second, k, options.element, options.connectivity))
          unite(parent, bucketed[static_cast<size_t>(a)].second, bucketed[static_cast<size_t>(b)].second);
      }
    }
  };
  // Each unordered pair of neighbouring buckets is visited once: itself, then the forward half.
  for (size_t b = 0; b < bucket_keys.size(); ++b) {
    const std::uint64_t by = bucket_keys[b] & 0xffffffffu;
    join_ranges(bucket_start[b], bucket_start[b + 1], bucket_start[b], bucket_start[b + 1], true);
    for (const auto& offset : kForward) {
      if (offset[1] < 0 && by == 0) continue;
      const std::uint64_t key = neighbour_key(bucket_keys[b], offset);
      const auto found = std::lower_bound(bucket_keys.begin(), bucket_keys.end(), key);
      if (found == bucket_keys.end() || *found != key) continue;
      const auto other = static_cast<size_t>(found - bucket_keys.begin());
      join_ranges(bucket_start[b], bucket_start[b + 1], bucket_start[other], bucket_start[other + 1], false);
    }
  }
  std::vector<int> group(n);
  for (size_t i = 0; i < n; ++i) group[i] = find_root(parent, static_cast<int>(i));
  return number_by_first_point(cells, group, static_cast<int>(n));
}

Labeling label_raster(const Cells& cells, const LabelingOptions& options) {
  // A margin of k+1 cells keeps every dilated footprint inside the image, so clipping never
  // changes which footprints touch.
  const int pad = options.dilation + 1;
  const double total = (static_cast<double>(cells.columns) + 2.0 * pad) * (static_cast<double>(cells.rows) + 2.0 * pad);
  if (total > kMaxRasterCells)
    throw Error("the points' bounding box needs " + std::to_string(static_cast<long long>(total)) +
                " raster cells; use a larger cell size or the sparse labeling method");
  cv::Mat image = cv::Mat::zeros(cells.rows + 2 * pad, cells.columns + 2 * pad, CV_8UC1);
  for (const auto& [cx, cy] : cells.cells) image.at<unsigned char>(cy + pad, cx + pad) = 255;
  if (options.dilation > 0) {
    const cv::Mat element = cv::getStructuringElement(
        options.element == StructuringElement::kCross ? cv::MORPH_CROSS : cv::MORPH_RECT, cv::Size(3, 3));
    cv::dilate(image, image, element, cv::Point(-1, -1), options.dilation, cv::BORDER_CONSTANT, cv::Scalar(0));
  }
  cv::Mat component;
  const int count = cv::connectedComponents(image, component, options.connectivity, CV_32S);
  std::vector<int> group(cells.cells.size());
  for (size_t i = 0; i < cells.cells.size(); ++i)
    group[i] = component.at<int>(cells.cells[i].second + pad, cells.cells[i].first + pad);
  return number_by_first_point(cells, group, count);
}

}  // namespace

Labeling label_points(std::span<const Point2> points, const LabelingOptions& options) {
  validate_options(options);
  const Cells cells = rasterize(points, options.cell_size);
  if (cells.cells.empty()) {
    Labeling empty;
    empty.labels.assign(points.size(), -1);
    return empty;
  }
  return options.method == LabelingMethod::kRaster ? label_raster(cells, options) : label_sparse(cells, options);
}

Labeling label_scan(const Scan& scan, const LabelingOptions& options) {
  validate(scan);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Point2> points(scan.size(), Point2{nan, nan});
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (scan.is_valid(i)) points[i] = beam_point(scan, i);
  return label_points(points, options);
}

}  // namespace topocut
