#include "topocut/map/free_space_cleaning.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/core/occupancy_grid.h"

namespace topocut {

namespace {

int cells(double metres, double resolution) { return static_cast<int>(std::lround(metres / resolution)); }

// A disc of the given radius (cells) as a structuring element: an odd ellipse kernel.
cv::Mat disc(double radius) {
  const int r = std::max(1, static_cast<int>(std::lround(radius)));
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1});
}

// The mask (CV_8UC1) of the cells whose label the lookup marks with 255.
cv::Mat mask_of_labels(const cv::Mat& labels, const std::vector<unsigned char>& lookup) {
  cv::Mat mask(labels.size(), CV_8UC1);
  for (int r = 0; r < labels.rows; ++r) {
    const int* label = labels.ptr<int>(r);
    unsigned char* out = mask.ptr<unsigned char>(r);
    for (int c = 0; c < labels.cols; ++c) out[c] = lookup[static_cast<std::size_t>(label[c])];
  }
  return mask;
}

// Non-free regions enclosed by free space with a bounding box of at most max_side cells a side.
cv::Mat obstacle_specks(const cv::Mat& free, int max_side) {
  if (max_side <= 0) return cv::Mat::zeros(free.size(), CV_8UC1);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(free == 0, labels, stats, centroids, 8, CV_32S);
  std::vector<unsigned char> is_speck(static_cast<std::size_t>(n), 0);
  for (int i = 1; i < n; ++i) {
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    const bool enclosed = x > 0 && y > 0 && x + w < free.cols && y + h < free.rows;
    is_speck[static_cast<std::size_t>(i)] = enclosed && w <= max_side && h <= max_side ? 255 : 0;
  }
  return mask_of_labels(labels, is_speck);
}

// The cells of solid covered by discs of radius (cells) that fit into it (its opening; the map's
// edge counts as an obstacle), grown by margin cells along solid (the corners a disc cannot reach).
cv::Mat thick_part(const cv::Mat& solid, double radius, int margin) {
  // A disc as wide as the map reaches past its edge from every cell, so nothing fits: the answer
  // without an erosion whose cost grows with the disc's area (a map at 0.1 mm per cell).
  if (std::lround(radius) >= std::min(solid.rows, solid.cols)) return cv::Mat::zeros(solid.size(), CV_8UC1);
  const cv::Mat element = disc(radius);
  cv::Mat thick;
  cv::erode(solid, thick, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::dilate(thick, thick, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  thick &= solid;
  const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
  for (int i = 0; i < margin; ++i) {
    cv::dilate(thick, thick, square);
    thick &= solid;
  }
  return thick;
}

// The parts of thin (8-connected) that are rays: more of the non-free cells next to them are
// unknown than occupied. A laser ray ends in the unknown; a narrow corridor, a closet or the gap
// between a cupboard and a wall is walled in.
cv::Mat rays_of(const cv::Mat& thin, const cv::Mat& cells) {
  cv::Mat labels;
  const int n = cv::connectedComponents(thin, labels, 8, CV_32S);
  std::vector<long long> unknown(static_cast<std::size_t>(n), 0), occupied(static_cast<std::size_t>(n), 0);
  const int h = thin.rows, w = thin.cols;
  auto count = [&](std::size_t l, unsigned char state) {
    unknown[l] += state == kUnknown;
    occupied[l] += state == kOccupied;
  };
  for (int r = 0; r < h; ++r) {
    const int* label = labels.ptr<int>(r);
    const unsigned char* row = cells.ptr<unsigned char>(r);
    const unsigned char* above = r > 0 ? cells.ptr<unsigned char>(r - 1) : nullptr;
    const unsigned char* below = r + 1 < h ? cells.ptr<unsigned char>(r + 1) : nullptr;
    for (int c = 0; c < w; ++c) {
      if (label[c] == 0) continue;
      const std::size_t l = static_cast<std::size_t>(label[c]);
      // Beyond the window counts as unknown.
      count(l, above ? above[c] : kUnknown);
      count(l, below ? below[c] : kUnknown);
      count(l, c > 0 ? row[c - 1] : kUnknown);
      count(l, c + 1 < w ? row[c + 1] : kUnknown);
    }
  }
  std::vector<unsigned char> is_ray(static_cast<std::size_t>(n), 0);
  for (std::size_t i = 1; i < is_ray.size(); ++i) is_ray[i] = unknown[i] > occupied[i] ? 255 : 0;
  return mask_of_labels(labels, is_ray);
}

// Morphological closing of mask with a square of the given side (cells); the map's edge does not
// erode. A square, not a disc: the inside test is coarse, and a square is ten times cheaper.
cv::Mat square_closing(const cv::Mat& mask, double side) {
  if (side <= 0.0) return cv::Mat::zeros(mask.size(), CV_8UC1);
  const int n = std::max(1, static_cast<int>(std::lround(side / 2.0)));
  // A square wider than the map covers all of it from every cell: full if any cell is set, else empty.
  if (n >= std::max(mask.rows, mask.cols)) {
    return cv::countNonZero(mask) > 0 ? cv::Mat(mask.size(), CV_8UC1, cv::Scalar(255)) : cv::Mat::zeros(mask.size(), CV_8UC1);
  }
  const cv::Mat element = cv::getStructuringElement(cv::MORPH_RECT, {2 * n + 1, 2 * n + 1});
  cv::Mat closed;
  cv::dilate(mask, closed, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::erode(closed, closed, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(255));
  return closed;
}

// Which of the lost cells lie inside the building: enclosed by its structure (floor and walls), once
// gaps narrower than side cells (windows, doors, unseen stretches of wall) are closed. Rays that
// reach into a room never entered end on its walls and stay inside; rays through a window into the
// open do not.
cv::Mat inside_building(const cv::Mat& lost, const cv::Mat& floor, const cv::Mat& walls, double side) {
  if (side <= 0.0 || cv::countNonZero(lost) == 0) return cv::Mat::zeros(lost.size(), CV_8UC1);
  const cv::Mat closed = square_closing(floor | walls, side);
  // Flood the outside from a one-cell frame around the window; what it does not reach is enclosed.
  cv::Mat outside;
  cv::copyMakeBorder(~closed, outside, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(255));
  cv::floodFill(outside, cv::Point(0, 0), cv::Scalar(0), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
  const cv::Mat enclosed = outside(cv::Rect(1, 1, lost.cols, lost.rows)) != 0;
  return (closed | enclosed) & lost;
}

void clean_window(const cv::Mat& free, const cv::Mat& grid_cells, double resolution, const FreeSpaceCleaningOptions& options,
                  cv::Mat& floor, cv::Mat& removed) {
  const cv::Mat specks = obstacle_specks(free, cells(options.max_obstacle_speck, resolution));
  const cv::Mat solid = free | specks;
  const double radius = options.min_width / resolution / 2.0;
  const cv::Mat thick = radius > 0.5 ? thick_part(solid, radius, static_cast<int>(std::ceil(radius / 2.0))) : solid;
  const cv::Mat thin = solid & ~thick;
  floor = cv::countNonZero(thin) > 0 ? solid & ~rays_of(thin, grid_cells) : solid.clone();
  const cv::Mat lost = free & ~floor;
  removed = cv::Mat::zeros(free.size(), CV_8UC1);
  removed.setTo(kCellObstacleSpeck, specks & floor);
  removed.setTo(kCellRemovedOutside, lost);
  removed.setTo(kCellRemovedInside, inside_building(lost, floor, grid_cells == kOccupied, options.inside_closing / resolution));
}

}  // namespace

void validate(const FreeSpaceCleaningOptions& options) {
  for (const double value : {options.max_obstacle_speck, options.min_width, options.inside_closing}) {
    if (!std::isfinite(value) || value < 0.0)
      throw Error("the free-space cleaning sizes must be finite, non-negative numbers of metres");
  }
}

CleanedFreeSpace clean_free_space(const cv::Mat& free, const cv::Mat& grid_cells, double resolution,
                                  const FreeSpaceCleaningOptions& options) {
  if (free.empty() || free.type() != CV_8UC1) throw Error("the free-space mask must be a non-empty 8-bit image");
  if (grid_cells.type() != CV_8UC1 || grid_cells.size() != free.size())
    throw Error("the grid cells must be an 8-bit image of the free-space mask's size");
  if (!std::isfinite(resolution) || resolution <= 0.0) throw Error("the resolution must be a positive number of metres");
  validate(options);
  CleanedFreeSpace result;
  result.floor = cv::Mat::zeros(free.size(), CV_8UC1);
  result.removed = cv::Mat::zeros(free.size(), CV_8UC1);
  // Work in the box around the free space (SLAM maps are mostly unknown), with room for the closing.
  const cv::Rect box = cv::boundingRect(free);  // of the nonzero cells
  if (box.empty()) return result;
  const int margin = cells(options.inside_closing, resolution) + 2;
  const cv::Rect window = cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) &
                          cv::Rect(0, 0, free.cols, free.rows);
  cv::Mat floor, removed;
  clean_window(free(window) != 0, grid_cells(window), resolution, options, floor, removed);
  floor.copyTo(result.floor(window));
  removed.copyTo(result.removed(window));
  result.removed_cells = cv::countNonZero(removed >= kCellRemovedInside);
  result.outside_cells = cv::countNonZero(removed == kCellRemovedOutside);
  return result;
}

cv::Mat render_cleaned_map(const cv::Mat& cells, const CleanedFreeSpace& cleaned) {
  CV_Assert(cells.type() == CV_8UC1);
  cv::Mat picture(cells.size(), CV_8UC3, cv::Scalar(160, 160, 160));
  picture.setTo(cv::Scalar(255, 255, 255), cells == kFree);
  picture.setTo(cv::Scalar(0, 0, 0), cells == kOccupied);
  if (cleaned.removed.empty()) return picture;
  CV_Assert(cleaned.removed.size() == cells.size());
  picture.setTo(cv::Scalar(235, 200, 120), cleaned.removed == kCellObstacleSpeck);
  picture.setTo(cv::Scalar(40, 40, 220), cleaned.removed == kCellRemovedOutside);
  picture.setTo(cv::Scalar(40, 160, 250), cleaned.removed == kCellRemovedInside);
  return picture;
}

}  // namespace topocut
