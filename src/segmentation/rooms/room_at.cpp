#include "topocut/segmentation/room_at.h"

#include <cmath>

#include "topocut/core/error.h"

namespace topocut {

int room_at(const Segmentation& segmentation, const GridFrame& frame, const Point2& point) {
  if (!std::isfinite(point.x) || !std::isfinite(point.y)) throw Error("the point must have finite coordinates");
  const cv::Mat& labels = segmentation.labels;
  // Undo the yaw: the point in the grid's own axes, relative to the origin, in cells.
  const double dx = point.x - segmentation.origin.x, dy = point.y - segmentation.origin.y;
  const double c = std::cos(frame.yaw), s = std::sin(frame.yaw);
  const double column = std::floor((c * dx + s * dy) / segmentation.resolution);
  const double row_up = std::floor((-s * dx + c * dy) / segmentation.resolution);
  // Written so that NaN (a resolution or yaw that is not a number) fails too: off the grid, never a
  // read outside the labels.
  if (!(column >= 0 && row_up >= 0 && column < labels.cols && row_up < labels.rows) || labels.type() != CV_32SC1) return 0;
  const int row = frame.row_order == RowOrder::kBottomUp ? static_cast<int>(row_up) : labels.rows - 1 - static_cast<int>(row_up);
  return labels.at<int>(row, static_cast<int>(column));
}

}  // namespace topocut
