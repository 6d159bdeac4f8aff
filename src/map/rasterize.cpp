#include "topocut/map/rasterize.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <string>

#include <opencv2/imgproc.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

// box grown by margin cells on every side, clipped to bounds.
cv::Rect grown_box(const cv::Rect& box, int margin, const cv::Rect& bounds) {
  return cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) & bounds;
}

// The nearest label in a straight line of each cell of `cells`, from a distance transform of
// `window` of labels (0: no label in the window). Approximate (OpenCV's 5x5 mask), as before. With
// as_whole_map, a cell gets -1 unless the transform of the whole map is sure to give it the same
// label: its value at a cell is the length of a path of mask steps from the label it names, each step
// at least as long as the rows or columns it spans, its ties are broken by comparing values along such
// paths no longer than it, and a window's value is never below the whole map's. So wherever the
// square around the cell of half-side its distance lies within the window (or beyond the map's edge),
// the whole map's transform takes the same steps.
// reaches, if given, receives for each cell the half-side of the square around it that holds its
// nearest label in the whole map (from the window's distance, never below the whole map's), -1 when
// the window holds no label.
std::vector<int> window_nearest_labels(const cv::Mat& labels, const cv::Rect& window, const std::vector<int>& cells,
                                       bool as_whole_map, std::vector<int>* reaches = nullptr) {
  const int w = labels.cols;
  const cv::Mat local = labels(window);
  if (reaches) reaches->assign(cells.size(), -1);
  cv::Mat sources = local <= 0;  // distanceTransform measures distance to zero cells: the labelled ones
  if (cv::countNonZero(sources == 0) == 0) return std::vector<int>(cells.size(), as_whole_map ? -1 : 0);  // no label
  cv::Mat distance, nearest;
  cv::distanceTransform(sources, distance, nearest, cv::DIST_L2, 5, cv::DIST_LABEL_PIXEL);
  double max_index = 0.0;
  cv::minMaxLoc(nearest, nullptr, &max_index);
  std::vector<int> label_of(static_cast<std::size_t>(max_index) + 1, 0);
  for (int r = 0; r < local.rows; ++r) {
    const int* l = local.ptr<int>(r);
    const int* n = nearest.ptr<int>(r);
    for (int c = 0; c < local.cols; ++c)
      if (l[c] > 0) label_of[static_cast<std::size_t>(n[c])] = l[c];
  }
  // The window's sides inside the map (a side on the map's edge hides nothing).
  const bool left = window.x > 0, top = window.y > 0;
  const bool right = window.x + window.width < labels.cols, bottom = window.y + window.height < labels.rows;
  std::vector<int> found(cells.size(), 0);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const int r = cells[k] / w - window.y, c = cells[k] % w - window.x;
    found[k] = label_of[static_cast<std::size_t>(nearest.at<int>(r, c))];
    if (!as_whole_map) continue;
    // Above the distance (the float rounds a fixed-point value; a relative 1e-6 covers it).
    const int reach = static_cast<int>(std::floor(distance.at<float>(r, c) * (1.0 + 1e-6))) + 1;
    if (reaches) (*reaches)[k] = reach;
    if ((left && c - reach < 0) || (top && r - reach < 0) || (right && c + reach >= window.width) ||
        (bottom && r + reach >= window.height))
      found[k] = -1;
  }
  return found;
}

// Appends each of `cells` that found gives a label (found[k] != 0) to settled_index and settled_label.
void append_settled(const std::vector<int>& cells, const std::vector<int>& found, std::vector<int>& settled_index,
                    std::vector<int>& settled_label) {
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (found[k] == 0) continue;
    settled_index.push_back(cells[k]);
    settled_label.push_back(found[k]);
  }
}

// Appends the cells of `cells` the window's transform gives a label to settled_index and settled_label.
void nearest_labels_in(const cv::Mat& labels, const cv::Rect& window, const std::vector<int>& cells,
                       std::vector<int>& settled_index, std::vector<int>& settled_label) {
  append_settled(cells, window_nearest_labels(labels, window, cells, false), settled_index, settled_label);
}

// A cut-off blob of free cells and the window around it that holds its nearest labels.
struct OrphanBlob {
  std::vector<int> cells;
  cv::Rect window;
};

constexpr int kLabelTile = 16;  // cells a side of a tile of LabelPresence

// Whether one of the kLabelTile cells from cell on holds a label (> 0): 1 or 0.
unsigned char any_label(const int* cell) {
#if defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  __m128i any = zero;
  for (int k = 0; k < kLabelTile; k += 4)
    any = _mm_or_si128(any, _mm_cmpgt_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(cell + k)), zero));
  return _mm_movemask_epi8(any) != 0;
#else
  int any = 0;
  for (int k = 0; k < kLabelTile; ++k) any |= cell[k] > 0;
  return static_cast<unsigned char>(any);
#endif
}

// Whether a window of the label image holds a label: a tile summary (one count per 16 x 16 tile,
// summed) rules most windows out in constant time; the cells are counted only when a tile says yes.
class LabelPresence {
 public:
  explicit LabelPresence(const cv::Mat& labels) : labels_(labels) {
    cv::Mat tiles(cv::Size((labels.cols + kTile - 1) / kTile, (labels.rows + kTile - 1) / kTile), CV_8UC1, cv::Scalar(0));
    const int whole = labels.cols / kTile;  // tiles of a full kTile cells
    for (int r = 0; r < labels.rows; ++r) {
      const int* row = labels.ptr<int>(r);
      unsigned char* tile_row = tiles.ptr<unsigned char>(r / kTile);
      // A tile a row above found a label in is not read again: inside rooms, once per tile.
      for (int t = 0; t < whole; ++t)
        if (!tile_row[t]) tile_row[t] = any_label(row + t * kTile);
      for (int c = whole * kTile; c < labels.cols; ++c) tile_row[c / kTile] |= row[c] > 0;
    }
    cv::integral(tiles, sums_, CV_32S);
  }
  // False when no tile the window touches holds a label (a window inside the image).
  bool maybe(const cv::Rect& window) const {
    const int x0 = window.x / kTile, y0 = window.y / kTile;
    const int x1 = (window.x + window.width - 1) / kTile + 1, y1 = (window.y + window.height - 1) / kTile + 1;
    return sums_.at<int>(y1, x1) - sums_.at<int>(y0, x1) - sums_.at<int>(y1, x0) + sums_.at<int>(y0, x0) > 0;
  }
  // True when window holds a label; cells_counted grows by the cells counted to decide it.
  bool holds(const cv::Rect& window, double& cells_counted) const {
    if (!maybe(window)) return false;
    cells_counted += window.area();
    return cv::countNonZero(labels_(window) > 0) > 0;
  }

 private:
  static constexpr int kTile = kLabelTile;
  const cv::Mat& labels_;
  cv::Mat sums_;
};

// The 8-connected blobs of orphan cells, each with the window around it that holds its nearest
// labels: grown from the blob's box until it holds labels, then by the blob's own size again, so
// that the nearest label of every cell of the blob lies inside. Blobs without any label in reach
// are left out. Returns nothing once the cells counted and the windows together exceed the map
// (many specks far from any room): one transform of the whole map is then cheaper.
std::optional<std::vector<OrphanBlob>> orphan_blobs(const cv::Mat& labels, const LabelPresence& presence,
                                                   const std::vector<int>& orphans) {
  const int h = labels.rows, w = labels.cols;
  const double budget = static_cast<double>(labels.total());
  double work = 0.0;
  std::vector<unsigned char> seen(orphans.size(), 0);
  std::unordered_map<int, std::size_t> orphan_at;
  orphan_at.reserve(orphans.size() * 2);
  for (std::size_t k = 0; k < orphans.size(); ++k) orphan_at.emplace(orphans[k], k);
  std::vector<OrphanBlob> blobs;
  const cv::Rect all(0, 0, w, h);
  for (std::size_t k = 0; k < orphans.size(); ++k) {
    if (seen[k]) continue;
    std::vector<int> blob{orphans[k]};
    seen[k] = 1;
    int r0 = h, r1 = -1, c0 = w, c1 = -1;
    for (std::size_t head = 0; head < blob.size(); ++head) {
      const int i = blob[head];
      const int r = i / w, c = i % w;
      r0 = std::min(r0, r);
      r1 = std::max(r1, r);
      c0 = std::min(c0, c);
      c1 = std::max(c1, c);
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          if (r + dr < 0 || r + dr >= h || c + dc < 0 || c + dc >= w) continue;
          const auto it = orphan_at.find(i + dr * w + dc);
          if (it == orphan_at.end() || seen[it->second]) continue;
          seen[it->second] = 1;
          blob.push_back(it->first);
        }
    }
    const cv::Rect box(c0, r0, c1 - c0 + 1, r1 - r0 + 1);
    int margin = 8;
    cv::Rect window;
    while (true) {
      window = grown_box(box, margin, all);
      if (presence.holds(window, work) || window == all) break;
      margin *= 2;
    }
    margin += std::max(r1 - r0, c1 - c0) + 2;
    window = grown_box(box, margin, all);
    if (!presence.holds(window, work)) continue;  // no label anywhere
    work += window.area();
    if (work > budget) return std::nullopt;
    blobs.push_back({std::move(blob), window});
  }
  return blobs;
}

// Some of the orphans (members: their indices) and a window around them.
struct OrphanGroup {
  std::vector<std::size_t> members;
  cv::Rect window;
};

// The orphans `which` in groups, each with its box grown by margin as window: orphans in squares of
// margin cells a side within two squares of each other go together (their windows would overlap).
std::vector<OrphanGroup> orphan_groups(const std::vector<int>& orphans, const std::vector<std::size_t>& which, int margin,
                                       cv::Size size) {
  const int w = size.width;
  const int gw = (size.width + margin - 1) / margin, gh = (size.height + margin - 1) / margin;
  const auto square = [&](std::size_t k) { return orphans[k] / w / margin * gw + orphans[k] % w / margin; };
  std::vector<int> group_of(static_cast<std::size_t>(gw) * static_cast<std::size_t>(gh), -2);  // -2: no orphan
  for (const std::size_t k : which) group_of[static_cast<std::size_t>(square(k))] = -1;
  int groups = 0;
  std::vector<int> queue;
  for (std::size_t start = 0; start < group_of.size(); ++start) {
    if (group_of[start] != -1) continue;
    group_of[start] = groups;
    queue.assign(1, static_cast<int>(start));
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int gy = queue[head] / gw, gx = queue[head] % gw;
      for (int y = std::max(0, gy - 2); y <= std::min(gh - 1, gy + 2); ++y)
        for (int x = std::max(0, gx - 2); x <= std::min(gw - 1, gx + 2); ++x) {
          int& g = group_of[static_cast<std::size_t>(y * gw + x)];
          if (g != -1) continue;
          g = groups;
          queue.push_back(y * gw + x);
        }
    }
    ++groups;
  }
  std::vector<OrphanGroup> out(static_cast<std::size_t>(groups));
  std::vector<cv::Rect> box(out.size());
  for (const std::size_t k : which) {
    const std::size_t g = static_cast<std::size_t>(group_of[static_cast<std::size_t>(square(k))]);
    const cv::Rect cell(orphans[k] % w, orphans[k] / w, 1, 1);
    box[g] = out[g].members.empty() ? cell : box[g] | cell;
    out[g].members.push_back(k);
  }
  for (std::size_t g = 0; g < out.size(); ++g)
    out[g].window = grown_box(box[g], margin, cv::Rect(0, 0, size.width, size.height));
  return out;
}

constexpr int kSpreadMargin = 64;  // first margin around groups of spread orphans (cells)

// The next round's groups after a round over groups (margins: the margin each was grown by): each
// group's orphans its window's transform left unsure (got < 0; reaches: theirs), in their box grown by
// the largest of their reaches, which holds what the whole map gives each (a reach bounds the whole
// map's distance from above), or by twice the group's margin where one of them saw no label at all.
// Each group takes its own reach: one far orphan no longer grows every other group's window.
void next_round(const std::vector<int>& orphans, cv::Size size, const OrphanGroup& group, int margin, const std::vector<int>& got,
                const std::vector<int>& reaches, std::vector<OrphanGroup>& next, std::vector<int>& next_margins) {
  OrphanGroup unsure;
  cv::Rect box;
  int reach = 0;  // the largest reach of the unsure orphans, -1 if one has none
  for (std::size_t j = 0; j < got.size(); ++j) {
    if (got[j] >= 0) continue;
    const std::size_t k = group.members[j];
    const cv::Rect cell(orphans[k] % size.width, orphans[k] / size.width, 1, 1);
    box = unsure.members.empty() ? cell : box | cell;
    unsure.members.push_back(k);
    reach = reaches[j] < 0 || reach < 0 ? -1 : std::max(reach, reaches[j]);
  }
  if (unsure.members.empty()) return;
  const int grown = reach > 0 ? reach : static_cast<int>(std::min<long>(2L * margin, std::max(size.width, size.height)));
  unsure.window = grown_box(box, grown, cv::Rect(0, 0, size.width, size.height));
  next.push_back(std::move(unsure));
  next_margins.push_back(grown);
}

// The labels one transform of the whole map gives orphans too many and too spread for a window
// each (settled as nearest_labels_in() over the map, in the orphans' order): from the transforms of
// windows around groups of them, each orphan the whole map might answer otherwise (its distance
// reaching the window's side) again in a window grown by its group's reach (next_round(): a round
// that cannot fail, but where a window held no label); the rest in one transform of the whole map
// once the windows would cost more than it (lab_b: 1,205 orphans at 25-61 cells from a label, their
// windows a fifth of the map).
void nearest_labels_spread(const cv::Mat& labels, const std::vector<int>& orphans, std::vector<int>& settled_index,
                           std::vector<int>& settled_label) {
  const cv::Rect all(0, 0, labels.cols, labels.rows);
  const double budget = static_cast<double>(labels.total());
  double work = 0.0;
  std::vector<int> found(orphans.size(), 0);
  std::vector<std::size_t> left(orphans.size());
  std::iota(left.begin(), left.end(), std::size_t{0});
  const auto cells_of = [&](const std::vector<std::size_t>& members) {
    std::vector<int> cells;
    cells.reserve(members.size());
    for (const std::size_t k : members) cells.push_back(orphans[k]);
    return cells;
  };
  std::vector<OrphanGroup> groups;
  if (kSpreadMargin < std::max(labels.rows, labels.cols)) groups = orphan_groups(orphans, left, kSpreadMargin, labels.size());
  std::vector<int> margins(groups.size(), kSpreadMargin);
  while (!left.empty()) {
    double area = 0.0;
    for (const OrphanGroup& group : groups) area += group.window.area();
    if (groups.empty() || work + area > budget) {
      const std::vector<int> whole = window_nearest_labels(labels, all, cells_of(left), false);
      for (std::size_t j = 0; j < left.size(); ++j) found[left[j]] = whole[j];
      break;
    }
    work += area;
    std::vector<OrphanGroup> next;
    std::vector<int> next_margins;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      std::vector<int> reaches;
      const std::vector<int> got = window_nearest_labels(labels, groups[g].window, cells_of(groups[g].members), true, &reaches);
      for (std::size_t j = 0; j < got.size(); ++j)
        if (got[j] >= 0) found[groups[g].members[j]] = got[j];
      next_round(orphans, labels.size(), groups[g], margins[g], got, reaches, next, next_margins);
    }
    left.clear();
    for (const OrphanGroup& group : next) left.insert(left.end(), group.members.begin(), group.members.end());
    groups = std::move(next);
    margins = std::move(next_margins);
  }
  append_settled(orphans, found, settled_index, settled_label);
}

// Free cells cut off from every label take the nearest label in a straight line. Few blobs are
// each solved in their own window, instead of a distance transform of the whole map; many specks
// far from any room take what one transform of the whole map gives them, from windows around groups
// of them where those are enough, so the work stays linear in the map's size.
void settle_orphans(const cv::Mat& labels, const LabelPresence& presence, const std::vector<int>& orphans,
                    std::vector<int>& settled_index, std::vector<int>& settled_label) {
  if (orphans.empty()) return;
  const std::optional<std::vector<OrphanBlob>> blobs = orphan_blobs(labels, presence, orphans);
  if (!blobs) {
    nearest_labels_spread(labels, orphans, settled_index, settled_label);
    return;
  }
  for (const OrphanBlob& blob : *blobs) nearest_labels_in(labels, blob.window, blob.cells, settled_index, settled_label);
}


// Breadth-first search through free space from the labelled free cells next to unlabelled ones,
// in raster order (ties between equally near labels are broken the same way every time, as if
// every labelled cell were a source). Returns how many unlabelled cells it could not reach.
std::size_t flood_from_labels(cv::Mat& labels, const cv::Mat& free_mask, const std::vector<int>& unlabelled,
                              std::vector<LabelChange>* changes) {
  const int h = labels.rows, w = labels.cols;
  int* data = labels.ptr<int>(0);
  const unsigned char* free = free_mask.ptr<unsigned char>(0);
  std::vector<int> queue;
  queue.reserve(unlabelled.size() * 2);
  for (const int i : unlabelled) {
    const int r = i / w, c = i % w;
    const int neighbours[4] = {r > 0 ? i - w : -1, c > 0 ? i - 1 : -1, c + 1 < w ? i + 1 : -1, r + 1 < h ? i + w : -1};
    for (const int j : neighbours)
      if (j >= 0 && free[j] && data[j] > 0) queue.push_back(j);
  }
  std::sort(queue.begin(), queue.end());
  queue.erase(std::unique(queue.begin(), queue.end()), queue.end());
  std::size_t left = unlabelled.size();
  for (std::size_t head = 0; head < queue.size() && left > 0; ++head) {
    const int i = queue[head];
    const int r = i / w, c = i % w;
    const int neighbours[4] = {r > 0 ? i - w : -1, c > 0 ? i - 1 : -1, c + 1 < w ? i + 1 : -1, r + 1 < h ? i + w : -1};
    for (const int j : neighbours) {
      if (j < 0 || !free[j] || data[j] != 0) continue;
      data[j] = data[i];
      if (changes) changes->push_back({j, 0, data[i]});
      queue.push_back(j);
      --left;
    }
  }
  return left;
}

// Specks settled by the ring search (index, label: not yet written) and those left for a window.
struct SpeckLabels {
  std::vector<int> orphans, settled_index, settled_label;
};

// For the rows of a band of the label image, the nearest labelled column at or left of each
// column and at or right of it: a row's nearest label to a cell in one lookup, instead of reading
// every cell around it. The rows are kept in a ring of `rows` slots, filled as the band moves down,
// each only across the columns its cells may ask about (a label beyond them lies farther than the
// cap from every cell that asks).
class RowNeighbours {
 public:
  static constexpr int kNone = std::numeric_limits<int>::min() / 4;  // no label on that side

  RowNeighbours(const cv::Mat& labels, int rows) : labels_(labels), rows_(rows),
      row_of_(static_cast<std::size_t>(rows), -1), left_(static_cast<std::size_t>(rows) * labels.cols),
      right_(left_.size()), from_(static_cast<std::size_t>(labels.rows), labels.cols), to_(from_.size(), -1) {}

  // Announces a cell (r, c) that will ask about the rows within cap of it, columns within cap of c.
  void will_ask(int r, int c) {
    from_[static_cast<std::size_t>(r)] = std::min(from_[static_cast<std::size_t>(r)], c);
    to_[static_cast<std::size_t>(r)] = std::max(to_[static_cast<std::size_t>(r)], c);
  }

  // Columns of the nearest labels at or left of column c and at or right of it in row y (kNone and
  // -kNone where there is none within the columns announced for the row); y must not lie `rows`
  // rows or more above a row asked before, and (y, c) must be within the cap of an announced cell.
  std::pair<int, int> at(int y, int c) {
    const std::size_t slot = static_cast<std::size_t>(y % rows_), w = static_cast<std::size_t>(labels_.cols);
    if (row_of_[slot] != y) fill(y, slot);
    return {left_[slot * w + static_cast<std::size_t>(c)], right_[slot * w + static_cast<std::size_t>(c)]};
  }

 private:
  void fill(int y, std::size_t slot) {
    const int w = labels_.cols;
    // The columns the announced cells within cap rows may ask about.
    const int cap = rows_ / 2;
    int from = labels_.cols, to = -1;
    for (int r = std::max(0, y - cap); r <= std::min(labels_.rows - 1, y + cap); ++r) {
      from = std::min(from, from_[static_cast<std::size_t>(r)]);
      to = std::max(to, to_[static_cast<std::size_t>(r)]);
    }
    from = std::max(0, from - cap);
    to = std::min(w - 1, to + cap);
    const int* row = labels_.ptr<int>(y);
    int* left = left_.data() + slot * static_cast<std::size_t>(w);
    int* right = right_.data() + slot * static_cast<std::size_t>(w);
    int last = kNone;
    for (int c = from; c <= to; ++c) left[c] = last = row[c] > 0 ? c : last;
    last = -kNone;
    for (int c = to; c >= from; --c) right[c] = last = row[c] > 0 ? c : last;
    row_of_[slot] = y;
  }

  const cv::Mat& labels_;
  int rows_;
  std::vector<int> row_of_, left_, right_;
  std::vector<int> from_, to_;  // per row: the first and last column of its announced cells
};

// The label of the nearest labelled cell to the cell (r, c) within cap cells in x and y, by
// squared distance; among equally near ones the first in the order of a search in square rings
// around the cell (ring, then row, then column): the lowest ring, row and column. 0 when none.
// Each row offers one cell (its nearest, the left one at equal distance) and the rows are compared
// by (distance, ring, row), an order with one least element whatever order the rows are read in:
// they are read outwards from the cell's own row, and no farther row can be nearer once a row is
// farther than the best found.
int nearest_in_band(const cv::Mat& labels, RowNeighbours& rows, int r, int c, int cap) {
  const int h = labels.rows;
  long best = std::numeric_limits<long>::max();
  int best_ring = 0, best_y = 0, label = 0;
  auto offer = [&](int y) {
    const long dy = y - r;
    const auto [left, right] = rows.at(y, c);
    // In one row the nearer column wins; at equal distance the left one (a lower column).
    const int x = c - left <= right - c ? left : right;
    const long dx = x - c;
    if (dx < -cap || dx > cap) return;
    const long d = dy * dy + dx * dx;
    const int ring = static_cast<int>(std::max(std::abs(dy), std::abs(dx)));
    if (d < best || (d == best && (ring < best_ring || (ring == best_ring && y < best_y)))) {
      best = d;
      best_ring = ring;
      best_y = y;
      label = labels.ptr<int>(y)[x];
    }
  };
  for (long dy = 0; dy <= cap && dy * dy <= best; ++dy) {
    if (r - dy >= 0) offer(r - static_cast<int>(dy));
    if (dy > 0 && r + dy < h) offer(r + static_cast<int>(dy));
  }
  return label;
}

// Most specks lie next to a room: the nearest label within kRingCap cells (nearest_in_band, which
// reads few rows for a speck next to a room) settles them without a window. The cells are searched
// in raster order, so that the rows' nearest labels are found once each, and the results kept in
// the cells' own order. Nothing is written here, so the labelled cells taken are those present
// before this step, as in settle_orphans' windows.
SpeckLabels nearest_in_rings(const cv::Mat& labels, const LabelPresence& presence, const std::vector<int>& unlabelled) {
  constexpr int kRingCap = 24;
  const int h = labels.rows, w = labels.cols;
  const int* data = labels.ptr<int>(0);
  const cv::Rect all(0, 0, w, h);
  std::vector<std::size_t> search;  // positions in unlabelled of the cells to search around
  for (std::size_t k = 0; k < unlabelled.size(); ++k) {
    const int i = unlabelled[k];
    if (data[i] != 0) continue;
    if (presence.maybe(cv::Rect(i % w - kRingCap, i / w - kRingCap, 2 * kRingCap + 1, 2 * kRingCap + 1) & all))
      search.push_back(k);
  }
  if (!std::is_sorted(search.begin(), search.end(), [&](std::size_t a, std::size_t b) { return unlabelled[a] < unlabelled[b]; }))
    std::stable_sort(search.begin(), search.end(), [&](std::size_t a, std::size_t b) { return unlabelled[a] < unlabelled[b]; });
  std::vector<int> found(unlabelled.size(), 0);
  RowNeighbours rows(labels, 2 * kRingCap + 1);
  for (const std::size_t k : search) rows.will_ask(unlabelled[k] / w, unlabelled[k] % w);
  for (const std::size_t k : search) found[k] = nearest_in_band(labels, rows, unlabelled[k] / w, unlabelled[k] % w, kRingCap);
  SpeckLabels specks;
  for (std::size_t k = 0; k < unlabelled.size(); ++k) {
    const int i = unlabelled[k];
    if (data[i] != 0) continue;
    if (found[k] > 0) {
      specks.settled_index.push_back(i);
      specks.settled_label.push_back(found[k]);
    } else {
      specks.orphans.push_back(i);  // no label within the rings' reach
    }
  }
  return specks;
}

}  // namespace

std::vector<CellSpan> polygon_spans(const std::vector<PolygonWithHoles>& polygons, cv::Size size) {
  if (size.width <= 0 || size.height <= 0) throw Error("cannot rasterize into an empty image");
  const int height = size.height, width = size.width;
  std::vector<CellSpan> spans;
  std::vector<std::vector<double>> rows_x(static_cast<std::size_t>(height));
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    // Only the rows the polygon spans are touched, so many small polygons stay cheap.
    double y_low = std::numeric_limits<double>::infinity(), y_high = -y_low;
    auto extend = [&](const Ring& ring) {
      for (const Point2& p : ring) {
        y_low = std::min(y_low, p.y);
        y_high = std::max(y_high, p.y);
      }
    };
    extend(polygons[i].outer);
    for (const Ring& hole : polygons[i].holes) extend(hole);
    if (!(y_low <= y_high)) continue;
    const int y_first = std::max(0, static_cast<int>(std::ceil(y_low)));
    const int y_last = std::min(height - 1, static_cast<int>(std::ceil(y_high)) - 1);
    add_crossings(polygons[i].outer, height, rows_x);
    for (const Ring& hole : polygons[i].holes) add_crossings(hole, height, rows_x);
    for (int y = y_first; y <= y_last; ++y) {
      std::vector<double>& xs = rows_x[static_cast<std::size_t>(y)];
      if (xs.empty()) continue;
      std::sort(xs.begin(), xs.end());
      // Even-odd spans [x0, x1): a centre exactly on the right end belongs to the next piece.
      for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
        const int c_first = std::max(0, static_cast<int>(std::ceil(xs[k])));
        const int c_end = std::min(width, static_cast<int>(std::ceil(xs[k + 1])));
        if (c_first < c_end) spans.push_back({height - 1 - y, c_first, c_end, static_cast<int>(i)});
      }
      xs.clear();
    }
  }
  return spans;
}

std::vector<CellSpan> kept_spans(const std::vector<CellSpan>& spans, const std::vector<int>& new_index) {
  std::vector<CellSpan> out;
  out.reserve(spans.size());
  for (const CellSpan& span : spans) {
    if (span.index < 0 || static_cast<std::size_t>(span.index) >= new_index.size())
      throw Error("a span names a polygon the index does not list");
    const int index = new_index[static_cast<std::size_t>(span.index)];
    if (index >= 0) out.push_back({span.row, span.first, span.end, index});
  }
  return out;
}

cv::Mat rasterize_polygons(const std::vector<PolygonWithHoles>& polygons, cv::Size size) {
  const std::vector<CellSpan> spans = polygon_spans(polygons, size);
  cv::Mat labels = cv::Mat::zeros(size, CV_32SC1);
  for (const CellSpan& span : spans) {
    int* row = labels.ptr<int>(span.row);
    const int label = span.index + 1;
    for (int c = span.first; c < span.end; ++c)
      if (row[c] == 0) row[c] = label;
  }
  return labels;
}

void fill_free_space_labels(cv::Mat& labels, const cv::Mat& free_mask, bool keep_non_free,
                            std::vector<LabelChange>* changes) {
  if (labels.type() != CV_32SC1 || free_mask.type() != CV_8UC1 || labels.size() != free_mask.size())
    throw Error("labels (CV_32SC1) and free-space mask (CV_8UC1) must have the same size");
  const int h = labels.rows, w = labels.cols;
  CV_Assert(labels.isContinuous() && free_mask.isContinuous());
  int* data = labels.ptr<int>(0);
  const unsigned char* free = free_mask.ptr<unsigned char>(0);

  // One pass: clear labelled non-free cells (unless kept) and list the unlabelled free cells. Most
  // rows need neither, which a branch-free test finds quickly.
  std::vector<int> unlabelled;
  for (int r = 0; r < h; ++r) {
    int* row = data + static_cast<std::size_t>(r) * w;
    const unsigned char* f = free + static_cast<std::size_t>(r) * w;
    int odd = 0;
    if (keep_non_free) {
      for (int c = 0; c < w; ++c) odd |= (f[c] != 0) & (row[c] == 0);
    } else {
      for (int c = 0; c < w; ++c) odd |= (f[c] != 0) != (row[c] != 0);
    }
    if (!odd) continue;
    for (int c = 0; c < w; ++c) {
      if (f[c] == 0) {
        if (!keep_non_free && row[c] != 0) {
          if (changes) changes->push_back({r * w + c, row[c], 0});
          row[c] = 0;
        }
      } else if (row[c] == 0) {
        unlabelled.push_back(r * w + c);
      }
    }
  }
  complete_unlabelled_cells(labels, free_mask, unlabelled, changes);
}

void complete_unlabelled_cells(cv::Mat& labels, const cv::Mat& free_mask, const std::vector<int>& unlabelled,
                               std::vector<LabelChange>* changes) {
  if (unlabelled.empty()) return;
  if (labels.type() != CV_32SC1 || free_mask.type() != CV_8UC1 || labels.size() != free_mask.size())
    throw Error("labels (CV_32SC1) and free-space mask (CV_8UC1) must have the same size");
  CV_Assert(labels.isContinuous() && free_mask.isContinuous());
  if (flood_from_labels(labels, free_mask, unlabelled, changes) == 0) return;

  // Free cells cut off from every label (specks too small to be rooms): nearest label in a
  // straight line. They are few and small: most are settled by a ring search around them, the
  // rest in a window around each blob that grows until it holds labels, then by the blob's own
  // size again (so the nearest label of every cell of the blob lies inside), instead of a distance
  // transform of the whole map.
  const LabelPresence presence(labels);
  SpeckLabels specks = nearest_in_rings(labels, presence, unlabelled);
  settle_orphans(labels, presence, specks.orphans, specks.settled_index, specks.settled_label);
  // Written only now, so that no speck takes its label from another speck.
  int* data = labels.ptr<int>(0);
  for (std::size_t k = 0; k < specks.settled_index.size(); ++k) {
    data[specks.settled_index[k]] = specks.settled_label[k];
    if (changes) changes->push_back({specks.settled_index[k], 0, specks.settled_label[k]});
  }
}

}  // namespace topocut
