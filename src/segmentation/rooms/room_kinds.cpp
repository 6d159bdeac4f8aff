#include "topocut/segmentation/room_kinds.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {

void validate(const RoomKindOptions& options) { check_option_rows(room_kind_option_rows(), options); }

namespace {

// Cells of a room all of whose 4-neighbours lie in the same room (255), others 0: the distance to the
// nearest 0 cell, plus half a cell, is the distance from a cell's centre to the room's edge.
cv::Mat interiors(const cv::Mat& labels) {
  cv::Mat inside(labels.size(), CV_8UC1, cv::Scalar(0));
  const int cols = labels.cols;
  for (int r = 1; r + 1 < labels.rows; ++r) {
    const int* __restrict up = labels.ptr<int>(r - 1);
    const int* __restrict row = labels.ptr<int>(r);
    const int* __restrict down = labels.ptr<int>(r + 1);
    unsigned char* __restrict out = inside.ptr<unsigned char>(r);
    for (int c = 1; c + 1 < cols; ++c) {  // & rather than && and no branch, so that the loop vectorizes
      const int l = row[c];
      out[c] = static_cast<unsigned char>(-((l > 0) & (up[c] == l) & (down[c] == l) & (row[c - 1] == l) & (row[c + 1] == l)));
    }
  }
  return inside;
}

// Cells along which each pair of rooms (smaller label first) touches: 4-neighbours with different labels.
std::map<std::pair<int, int>, int> contacts(const cv::Mat& labels) {
  std::map<std::pair<int, int>, int> cells;
  auto touch = [&cells](int a, int b) {
    if (a > 0 && b > 0 && a != b) ++cells[{std::min(a, b), std::max(a, b)}];
  };
  // Most cells equal both neighbours: eight at a time are passed over when they do.
  const int cols = labels.cols;
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    const int* down = r + 1 < labels.rows ? labels.ptr<int>(r + 1) : row;  // the last row: itself, no contact
    int c = 0;
    for (; c + 9 <= cols; c += 8) {
      int differ = 0;
      for (int k = c; k < c + 8; ++k) differ |= (row[k] != row[k + 1]) | (row[k] != down[k]);
      if (!differ) continue;
      for (int k = c; k < c + 8; ++k) {
        touch(row[k], row[k + 1]);
        touch(row[k], down[k]);
      }
    }
    for (; c < cols; ++c) {
      if (c + 1 < cols) touch(row[c], row[c + 1]);
      touch(row[c], down[c]);
    }
  }
  return cells;
}

// Every step-th cell of every step-th row of labels.
cv::Mat sampled(const cv::Mat& labels, int step) {
  if (step <= 1) return labels;
  cv::Mat out((labels.rows + step - 1) / step, (labels.cols + step - 1) / step, CV_32SC1);
  for (int r = 0; r < out.rows; ++r) {
    const int* in = labels.ptr<int>(r * step);
    int* row = out.ptr<int>(r);
    for (int c = 0; c < out.cols; ++c) row[c] = in[c * step];
  }
  return out;
}

}  // namespace

int room_kind_sample_step(const RoomKindOptions& options, double resolution) {
  return static_cast<int>(std::clamp(std::floor(options.sample / resolution + 1e-9), 1.0, 1e6));
}

std::vector<RoomShape> room_shapes(const cv::Mat& all_labels, double cell_size, const RoomKindOptions& options) {
  if (all_labels.type() != CV_32SC1) throw Error("room kinds need CV_32SC1 labels");
  if (!(cell_size > 0.0) || !std::isfinite(cell_size)) throw Error("room kinds need a positive resolution");
  const int step = room_kind_sample_step(options, cell_size);
  const cv::Mat labels = sampled(all_labels, step);
  const double resolution = cell_size * step;
  double largest = 0.0;  // of the samples: a pass over every cell would cost a third of the rest at 0.05 m
  if (!labels.empty()) cv::minMaxLoc(labels, nullptr, &largest);
  std::vector<RoomShape> shapes(static_cast<std::size_t>(std::max(0.0, largest)));
  if (shapes.empty()) return shapes;
  cv::Mat distance;
  cv::distanceTransform(interiors(labels), distance, cv::DIST_L2, cv::DIST_MASK_3);
  std::vector<double> cells(shapes.size(), 0.0), distance_sum(shapes.size(), 0.0);
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    const float* d = distance.ptr<float>(r);
    for (int c = 0; c < labels.cols; ++c) {
      if (row[c] <= 0) continue;
      const auto i = static_cast<std::size_t>(row[c] - 1);
      cells[i] += 1.0;
      distance_sum[i] += d[c] + 0.5;  // from the cell's centre to the room's edge
    }
  }
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    if (cells[i] == 0.0) continue;
    RoomShape& s = shapes[i];
    s.area = cells[i] * resolution * resolution;
    s.mean_width = 4.0 * distance_sum[i] / cells[i] * resolution;
    s.elongation = s.area / (s.mean_width * s.mean_width);
  }
  const double min_cells = options.min_contact / resolution;
  for (const auto& [pair, n] : contacts(labels)) {
    if (n < min_cells) continue;
    ++shapes[static_cast<std::size_t>(pair.first - 1)].openings;
    ++shapes[static_cast<std::size_t>(pair.second - 1)].openings;
  }
  return shapes;
}

RoomKind room_kind(const RoomShape& shape, const RoomKindOptions& options) {
  const bool narrow = shape.mean_width <= options.width || shape.elongation >= options.hallway_elongation;
  const bool corridor = shape.openings >= options.openings && shape.elongation >= options.elongation && narrow;
  return corridor ? RoomKind::kCorridor : RoomKind::kRoom;
}

void assign_room_kinds(Segmentation& segmentation, const RoomKindOptions& options) {
  const std::vector<RoomShape> shapes = room_shapes(segmentation.labels, segmentation.resolution, options);
  for (Room& room : segmentation.rooms) {
    const auto i = static_cast<std::size_t>(room.id - 1);
    room.kind = room.id > 0 && i < shapes.size() ? room_kind(shapes[i], options) : RoomKind::kRoom;
  }
}

}  // namespace topocut
