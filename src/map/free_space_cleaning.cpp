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

// Marks (2) the non-free cells (1) of a row that lie in a run of non-free cells longer than
// max_side: their region is wider than any speck.
void mark_long_runs(unsigned char* row, int n, int max_side) {
  for (int c = 0; c < n;) {
    if (row[c] == 0) {
      ++c;
      continue;
    }
    int end = c;
    while (end < n && row[end] != 0) ++end;
    if (end - c > max_side) std::fill(row + c, row + end, static_cast<unsigned char>(2));
    c = end;
  }
}

// Whether the column run of non-free cells through (r, c) is longer than max_side.
bool in_long_column_run(const cv::Mat& state, int r, int c, int max_side) {
  int length = 1;
  for (int y = r - 1; y >= 0 && state.at<unsigned char>(y, c) != 0 && length <= max_side; --y) ++length;
  for (int y = r + 1; y < state.rows && state.at<unsigned char>(y, c) != 0 && length <= max_side; ++y) ++length;
  return length > max_side;
}

// Non-free regions (8-connected) enclosed by free space with a bounding box of at most max_side
// cells a side. A region holding a row or column run longer than max_side cannot be one, so only
// regions made of short runs (next to free space; most of a SLAM map is one unknown region) are
// followed cell by cell, and the answer is that of a labelling of every non-free region.
cv::Mat obstacle_specks(const cv::Mat& free, int max_side) {
  cv::Mat specks = cv::Mat::zeros(free.size(), CV_8UC1);
  if (max_side <= 0) return specks;
  const int h = free.rows, w = free.cols;
  // 0 free, 1 non-free in short runs, 2 non-free in a long run (or known not to be a speck), 3 done.
  cv::Mat state = free == 0;
  state &= 1;
  for (int r = 0; r < h; ++r) mark_long_runs(state.ptr<unsigned char>(r), w, max_side);
  std::vector<cv::Point> region;
  for (int r = 0; r < h; ++r) {
    const unsigned char* row = state.ptr<unsigned char>(r);
    for (int c = 0; c < w; ++c) {
      if (row[c] != 1) continue;
      if (in_long_column_run(state, r, c, max_side)) {
        state.at<unsigned char>(r, c) = 2;
        continue;
      }
      // Follow the region; it is a speck unless it reaches a long run, the window's edge or a box
      // wider than max_side.
      region.assign(1, {c, r});
      state.at<unsigned char>(r, c) = 3;
      bool speck = true;
      int x0 = c, x1 = c, y0 = r, y1 = r;
      for (std::size_t k = 0; k < region.size(); ++k) {
        const cv::Point p = region[k];
        if (p.x == 0 || p.y == 0 || p.x == w - 1 || p.y == h - 1) speck = false;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = p.x + dx, y = p.y + dy;
            if (x < 0 || y < 0 || x >= w || y >= h) continue;
            unsigned char& s = state.at<unsigned char>(y, x);
            if (s == 2) speck = false;
            if (s != 1) continue;
            if (in_long_column_run(state, y, x, max_side)) {
              s = 2;
              speck = false;
              continue;
            }
            s = 3;
            region.push_back({x, y});
            x0 = std::min(x0, x);
            x1 = std::max(x1, x);
            y0 = std::min(y0, y);
            y1 = std::max(y1, y);
          }
        }
      }
      speck = speck && x1 - x0 < max_side && y1 - y0 < max_side;
      if (speck)
        for (const cv::Point& p : region) specks.at<unsigned char>(p) = 255;
    }
  }
  return specks;
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

// thick_part() computed within the box of solid's cells, which gives the same cells: outside the
// box solid is empty, like the erosion's border, and every step ends by keeping solid cells only.
// Only the shortcut for discs wider than the map looks at the size, and a disc wider than the box
// fits nowhere either.
cv::Mat thick_part_in_box(const cv::Mat& solid, double radius, int margin) {
  cv::Mat thick = cv::Mat::zeros(solid.size(), CV_8UC1);
  const cv::Rect box = cv::boundingRect(solid);
  if (!box.empty()) thick_part(solid(box), radius, margin).copyTo(thick(box));
  return thick;
}

// The parts of thin (8-connected) that are rays: more of the non-free cells next to them are
// unknown than occupied. A laser ray ends in the unknown; a narrow corridor, a closet or the gap
// between a cupboard and a wall is walled in.
cv::Mat rays_of(const cv::Mat& thin, const cv::Mat& cells) {
  // Labelled within the thin cells' box; the cells around it are read from the whole window.
  cv::Mat rays = cv::Mat::zeros(thin.size(), CV_8UC1);
  const cv::Rect box = cv::boundingRect(thin);
  if (box.empty()) return rays;
  cv::Mat labels;
  const int n = cv::connectedComponents(thin(box), labels, 8, CV_32S);
  std::vector<long long> unknown(static_cast<std::size_t>(n), 0), occupied(static_cast<std::size_t>(n), 0);
  const int h = thin.rows, w = thin.cols;
  auto count = [&](std::size_t l, unsigned char state) {
    unknown[l] += state == kUnknown;
    occupied[l] += state == kOccupied;
  };
  for (int r = box.y; r < box.y + box.height; ++r) {
    const int* label = labels.ptr<int>(r - box.y) - box.x;
    const unsigned char* row = cells.ptr<unsigned char>(r);
    const unsigned char* above = r > 0 ? cells.ptr<unsigned char>(r - 1) : nullptr;
    const unsigned char* below = r + 1 < h ? cells.ptr<unsigned char>(r + 1) : nullptr;
    for (int c = box.x; c < box.x + box.width; ++c) {
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
  mask_of_labels(labels, is_ray).copyTo(rays(box));
  return rays;
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
  const cv::Mat thick = radius > 0.5 ? thick_part_in_box(solid, radius, static_cast<int>(std::ceil(radius / 2.0))) : solid;
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
