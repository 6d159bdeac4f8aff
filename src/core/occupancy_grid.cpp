#include "topocut/core/occupancy_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "topocut/core/error.h"
#include "topocut/core/value_ranges.h"

namespace topocut {

Point2 cell_center_world(const OccupancyGrid& grid, int column, int row) {
  return {grid.origin.x + (column + 0.5) * grid.resolution,
          grid.origin.y + (grid.height() - row - 0.5) * grid.resolution};
}

cv::Point world_to_cell(const OccupancyGrid& grid, const Point2& world) {
  const double c = (world.x - grid.origin.x) / grid.resolution;
  const double r_from_bottom = (world.y - grid.origin.y) / grid.resolution;
  return {static_cast<int>(std::floor(c)), grid.height() - 1 - static_cast<int>(std::floor(r_from_bottom))};
}

Point2 grid_to_world(const OccupancyGrid& grid, const Point2& g) {
  return {grid.origin.x + (g.x + 0.5) * grid.resolution, grid.origin.y + (g.y + 0.5) * grid.resolution};
}

OccupancyGrid crop(const OccupancyGrid& grid, const cv::Rect& box) {
  if (box.empty() || (box & cv::Rect(0, 0, grid.width(), grid.height())) != box)
    throw Error("the box to crop must be a non-empty part of the map");
  OccupancyGrid part;
  part.cells = grid.cells(box).clone();
  part.resolution = grid.resolution;
  part.origin = {grid.origin.x + box.x * grid.resolution,
                 grid.origin.y + (grid.height() - box.y - box.height) * grid.resolution};
  return part;
}

namespace {

constexpr std::uint64_t kUnknownWord = 0x0101010101010101ull * kUnknown;

// The first cell of [begin, end) of a row that is not unknown, or end; eight cells at a time.
int first_known(const unsigned char* row, int begin, int end) {
  int x = begin;
  for (; x + 8 <= end; x += 8) {
    std::uint64_t word;
    std::memcpy(&word, row + x, sizeof word);
    if (word != kUnknownWord) break;
  }
  for (; x < end && row[x] == kUnknown; ++x) {
  }
  return x;
}

// The last cell of [begin, end) that is not unknown, or begin - 1.
int last_known(const unsigned char* row, int begin, int end) {
  int x = end;
  for (; x - 8 >= begin; x -= 8) {
    std::uint64_t word;
    std::memcpy(&word, row + x - 8, sizeof word);
    if (word != kUnknownWord) break;
  }
  for (; x > begin && row[x - 1] == kUnknown; --x) {
  }
  return x - 1;
}

}  // namespace

cv::Rect known_box(const cv::Mat& cells) {
  CV_Assert(cells.type() == CV_8UC1);
  const int h = cells.rows, w = cells.cols;
  int y0 = 0;
  while (y0 < h && first_known(cells.ptr<unsigned char>(y0), 0, w) == w) ++y0;
  if (y0 == h) return {};
  int y1 = h - 1;
  while (first_known(cells.ptr<unsigned char>(y1), 0, w) == w) --y1;
  int x0 = w, x1 = -1;
  for (int y = y0; y <= y1; ++y) {
    const unsigned char* row = cells.ptr<unsigned char>(y);
    x0 = std::min(x0, first_known(row, 0, std::min(x0, w)));
    x1 = std::max(x1, last_known(row, std::max(x1 + 1, 0), w));
  }
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

cv::Mat uncrop(const cv::Mat& part, const cv::Size& size, const cv::Rect& box, double value) {
  CV_Assert(box.size() == part.size() && (box & cv::Rect(0, 0, size.width, size.height)) == box);
  cv::Mat whole(size, part.type());
  const cv::Scalar fill = cv::Scalar::all(value);
  whole.rowRange(0, box.y).setTo(fill);
  whole.rowRange(box.y + box.height, size.height).setTo(fill);
  const cv::Mat band = whole.rowRange(box.y, box.y + box.height);
  band.colRange(0, box.x).setTo(fill);
  band.colRange(box.x + box.width, size.width).setTo(fill);
  part.copyTo(whole(box));
  return whole;
}

void validate(const OccupancyGrid& grid) {
  if (grid.cells.empty()) throw Error("the map is empty (0 cells)");
  if (grid.cells.type() != CV_8UC1) throw Error("the occupancy grid must be a single-channel 8-bit image");
  check_resolution(grid.resolution, "the map resolution");
  check_world_coordinate(grid.origin.x, "the map origin's x");
  check_world_coordinate(grid.origin.y, "the map origin's y");
}

}  // namespace topocut
