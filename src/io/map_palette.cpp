#include "topocut/io/map_palette.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "topocut/core/occupancy_grid.h"

namespace topocut {

namespace {

using Histogram = std::array<double, 256>;

void count_levels(const unsigned char* level, const unsigned char* transparent, int n, Histogram& histogram) {
  for (int i = 0; i < n; ++i) {
    if (!transparent[i]) histogram[level[i]] += 1.0;
  }
}

// Whether the 16 bytes from p all equal v, compared as two 8-byte words.
bool uniform16(const unsigned char* p, unsigned char v) {
  std::uint64_t a = 0, b = 0;
  std::memcpy(&a, p, 8);
  std::memcpy(&b, p + 8, 8);
  const std::uint64_t all = 0x0101010101010101ULL * v;
  return ((a ^ all) | (b ^ all)) == 0;
}

// Integer counts in four interleaved tables, so that runs of one level (most of a map) do not
// wait on each other's increments; a block of 16 opaque pixels of one level (most of a map, again)
// is counted at once. The sums are exact in doubles.
Histogram level_histogram(const cv::Mat& levels, const cv::Mat& transparent) {
  std::vector<std::array<std::uint32_t, 256>> counts(4, std::array<std::uint32_t, 256>{});
  const bool opaque = cv::countNonZero(transparent) == 0;
  for (int r = 0; r < levels.rows; ++r) {
    const unsigned char* level = levels.ptr<unsigned char>(r);
    const unsigned char* clear = transparent.ptr<unsigned char>(r);
    const int n = levels.cols;
    int i = 0;
    if (!opaque && std::find_if(clear, clear + n, [](unsigned char t) { return t != 0; }) != clear + n) {
      for (; i + 4 <= n; i += 4) {
        counts[0][level[i]] += clear[i] == 0;
        counts[1][level[i + 1]] += clear[i + 1] == 0;
        counts[2][level[i + 2]] += clear[i + 2] == 0;
        counts[3][level[i + 3]] += clear[i + 3] == 0;
      }
      for (; i < n; ++i) counts[0][level[i]] += clear[i] == 0;
      continue;
    }
    for (; i + 16 <= n; i += 16) {
      if (uniform16(level + i, level[i])) {
        counts[0][level[i]] += 16;
        continue;
      }
      for (int k = 0; k < 16; k += 4) {
        ++counts[0][level[i + k]];
        ++counts[1][level[i + k + 1]];
        ++counts[2][level[i + k + 2]];
        ++counts[3][level[i + k + 3]];
      }
    }
    for (; i < n; ++i) ++counts[0][level[i]];
  }
  Histogram histogram{};
  for (int v = 0; v < 256; ++v) {
    const std::uint64_t total = std::uint64_t{counts[0][v]} + counts[1][v] + counts[2][v] + counts[3][v];
    histogram[static_cast<std::size_t>(v)] = static_cast<double>(total);
  }
  return histogram;
}

// The outermost ring of pixels: the surroundings a SLAM tool never saw.
Histogram border_histogram(const cv::Mat& levels, const cv::Mat& transparent) {
  Histogram histogram{};
  const int last_row = levels.rows - 1, last_col = levels.cols - 1;
  count_levels(levels.ptr<unsigned char>(0), transparent.ptr<unsigned char>(0), levels.cols, histogram);
  if (last_row > 0)
    count_levels(levels.ptr<unsigned char>(last_row), transparent.ptr<unsigned char>(last_row), levels.cols, histogram);
  for (int r = 1; r < last_row; ++r) {
    if (!transparent.at<unsigned char>(r, 0)) histogram[levels.at<unsigned char>(r, 0)] += 1.0;
    if (last_col > 0 && !transparent.at<unsigned char>(r, last_col)) histogram[levels.at<unsigned char>(r, last_col)] += 1.0;
  }
  return histogram;
}

// Local maxima of the histogram (ties go to the darker level) holding enough of the pixels, darkest
// first. The share is of the pixels not at the border's level (-1: none): a SLAM map's unexplored
// surroundings can be nearly all of it (gmapping's default map is 4000 x 4000 cells), and its walls
// must not drop below the share because the map around them is large.
std::vector<int> histogram_modes(const Histogram& histogram, int border, const PaletteDetectionOptions& options) {
  double total = 0.0;
  for (double count : histogram) total += count;
  if (border >= 0) total -= histogram[static_cast<std::size_t>(border)];
  std::vector<int> modes;
  for (int v = 0; v < 256; ++v) {
    if (histogram[v] <= 0.0 || histogram[v] < options.min_mode_share * total) continue;
    bool is_max = true;
    for (int u = std::max(0, v - options.mode_separation); u <= std::min(255, v + options.mode_separation) && is_max; ++u)
      is_max = u < v ? histogram[u] < histogram[v] : histogram[u] <= histogram[v];
    if (is_max) modes.push_back(v);
  }
  return modes;
}

// The most common border level, or -1 when none covers options.min_border_share of the border.
int border_level(const Histogram& border, const PaletteDetectionOptions& options) {
  double total = 0.0;
  for (double count : border) total += count;
  const int level = static_cast<int>(std::max_element(border.begin(), border.end()) - border.begin());
  return total > 0.0 && border[level] >= options.min_border_share * total ? level : -1;
}

int nearest(const std::vector<int>& modes, int level) {
  return *std::min_element(modes.begin(), modes.end(),
                           [&](int a, int b) { return std::abs(a - level) < std::abs(b - level); });
}

}  // namespace

MapPalette threshold_palette(int free_min, int occupied_max) {
  MapPalette palette;
  for (int v = 0; v < 256; ++v) palette.state[v] = v > free_min ? kFree : (v < occupied_max ? kOccupied : kUnknown);
  palette.description = "free > " + std::to_string(free_min) + ", occupied < " + std::to_string(occupied_max) + " (fixed)";
  return palette;
}

MapPalette detect_palette(const cv::Mat& levels, const cv::Mat& transparent, int fallback_free_min, int fallback_occupied_max,
                          const PaletteDetectionOptions& options) {
  CV_Assert(levels.type() == CV_8UC1 && transparent.type() == CV_8UC1 && levels.size() == transparent.size());
  const int border = border_level(border_histogram(levels, transparent), options);
  const std::vector<int> modes = histogram_modes(level_histogram(levels, transparent), border, options);
  if (modes.size() < 2 || modes.back() < 128) return threshold_palette(fallback_free_min, fallback_occupied_max);

  const int free = modes.back();
  int unknown = -1, occupied = -1;
  if (modes.size() == 2) {
    (modes.front() < options.dark_level ? occupied : unknown) = modes.front();
  } else {
    if (border >= 0 && nearest(modes, border) != free) unknown = nearest(modes, border);
    for (int mode : modes) {
      if (mode != unknown && mode != free) {
        occupied = mode;
        break;
      }
    }
  }
  const std::vector<int> not_free(modes.begin(), modes.end() - 1);
  MapPalette palette;
  for (int v = 0; v < 256; ++v) {
    palette.state[v] = std::abs(v - free) <= options.free_tolerance ? kFree
                       : nearest(not_free, v) == occupied        ? kOccupied
                                                                 : kUnknown;
  }
  palette.description = "free " + std::to_string(free);
  if (unknown >= 0) palette.description += ", unknown " + std::to_string(unknown);
  if (occupied >= 0) palette.description += ", occupied " + std::to_string(occupied);
  palette.description += " (detected)";
  return palette;
}

}  // namespace topocut
