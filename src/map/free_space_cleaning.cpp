#include "topocut/map/free_space_cleaning.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "map/byte_scan.h"
#include "map/row_runs.h"
#include "topocut/core/error.h"
#include "topocut/core/occupancy_grid.h"

namespace topocut {

namespace {

// Cells in metres at the resolution, at most limit (a longer reach covers the image all the same).
int cells(double metres, double resolution, int limit) {
  return static_cast<int>(std::min<double>(limit, std::lround(std::min(metres / resolution, 1e9))));
}

// Non-free regions (8-connected) enclosed by free space with a bounding box of at most max_side
// cells a side: the gaps between free runs, labelled on runs; a region reaching the window's edge
// is no speck.
RowRuns obstacle_specks(const RowRuns& free, int max_side) {
  if (max_side <= 0) return no_runs(free);
  const RowRuns gaps = complement(free);
  int n = 0;
  const std::vector<int> component = run_components(gaps, true, n);
  std::vector<int> x0(static_cast<std::size_t>(n), free.width()), x1(static_cast<std::size_t>(n), -1);
  std::vector<int> y0(static_cast<std::size_t>(n), free.height()), y1(static_cast<std::size_t>(n), -1);
  std::vector<unsigned char> edge(static_cast<std::size_t>(n), 0);
  const int h = free.height(), w = free.width();
  std::size_t i = 0;
  for (int y = 0; y < h; ++y) {
    for (const CellRun& run : gaps.row(y)) {
      const std::size_t c = static_cast<std::size_t>(component[i++]);
      x0[c] = std::min(x0[c], run.begin);
      x1[c] = std::max(x1[c], run.end - 1);
      y0[c] = std::min(y0[c], y);
      y1[c] = std::max(y1[c], y);
      if (run.begin == 0 || run.end == w || y == 0 || y == h - 1) edge[c] = 1;
    }
  }
  std::vector<unsigned char> keep(component.size());
  for (std::size_t k = 0; k < keep.size(); ++k) {
    const std::size_t c = static_cast<std::size_t>(component[k]);
    keep[k] = !edge[c] && x1[c] - x0[c] < max_side && y1[c] - y0[c] < max_side;
  }
  return select_runs(gaps, keep);
}

// The cells of solid covered by discs of radius (cells) that fit into it (its opening with
// OpenCV's elliptic disc; the window's edge counts as an obstacle), grown by margin cells along
// solid (the corners a disc cannot reach).
RowRuns thick_part(const RowRuns& solid, double radius, int margin) {
  const int r = std::max(1, static_cast<int>(std::lround(radius)));
  // A disc as tall or as wide as the window reaches past its edge from every cell: nothing fits.
  if (r >= std::min(solid.width(), solid.height())) return no_runs(solid);
  const std::vector<int> disc = disc_half_widths(r);
  return grow_within(dilate(erode(solid, disc), disc), solid, margin);
}

// The parts of thin (8-connected) that are rays: more of the non-free cells next to them are
// unknown than occupied. A laser ray ends in the unknown; a narrow corridor, a closet or the gap
// between a cupboard and a wall is walled in.
RowRuns rays_of(const RowRuns& thin, const cv::Mat& grid_cells) {
  int n = 0;
  const std::vector<int> component = run_components(thin, true, n);
  std::vector<long long> unknown(static_cast<std::size_t>(n), 0), occupied(static_cast<std::size_t>(n), 0);
  const int h = grid_cells.rows, w = grid_cells.cols;
  std::size_t i = 0;
  for (int y = 0; y < h; ++y) {
    const unsigned char* row = grid_cells.ptr<unsigned char>(y);
    const unsigned char* above = y > 0 ? grid_cells.ptr<unsigned char>(y - 1) : nullptr;
    const unsigned char* below = y + 1 < h ? grid_cells.ptr<unsigned char>(y + 1) : nullptr;
    for (const CellRun& run : thin.row(y)) {
      const std::size_t c = static_cast<std::size_t>(component[i++]);
      long long u = 0, o = 0;
      auto count = [&](unsigned char state) {
        u += state == kUnknown;
        o += state == kOccupied;
      };
      // The four neighbours of every cell of the run; beyond the window counts as unknown.
      for (int x = run.begin; x < run.end; ++x) {
        count(above ? above[x] : kUnknown);
        count(below ? below[x] : kUnknown);
        count(x > 0 ? row[x - 1] : kUnknown);
        count(x + 1 < w ? row[x + 1] : kUnknown);
      }
      unknown[c] += u;
      occupied[c] += o;
    }
  }
  std::vector<unsigned char> keep(component.size());
  for (std::size_t k = 0; k < keep.size(); ++k) {
    const std::size_t c = static_cast<std::size_t>(component[k]);
    keep[k] = unknown[c] > occupied[c];
  }
  return select_runs(thin, keep);
}

// Which of the lost cells lie inside the building: enclosed by its structure (floor and walls), once
// gaps narrower than side cells (windows, doors, unseen stretches of wall) are closed by a square
// (coarse, and separable). Rays that reach into a room never entered end on its walls and stay
// inside; rays through a window into the open do not. Outside is what a 4-connected flood from a
// frame around the window reaches through the open cells.
RowRuns inside_building(const RowRuns& lost, const RowRuns& floor, const cv::Mat& grid_cells, double side) {
  const int n = std::max(1, cells(side / 2.0, 1.0, std::max(grid_cells.rows, grid_cells.cols)));
  return subtract(lost, reached_from_edge(complement(close_square(unite(floor, runs_of_value(grid_cells, kOccupied)), n))));
}

// The bounding box of each 8-connected part of runs (the parts rays_of() judges one by one).
std::vector<cv::Rect> part_boxes(const RowRuns& runs) {
  int n = 0;
  const std::vector<int> component = run_components(runs, true, n);
  std::vector<cv::Rect> boxes(static_cast<std::size_t>(n));
  std::size_t i = 0;
  for (int y = 0; y < runs.height(); ++y) {
    for (const CellRun& run : runs.row(y)) {
      cv::Rect& box = boxes[static_cast<std::size_t>(component[i++])];
      box = box.empty() ? cv::Rect(run.begin, y, run.end - run.begin, 1) : box | cv::Rect(run.begin, y, run.end - run.begin, 1);
    }
  }
  return boxes;
}

// What the cleaning decides in its window, as runs.
struct WindowCleaning {
  RowRuns floor, specks, lost, inside;  // specks: those that stay floor; inside: lost cells inside
  std::vector<cv::Rect> thin_parts;     // boxes of the thin parts judged as rays or not
};

WindowCleaning clean_window(const RowRuns& free, const cv::Mat& grid_cells, double resolution,
                            const FreeSpaceCleaningOptions& options) {
  const int size = std::max(grid_cells.rows, grid_cells.cols);
  const RowRuns specks = obstacle_specks(free, cells(options.max_obstacle_speck, resolution, size));
  const RowRuns solid = unite(free, specks);
  const double radius = options.min_width / resolution / 2.0;
  const RowRuns thin = radius > 0.5 ? subtract(solid, thick_part(solid, radius, static_cast<int>(std::ceil(radius / 2.0))))
                                    : no_runs(free);
  const RowRuns rays = thin.empty() ? thin : rays_of(thin, grid_cells);
  WindowCleaning c{subtract(solid, rays), subtract(specks, rays), intersect(free, rays), no_runs(free), part_boxes(thin)};
  if (options.inside_closing > 0.0 && !c.lost.empty())
    c.inside = inside_building(c.lost, c.floor, grid_cells, options.inside_closing / resolution);
  return c;
}

// The runs of a window placed into an image of the given size (empty elsewhere).
RowRuns placed(const RowRuns& runs, const cv::Rect& window, const cv::Size& size) {
  RowRuns out(size.width);
  out.reserve(runs.all().size(), size.height);
  for (int y = 0; y < size.height; ++y) {
    if (y >= window.y && y < window.y + window.height) {
      for (const CellRun& r : runs.row(y - window.y)) out.push({r.begin + window.x, r.end + window.x});
    }
    out.end_row();
  }
  return out;
}

// The rows of runs within the window, shifted to its columns (runs must lie inside its columns).
RowRuns cropped(const RowRuns& runs, const cv::Rect& window) {
  RowRuns out(window.width);
  out.reserve(runs.all().size(), window.height);
  for (int y = window.y; y < window.y + window.height; ++y) {
    for (const CellRun& r : runs.row(y)) out.push({r.begin - window.x, r.end - window.x});
    out.end_row();
  }
  return out;
}

// The box of the runs' cells (empty if there are none).
cv::Rect box_of(const RowRuns& runs) {
  int x0 = runs.width(), x1 = 0, y0 = -1, y1 = -1;
  for (int y = 0; y < runs.height(); ++y) {
    const std::span<const CellRun> row = runs.row(y);
    if (row.empty()) continue;
    if (y0 < 0) y0 = y;
    y1 = y;
    x0 = std::min(x0, row.front().begin);
    x1 = std::max(x1, row.back().end);
  }
  return y0 < 0 ? cv::Rect() : cv::Rect(x0, y0, x1 - x0, y1 - y0 + 1);
}

}  // namespace

void validate(const FreeSpaceCleaningOptions& options) { check_option_rows(cleaning_option_rows(), options); }

CleanedFreeSpace clean_free_space(const cv::Mat& free, const cv::Mat& grid_cells, double resolution,
                                  const FreeSpaceCleaningOptions& options) {
  if (free.empty() || free.type() != CV_8UC1) throw Error("the free-space mask must be a non-empty 8-bit image");
  if (grid_cells.type() != CV_8UC1 || grid_cells.size() != free.size())
    throw Error("the grid cells must be an 8-bit image of the free-space mask's size");
  if (!std::isfinite(resolution) || resolution <= 0.0) throw Error("the resolution must be a positive number of metres");
  validate(options);
  CleanedFreeSpace result;
  result.removed = cv::Mat::zeros(free.size(), CV_8UC1);
  const RowRuns free_runs = runs_of(free);
  // Work in the box around the free space (SLAM maps are mostly unknown), with room for the closing.
  const cv::Rect box = box_of(free_runs);
  if (box.empty()) {
    result.floor = cv::Mat::zeros(free.size(), CV_8UC1);
    return result;
  }
  const int margin = cells(options.inside_closing, resolution, std::max(free.rows, free.cols)) + 2;
  const cv::Rect window = cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) &
                          cv::Rect(0, 0, free.cols, free.rows);
  const WindowCleaning c = clean_window(cropped(free_runs, window), grid_cells(window), resolution, options);
  result.floor.create(free.size(), CV_8UC1);
  write_mask(placed(c.floor, window, free.size()), result.floor, 255, 0);
  cv::Mat removed = result.removed(window);
  paint(c.specks, removed, kCellObstacleSpeck);
  paint(c.lost, removed, kCellRemovedOutside);
  paint(c.inside, removed, kCellRemovedInside);
  result.removed_cells = static_cast<int>(cell_count(c.lost));
  result.outside_cells = static_cast<int>(cell_count(c.lost) - cell_count(c.inside));
  result.speck_cells = static_cast<int>(cell_count(c.specks));
  result.window = window;
  for (const cv::Rect& part : c.thin_parts) result.thin_parts.push_back(part + window.tl());
  return result;
}

cv::Mat cells_after_cleaning(const cv::Mat& cells, const CleanedFreeSpace& cleaned) {
  CV_Assert(cells.type() == CV_8UC1);
  if (cleaned.outside_cells == 0 && cleaned.speck_cells == 0) return cells;
  CV_Assert(cleaned.removed.size() == cells.size());
  cv::Mat out = cells.clone();
  const cv::Rect w = cleaned.window;
  const int end = w.x + w.width;
  for (int y = w.y; y < w.y + w.height; ++y) {
    const unsigned char* removed = cleaned.removed.ptr<unsigned char>(y);
    unsigned char* cell = out.ptr<unsigned char>(y);
    for (int x = first_nonzero(removed, w.x, end); x < end; x = first_nonzero(removed, x + 1, end)) {
      if (removed[x] == kCellRemovedOutside) cell[x] = kUnknown;
      else if (removed[x] == kCellObstacleSpeck && cell[x] == kUnknown) cell[x] = kFree;
    }
  }
  return out;
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
