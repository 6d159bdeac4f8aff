#include "topocut/map/rasterize.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {

namespace {

// Adds the crossings of every edge of ring with the rows' centre lines (y = integer) to buckets.
void add_crossings(const Ring& ring, int height, std::vector<std::vector<double>>& rows_x) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    Point2 p = ring[i];
    Point2 q = ring[(i + 1) % n];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(q.x) || !std::isfinite(q.y))
      throw Error("cannot rasterize a polygon with non-finite coordinates");
    if (p.y == q.y) continue;
    // Canonical order (lower end first) so an edge shared by two pieces gives bit-identical x.
    if (q.y < p.y || (q.y == p.y && q.x < p.x)) std::swap(p, q);
    // Half-open in y: the edge covers centre lines p.y <= y < q.y.
    const int y_first = std::max(0, static_cast<int>(std::ceil(p.y)));
    const int y_last = std::min(height - 1, static_cast<int>(std::ceil(q.y)) - 1);
    const double slope = (q.x - p.x) / (q.y - p.y);
    for (int y = y_first; y <= y_last; ++y) rows_x[static_cast<std::size_t>(y)].push_back(p.x + (y - p.y) * slope);
  }
}

}  // namespace

cv::Mat rasterize_polygons(const std::vector<PolygonWithHoles>& polygons, cv::Size size) {
  if (size.width <= 0 || size.height <= 0) throw Error("cannot rasterize into an empty image");
  cv::Mat labels = cv::Mat::zeros(size, CV_32SC1);
  const int height = size.height, width = size.width;
  std::vector<std::vector<double>> rows_x(static_cast<std::size_t>(height));
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    for (auto& xs : rows_x) xs.clear();
    add_crossings(polygons[i].outer, height, rows_x);
    for (const Ring& hole : polygons[i].holes) add_crossings(hole, height, rows_x);
    const int label = static_cast<int>(i) + 1;
    for (int y = 0; y < height; ++y) {
      std::vector<double>& xs = rows_x[static_cast<std::size_t>(y)];
      if (xs.empty()) continue;
      std::sort(xs.begin(), xs.end());
      int* row = labels.ptr<int>(height - 1 - y);
      // Even-odd spans [x0, x1): a centre exactly on the right end belongs to the next piece.
      for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
        const int c_first = std::max(0, static_cast<int>(std::ceil(xs[k])));
        const int c_end = std::min(width, static_cast<int>(std::ceil(xs[k + 1])));
        for (int c = c_first; c < c_end; ++c)
          if (row[c] == 0) row[c] = label;
      }
    }
  }
  return labels;
}

void fill_free_space_labels(cv::Mat& labels, const cv::Mat& free_mask) {
  if (labels.type() != CV_32SC1 || free_mask.type() != CV_8UC1 || labels.size() != free_mask.size())
    throw Error("labels (CV_32SC1) and free-space mask (CV_8UC1) must have the same size");
  const int h = labels.rows, w = labels.cols;
  labels.setTo(0, free_mask == 0);

  // Breadth-first search through free space from every labelled cell (sources in raster order,
  // so ties between equally near labels are broken the same way every time).
  std::deque<int> queue;
  for (int r = 0; r < h; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < w; ++c)
      if (row[c] > 0) queue.push_back(r * w + c);
  }
  if (queue.empty()) return;
  int* data = labels.ptr<int>(0);
  CV_Assert(labels.isContinuous() && free_mask.isContinuous());
  const unsigned char* free = free_mask.ptr<unsigned char>(0);
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    const int r = i / w, c = i % w;
    const int neighbours[4] = {r > 0 ? i - w : -1, c > 0 ? i - 1 : -1, c + 1 < w ? i + 1 : -1, r + 1 < h ? i + w : -1};
    for (const int j : neighbours) {
      if (j < 0 || !free[j] || data[j] != 0) continue;
      data[j] = data[i];
      queue.push_back(j);
    }
  }

  // Free cells cut off from every label (specks too small to be rooms): nearest label in a
  // straight line.
  const cv::Mat orphans = (labels == 0) & (free_mask != 0);
  if (cv::countNonZero(orphans) == 0) return;
  cv::Mat sources = labels == 0;  // distanceTransform measures distance to zero cells: the labelled ones
  cv::Mat distance, nearest;
  cv::distanceTransform(sources, distance, nearest, cv::DIST_L2, 5, cv::DIST_LABEL_PIXEL);
  double max_index = 0.0;
  cv::minMaxLoc(nearest, nullptr, &max_index);
  std::vector<int> label_of(static_cast<std::size_t>(max_index) + 1, 0);
  for (int r = 0; r < h; ++r) {
    const int* l = labels.ptr<int>(r);
    const int* n = nearest.ptr<int>(r);
    for (int c = 0; c < w; ++c)
      if (l[c] > 0) label_of[static_cast<std::size_t>(n[c])] = l[c];
  }
  for (int r = 0; r < h; ++r) {
    int* l = labels.ptr<int>(r);
    const int* n = nearest.ptr<int>(r);
    const unsigned char* o = orphans.ptr<unsigned char>(r);
    for (int c = 0; c < w; ++c)
      if (o[c]) l[c] = label_of[static_cast<std::size_t>(n[c])];
  }
}

}  // namespace topocut
