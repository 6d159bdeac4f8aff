#include "topocut/segmentation/grid_segmentation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

namespace topocut {
namespace {

// For every room id, the labelled cell (top-down grid) farthest from any cell of another label: the
// distance transform of the cells whose four neighbours all share their label. Rooms without such a
// cell (one cell thin) take their first cell in raster order. Works in the box around the labelled
// cells grown by one cell: every cell outside it is a zero of the transform, and the nearest zero
// of a cell inside is never farther than the grown box's border, so the (exact) distances and the
// raster order of the labelled cells are those of the whole map.
std::vector<cv::Point> deepest_cells(const cv::Mat& labels, int max_id) {
  std::vector<cv::Point> best(static_cast<std::size_t>(max_id) + 1, cv::Point(-1, -1));
  const cv::Rect labelled = cv::boundingRect(labels > 0);
  if (labelled.empty()) return best;
  const cv::Rect box = cv::Rect(labelled.x - 1, labelled.y - 1, labelled.width + 2, labelled.height + 2) &
                       cv::Rect(0, 0, labels.cols, labels.rows);
  cv::Mat interior(box.size(), CV_8UC1, cv::Scalar(0));
  // Cells on the map's edge are never interior; the others compare with their four neighbours.
  for (int r = std::max(box.y, 1); r < std::min(box.y + box.height, labels.rows - 1); ++r) {
    const int* up = labels.ptr<int>(r - 1);
    const int* row = labels.ptr<int>(r);
    const int* down = labels.ptr<int>(r + 1);
    unsigned char* out = interior.ptr<unsigned char>(r - box.y) - box.x;
    for (int c = std::max(box.x, 1); c < std::min(box.x + box.width, labels.cols - 1); ++c) {
      const int id = row[c];
      out[c] = id > 0 && up[c] == id && down[c] == id && row[c - 1] == id && row[c + 1] == id ? 255 : 0;
    }
  }
  cv::Mat depth;
  cv::distanceTransform(interior, depth, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  std::vector<float> best_depth(best.size(), -1.0f);
  for (int r = box.y; r < box.y + box.height; ++r) {
    const int* row = labels.ptr<int>(r);
    const float* d = depth.ptr<float>(r - box.y) - box.x;
    for (int c = box.x; c < box.x + box.width; ++c) {
      const int id = row[c];
      if (id <= 0 || id > max_id || !(d[c] > best_depth[static_cast<std::size_t>(id)])) continue;
      best_depth[static_cast<std::size_t>(id)] = d[c];
      best[static_cast<std::size_t>(id)] = {c, r};
    }
  }
  return best;
}

std::vector<RoomPlacement> placements_of(const Segmentation& s) {
  int max_id = 0;
  for (const Room& room : s.rooms) max_id = std::max(max_id, room.id);
  const std::vector<cv::Point> deepest = deepest_cells(s.labels, max_id);
  std::vector<RoomPlacement> placements;
  placements.reserve(s.rooms.size());
  for (const Room& room : s.rooms) {
    RoomPlacement p;
    const cv::Point cell = deepest[static_cast<std::size_t>(room.id)];
    p.inside = cell.x < 0 ? room.centroid
                          : Point2{s.origin.x + (cell.x + 0.5) * s.resolution, s.origin.y + (s.labels.rows - cell.y - 0.5) * s.resolution};
    placements.push_back(p);
  }
  return placements;
}

// Rotation by yaw about the map origin: the map frame of a grid whose origin pose turns it.
struct Rotation {
  Point2 centre;
  double cos_yaw = 1.0, sin_yaw = 0.0;
  Point2 operator()(const Point2& p) const {
    const double dx = p.x - centre.x, dy = p.y - centre.y;
    return {centre.x + cos_yaw * dx - sin_yaw * dy, centre.y + sin_yaw * dx + cos_yaw * dy};
  }
};

void rotate(GridSegmentation& out, const Rotation& turn) {
  for (Room& room : out.segmentation.rooms) {
    for (Point2& v : room.polygon.outer) v = turn(v);
    for (Ring& hole : room.polygon.holes)
      for (Point2& v : hole) v = turn(v);
    room.centroid = turn(room.centroid);
  }
  for (Passage& passage : out.segmentation.passages) passage.cut = {turn(passage.cut.a), turn(passage.cut.b)};
  for (RoomPlacement& p : out.placements) p.inside = turn(p.inside);
}

void bound(GridSegmentation& out) {
  for (std::size_t k = 0; k < out.placements.size(); ++k) {
    RoomPlacement& p = out.placements[k];
    const double inf = std::numeric_limits<double>::infinity();
    p.min = {inf, inf};
    p.max = {-inf, -inf};
    for (const Point2& v : out.segmentation.rooms[k].polygon.outer) {
      p.min = {std::min(p.min.x, v.x), std::min(p.min.y, v.y)};
      p.max = {std::max(p.max.x, v.x), std::max(p.max.y, v.y)};
    }
  }
}

}  // namespace

GridSegmentation in_frame(Segmentation segmentation, const GridFrame& frame) {
  GridSegmentation out;
  out.frame = frame;
  out.placements = placements_of(segmentation);
  out.segmentation = std::move(segmentation);
  if (frame.yaw != 0.0)
    rotate(out, Rotation{out.segmentation.origin, std::cos(frame.yaw), std::sin(frame.yaw)});
  bound(out);
  if (frame.row_order == RowOrder::kBottomUp) {
    cv::Mat flipped;
    cv::flip(out.segmentation.labels, flipped, 0);
    out.segmentation.labels = flipped;
  }
  return out;
}

GridSegmentation segment_grid(const OccupancyGrid& grid, const GridFrame& frame, const SegmentOptions& options,
                              SegmentationInput* input) {
  return in_frame(segment(grid, options, input), frame);
}

GridSegmentation update_grid(IncrementalSegmenter& segmenter, const OccupancyGrid& grid, const GridFrame& frame) {
  return in_frame(segmenter.update(grid), frame);
}

}  // namespace topocut
