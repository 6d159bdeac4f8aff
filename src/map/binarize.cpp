#include "topocut/map/binarize.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {

namespace {

void check_length(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0)
    throw Error(std::string("the ") + name + " must be a finite, non-negative number of metres");
}

}  // namespace

cv::Mat free_space_mask(const OccupancyGrid& grid, const BinarizeOptions& options) {
  validate(grid);
  check_length(options.robot_radius, "robot radius");
  check_length(options.opening_size, "opening size");
  check_length(options.median_size, "median filter size");
  cv::Mat free = grid.cells == kFree;

  if (options.robot_radius > 0.0) {
    const cv::Mat obstacles = options.inflate_unknown ? (grid.cells != kFree) : (grid.cells == kOccupied);
    if (cv::countNonZero(obstacles) > 0) {
      // Exact Euclidean distance (in cells) from every cell to the nearest obstacle cell centre.
      cv::Mat distance;
      cv::distanceTransform(~obstacles, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
      const double radius_cells = options.robot_radius / grid.resolution;
      free.setTo(0, distance <= radius_cells * (1.0 + 1e-9));
    }
  }
  if (options.opening_size > 0.0) {
    const double side_cells = std::max(1.0, std::round(options.opening_size / grid.resolution));
    // A square taller or wider than the map fits nowhere in it (beyond the edge is not free), so the
    // opening leaves nothing: said without building a square of that side (100 km at 5 mm a cell).
    if (side_cells > std::min(free.cols, free.rows)) return cv::Mat::zeros(free.size(), CV_8UC1);
    const int side = static_cast<int>(side_cells);
    if (side > 1) {
      cv::Mat opened;
      cv::morphologyEx(free, opened, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_RECT, {side, side}),
                       cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
      free &= opened;
    }
  }
  if (options.median_size > 0.0) {
    // A window more than twice the map's size sees nothing more of it: clamped there, so that its
    // padded copy of the map stays the map's size.
    const double widest = 2.0 * std::max(free.cols, free.rows) + 1.0;
    int side = static_cast<int>(std::max(3.0, std::min(std::round(options.median_size / grid.resolution), widest)));
    if (side % 2 == 0) ++side;
    cv::Mat filtered;
    // medianBlur needs 8-bit input for windows above 5, which a 0/255 mask is.
    cv::medianBlur(free, filtered, side);
    free &= filtered;
  }
  return free;
}

}  // namespace topocut
