#include "topocut/segmentation/grid_segmentation.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

#include <opencv2/imgproc.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace topocut {
namespace {

// Where two parabolas of a lower envelope cross: at num / den (den > 0), kept as a fraction and
// compared by products: in doubles, exact while the squared distances stay below 2^24 (as do the
// floats cv::distanceTransform computes in) and without overflow beyond; in integers where the box
// is narrow enough (Depth of 16 bits) that the products stay below 2^53, where both are exact and so
// the same, the integers fewer instructions.
struct Crossing {
  std::int64_t num = 0, den = 1;
};

template <typename Depth>
bool at_or_before(const Crossing& a, const Crossing& b) {
  if constexpr (sizeof(Depth) == sizeof(std::int16_t)) {
    return a.num * b.den <= b.num * a.den;
  } else {
    return static_cast<double>(a.num) * static_cast<double>(b.den) <= static_cast<double>(b.num) * static_cast<double>(a.den);
  }
}

// out[x] = min over q of (x - q)^2 + g[q], for x and q in [0, n): the lower envelope of the parabolas
// (Felzenszwalb and Huttenlocher's distance transform along a row), in integers. v and z hold n entries.
template <typename Depth>
void lower_envelope(const std::int64_t* g, int n, std::int64_t* out, int* v, Crossing* z) {
  int k = 0;  // v[0..k]: the parabolas on the envelope; v[j] is lowest from z[j] on (z[0]: minus infinity)
  v[0] = 0;
  for (int q = 1; q < n; ++q) {
    for (;;) {
      const int p = v[k];
      const Crossing s{g[q] + std::int64_t{q} * q - g[p] - std::int64_t{p} * p, 2 * std::int64_t{q - p}};
      if (k > 0 && at_or_before<Depth>(s, z[k])) {  // q is lower than v[k] wherever v[k] was lowest
        --k;
        continue;
      }
      v[++k] = q;
      z[k] = s;
      break;
    }
  }
  for (int x = 0, j = 0; x < n; ++x) {
    while (j < k && !at_or_before<Depth>(Crossing{x, 1}, z[j + 1])) ++j;
    const std::int64_t dx = x - v[j];
    out[x] = dx * dx + g[v[j]];
  }
}

// Scans of a row for the next cell that is positive, or not. Most of a map's cells are not labelled,
// nor interior, and most of a room's are: where SSE2 is there, 16 bytes of cells are compared at
// once and the answer read from the comparison's bits, elsewhere cell by cell, with the same answer.
#if defined(__SSE2__)
// Bit i: whether byte i of the 16 at p belongs to a positive cell (sizeof(T) bits a cell).
template <typename T>
unsigned positive_bytes16(const T* p) {
  const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  const __m128i zero = _mm_setzero_si128();
  if constexpr (sizeof(T) == sizeof(std::int16_t)) {
    return static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpgt_epi16(v, zero)));
  } else {
    static_assert(sizeof(T) == sizeof(std::int32_t));
    return static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpgt_epi32(v, zero)));
  }
}
#endif

template <typename T>
constexpr int kCells16 = 16 / static_cast<int>(sizeof(T));  // the cells of 16 bytes

// The first of values[from, n) that is positive (want true) or not (want false), or n.
template <bool want, typename T>
int first_where_positive(const T* values, int from, int n) {
  int a = from;
#if defined(__SSE2__)
  for (; a + kCells16<T> <= n; a += kCells16<T>) {
    const unsigned found = want ? positive_bytes16(values + a) : ~positive_bytes16(values + a) & 0xFFFFu;
    if (found != 0) return a + std::countr_zero(found) / static_cast<int>(sizeof(T));
  }
#endif
  while (a < n && (values[a] > 0) != want) ++a;
  return a;
}

template <typename T>
int first_positive(const T* values, int from, int n) {
  return first_where_positive<true>(values, from, n);
}

template <typename T>
int first_not_positive(const T* values, int from, int n) {
  return first_where_positive<false>(values, from, n);
}

// The last of values[from, n) that is positive, or from - 1.
int last_positive(const int* values, int from, int n) {
  int b = n;  // values[b, n) hold none
#if defined(__SSE2__)
  for (; b - kCells16<int> >= from; b -= kCells16<int>) {
    const unsigned found = positive_bytes16(values + b - kCells16<int>);
    if (found != 0) return b - kCells16<int> + (std::bit_width(found) - 1) / static_cast<int>(sizeof(int));
  }
#endif
  while (b > from && values[b - 1] <= 0) --b;
  return b - 1;
}

// The column grid's cells: 16 bits when the box's sides allow (twice the cells per instruction,
// and SSE2 has their min and max), else 32.
template <typename Depth>
constexpr int kDepthType = sizeof(Depth) == sizeof(std::int16_t) ? CV_16SC1 : CV_32SC1;

bool fits_short_depths(const cv::Rect& box) {
  return std::max(box.width, box.height) < std::numeric_limits<std::int16_t>::max();
}

#if defined(__SSE2__)
// All ones in each of the four cells of row from c that is interior (its label positive, its four
// neighbours' the same), else zero.
__m128i interior4(const int* above, const int* row, const int* below, int c) {
  const auto at = [c](const int* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + c)); };
  const __m128i id = at(row);
  __m128i interior = _mm_cmpgt_epi32(id, _mm_setzero_si128());
  interior = _mm_and_si128(interior, _mm_cmpeq_epi32(at(above), id));
  interior = _mm_and_si128(interior, _mm_cmpeq_epi32(at(below), id));
  interior = _mm_and_si128(interior, _mm_cmpeq_epi32(at(row - 1), id));
  return _mm_and_si128(interior, _mm_cmpeq_epi32(at(row + 1), id));
}

// column_distances()'s downward pass over the 16-bit cells [c0, c1) of a row, eight at a time: the
// compiler's own vectorization of the loop widens and narrows the masks lane by lane, while SSE2
// packs two of four 32-bit masks into eight 16-bit ones in one instruction. The first cell not done.
int down_from_above8(const int* above, const int* row, const int* below, const std::int16_t* last, std::int16_t* out, int c0,
                     int c1) {
  const __m128i one = _mm_set1_epi16(1);
  int c = c0;
  for (; c + 8 <= c1; c += 8) {
    const __m128i interior = _mm_packs_epi32(interior4(above, row, below, c), interior4(above, row, below, c + 4));
    const __m128i up = _mm_add_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(last + c)), one);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + c), _mm_and_si128(up, interior));
  }
  return c;
}
#endif

// For the cells of box (labels' box grown by one cell, whose border cells are never interior): 0 for
// a cell that is not interior (its label differs from one of its four neighbours', it has none or it
// lies on the map's edge), else its distance to the nearest such cell up or down its column.
template <typename Depth>
cv::Mat column_distances(const cv::Mat& labels, const cv::Rect& box) {
  cv::Mat column(box.size(), kDepthType<Depth>);
  const int c0 = std::max(box.x, 1), c1 = std::min(box.x + box.width, labels.cols - 1);
  const int r0 = box.y + 1, r1 = std::min(box.y + box.height, labels.rows - 1);
  // Zeroed only where the pass below does not write (filling the whole grid first cost more than the
  // pass itself on a large map).
  const int w0 = std::clamp(c0 - box.x, 0, box.width), w1 = std::clamp(c1 - box.x, w0, box.width);
  for (int i = 0; i < box.height; ++i) {
    Depth* out = column.ptr<Depth>(i);
    const bool written = box.y + i >= r0 && box.y + i < r1;
    std::fill(out, out + (written ? w0 : box.width), Depth{0});
    if (written) std::fill(out + w1, out + box.width, Depth{0});
  }
  // From the box's second row: its first is never interior (above the labels, or the map's edge),
  // and each row reads the one before it.
  for (int r = r0; r < r1; ++r) {
    const int* __restrict above = labels.ptr<int>(r - 1);
    const int* __restrict row = labels.ptr<int>(r);
    const int* __restrict below = labels.ptr<int>(r + 1);
    const Depth* __restrict last = column.ptr<Depth>(r - 1 - box.y) - box.x;
    Depth* __restrict out = column.ptr<Depth>(r - box.y) - box.x;
    int c = c0;
#if defined(__SSE2__)
    if constexpr (sizeof(Depth) == sizeof(std::int16_t)) c = down_from_above8(above, row, below, last, out, c0, c1);
#endif
    for (; c < c1; ++c) {  // & and a mask rather than && and a branch, so that the loop vectorizes
      const int id = row[c];
      const int interior = (id > 0) & (above[c] == id) & (below[c] == id) & (row[c - 1] == id) & (row[c + 1] == id);
      out[c] = static_cast<Depth>((last[c] + 1) & -interior);
    }
  }
  const int width = box.width;
  std::vector<Depth> down_buffer(static_cast<std::size_t>(width), Depth{0});
  Depth* __restrict down = down_buffer.data();
  for (int r = box.height - 1; r >= 0; --r) {
    Depth* __restrict out = column.ptr<Depth>(r);
    for (int c = 0; c < width; ++c) {
      const auto d = static_cast<Depth>((down[c] + 1) & -static_cast<int>(out[c] > 0));
      down[c] = d;
      out[c] = std::min(out[c], d);
    }
  }
  return column;
}

// A row's run of interior cells: all of one room, since each is its neighbours' label. A non-interior
// cell bounds each end, so no cell beyond it can be a run cell's nearest non-interior cell.
struct InteriorRun {
  int row = 0, begin = 0, end = 0;  // the row of the box and its columns [begin, end)
  int id = 0;
  float reach = 0.0f;  // at least every run cell's depth: the most, over its cells, of the nearest run or column end
};

float depth_of(std::int64_t squared) { return std::sqrt(static_cast<float>(squared)); }

// The most, over the run's cells col[begin, end), of the nearest of its column's ends and the run's:
// each half of the run counts to its own end, in a loop that vectorizes.
template <typename Depth>
int run_reach(const Depth* col, int begin, int end) {
  const int middle = begin + (end - begin) / 2;
  Depth most = 0;
  auto to_end = static_cast<Depth>(1);
  for (int b = begin; b < middle; ++b, ++to_end) most = std::max(most, std::min(col[b], to_end));
  to_end = static_cast<Depth>(end - middle);
  for (int b = middle; b < end; ++b, --to_end) most = std::max(most, std::min(col[b], to_end));
  return most;
}

// The interior runs of the box in raster order.
template <typename Depth>
std::vector<InteriorRun> interior_runs(const cv::Mat& labels, const cv::Rect& box, const cv::Mat& column) {
  std::vector<InteriorRun> runs;
  for (int r = 0; r < box.height; ++r) {
    const Depth* col = column.ptr<Depth>(r);
    for (int a = first_positive(col, 0, box.width); a < box.width;) {
      InteriorRun run{r, a, first_not_positive(col, a, box.width), labels.at<int>(box.y + r, box.x + a), 0.0f};
      const int most = run_reach(col, run.begin, run.end);
      run.reach = depth_of(std::int64_t{most} * most);
      runs.push_back(run);
      a = first_positive(col, run.end, box.width);
    }
  }
  return runs;
}

// The squared depth of the run's cell b: the least (b - q)^2 + col[q]^2 over the columns q of the
// run and the non-interior cell at each of its ends (no cell beyond an end is nearer than the end),
// searched outward from b until no farther column can be nearer. Once the least found is below
// floor the search stops and returns it: the cell cannot be the room's deepest.
template <typename Depth>
std::int64_t squared_depth(const Depth* col, int b, std::int64_t floor) {
  std::int64_t least = std::int64_t{col[b]} * col[b];
  // Both sides at once: the nearer run end (col 0) ends the search before the farther one is passed.
  for (std::int64_t k = 1; k * k < least && least >= floor; ++k) {
    const std::int64_t left = col[b - k], right = col[b + k];
    least = std::min(least, k * k + std::min(left * left, right * right));
  }
  return least;
}

// The least squared distance whose depth is at least depth (strict: more than depth). In steps of
// one from the square: few squared distances share a float depth below 2^14, and no map within the
// size limit has a deeper room.
std::int64_t least_squared_depth(float depth, bool strict) {
  const auto enough = [depth, strict](std::int64_t s) { return strict ? depth_of(s) > depth : depth_of(s) >= depth; };
  auto s = static_cast<std::int64_t>(static_cast<double>(depth) * depth);
  while (s > 0 && enough(s - 1)) --s;
  while (!enough(s)) ++s;
  return s;
}

// The lower envelope's buffers, kept from run to run.
struct EnvelopeBuffers {
  std::vector<std::int64_t> g, out;
  std::vector<int> v;
  std::vector<Crossing> z;
};

// The squared depth of the run's cells (buffers.out[k] for cell begin + k), by the lower envelope of
// the parabolas of the run's cells and the non-interior cell at each end.
template <typename Depth>
void run_depths(const InteriorRun& run, const Depth* col, EnvelopeBuffers& buffers) {
  const auto n = static_cast<std::size_t>(run.end - run.begin + 2);
  if (buffers.g.size() < n) {
    buffers.g.resize(n);
    buffers.out.resize(n);
    buffers.v.resize(n);
    buffers.z.resize(n);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::int64_t c = col[run.begin - 1 + static_cast<int>(k)];
    buffers.g[k] = c * c;
  }
  lower_envelope<Depth>(buffers.g.data(), static_cast<int>(n), buffers.out.data(), buffers.v.data(), buffers.z.data());
}

// The rooms wanted (by id) of those whose deepest cells are sought.
using WantedIds = std::vector<char>;

bool is_wanted(const WantedIds& wanted, int id) {
  return id > 0 && static_cast<std::size_t>(id) < wanted.size() && wanted[static_cast<std::size_t>(id)] != 0;
}

// Wanted rooms without an interior cell (one cell thin) take their first labelled cell in raster order.
void first_cells_of_thin_rooms(const cv::Mat& labels, const cv::Rect& box, const WantedIds& wanted, std::vector<cv::Point>& best) {
  int missing = 0;
  for (std::size_t id = 1; id < best.size(); ++id) missing += wanted[id] != 0 && best[id].x < 0 ? 1 : 0;
  for (int r = box.y; r < box.y + box.height && missing > 0; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = box.x; c < box.x + box.width; ++c) {
      const int id = row[c];
      if (!is_wanted(wanted, id) || best[static_cast<std::size_t>(id)].x >= 0) continue;
      best[static_cast<std::size_t>(id)] = {c, r};
      --missing;
    }
  }
}

// The bounding box of the cells with a positive label (empty: none), as cv::boundingRect(labels > 0)
// gives it, without the mask of the whole map: each row is looked at right of the box so far, left
// of it, and only when neither holds a label, inside it.
cv::Rect labelled_box(const cv::Mat& labels) {
  const int n = labels.cols;
  int x0 = n, x1 = -1, y0 = -1, y1 = -1;
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    const int last = last_positive(row, x1 + 1, n), first = first_positive(row, 0, x0);
    const bool labelled = last > x1 || first < x0 || (x0 <= x1 && first_positive(row, x0, x1 + 1) <= x1);
    x1 = std::max(x1, last);
    x0 = std::min(x0, first);
    if (!labelled) continue;
    if (y0 < 0) y0 = r;
    y1 = r;
  }
  return y0 < 0 ? cv::Rect() : cv::Rect(x0, y0, x1 - x0 + 1, y1 - y0 + 1);
}

// A room's deepest cell so far (box coordinates) and the least squared depth a cell needs to take
// its place: as deep and earlier in raster order, or deeper.
struct Deepest {
  float depth = 0.0f;
  cv::Point cell{-1, -1};
  std::int64_t as_deep = 0, deeper = 1;

  bool before(int row, int c) const { return std::tie(row, c) < std::tie(cell.y, cell.x); }
  void take(float d, cv::Point at) {
    depth = d;
    cell = at;
    as_deep = least_squared_depth(d, false);
    deeper = least_squared_depth(d, true);
  }
};

// The run's cells that may take the room's place, each measured by squared_depth(): not a cell whose
// bound (its nearest column or run end) is below what it needs, nor one whose search falls below.
template <typename Depth>
void search_run(const InteriorRun& run, const Depth* col, Deepest& deepest) {
  for (int b = run.begin; b < run.end; ++b) {
    const std::int64_t bound = std::min({static_cast<int>(col[b]), b - run.begin + 1, run.end - b});
    const std::int64_t needed = deepest.before(run.row, b) ? deepest.as_deep : deepest.deeper;
    if (bound * bound < needed) continue;
    const std::int64_t squared = squared_depth(col, b, needed);
    if (squared < needed) continue;
    const float d = depth_of(squared);
    if (d > deepest.depth || (d == deepest.depth && deepest.before(run.row, b))) deepest.take(d, {b, run.row});
  }
}

// A room's first run (its widest reach) transformed whole: searched cell by cell, each cell on the
// way up to its deepest would be deeper than the last, searched to its end, and the room's deepest
// taken again; the envelope costs the same for every cell and sets the room's deepest near its
// final depth at once.
template <typename Depth>
void deepest_of_first_run(const InteriorRun& run, const Depth* col, EnvelopeBuffers& buffers, Deepest& room) {
  run_depths(run, col, buffers);
  float depth = 0.0f;
  int at = run.begin;
  for (int c = run.begin; c < run.end; ++c) {  // the first in raster order among equals
    const float d = depth_of(buffers.out[static_cast<std::size_t>(c - run.begin + 1)]);
    if (d > depth) {
      depth = d;
      at = c;
    }
  }
  room.take(depth, {at, run.row});
}

// Each wanted room's deepest cell among the box's interior runs (best; the box's column grid of
// Depth). Each room's runs are taken from the widest reach down, until a run's reach (a bound of
// its depths) is below the deepest cell found: the first transformed whole, the others' cells
// searched where they may be deeper.
template <typename Depth>
void deepest_interior_cells(const cv::Mat& labels, const cv::Rect& box, const WantedIds& wanted, std::vector<cv::Point>& best) {
  const cv::Mat column = column_distances<Depth>(labels, box);
  const std::vector<InteriorRun> runs = interior_runs<Depth>(labels, box, column);
  std::vector<std::size_t> order;
  order.reserve(runs.size());
  for (std::size_t k = 0; k < runs.size(); ++k)
    if (is_wanted(wanted, runs[k].id)) order.push_back(k);
  std::sort(order.begin(), order.end(), [&runs](std::size_t a, std::size_t b) {
    return runs[a].id != runs[b].id ? runs[a].id < runs[b].id : runs[a].reach > runs[b].reach;
  });
  std::vector<Deepest> deepest(best.size());
  EnvelopeBuffers buffers;
  for (const std::size_t k : order) {
    const InteriorRun& run = runs[k];
    Deepest& room = deepest[static_cast<std::size_t>(run.id)];
    if (run.reach < room.depth) continue;
    if (room.cell.x < 0) {
      deepest_of_first_run(run, column.ptr<Depth>(run.row), buffers, room);
    } else {
      search_run(run, column.ptr<Depth>(run.row), room);
    }
  }
  for (std::size_t id = 0; id < best.size(); ++id)
    if (wanted[id] != 0 && deepest[id].cell.x >= 0) best[id] = {box.x + deepest[id].cell.x, box.y + deepest[id].cell.y};
}

// For every wanted room id, the labelled cell (top-down grid) farthest from any cell of another
// label (into best; the others' entries untouched): the distance transform of the cells whose four
// neighbours all share their label (the float that cv::distanceTransform, DIST_L2 and
// DIST_MASK_PRECISE, gives: the rounded root of the exact squared distance), the first in raster
// order among equals. Rooms without such a cell (one cell thin) take their first cell in raster
// order. Works in within (the labels' box when empty), grown by one cell, which must hold every cell
// of the wanted rooms: a cell of a room beside another room's cell or none is not interior, so the
// nearest non-interior cell of a room's interior cell lies within the room's box (a staircase path
// to any nearer cell of another label leaves the room through one within the box of the two), and
// the distances and the raster order are those of the whole map.
void deepest_cells(const cv::Mat& labels, const cv::Rect& within, const WantedIds& wanted, std::vector<cv::Point>& best) {
  const cv::Rect labelled = within.empty() ? labelled_box(labels) : within;
  if (labelled.empty()) return;
  const cv::Rect box = cv::Rect(labelled.x - 1, labelled.y - 1, labelled.width + 2, labelled.height + 2) &
                       cv::Rect(0, 0, labels.cols, labels.rows);
  if (fits_short_depths(box)) {
    deepest_interior_cells<std::int16_t>(labels, box, wanted, best);
  } else {
    deepest_interior_cells<int>(labels, box, wanted, best);
  }
  first_cells_of_thin_rooms(labels, box, wanted, best);
}

int max_room_id(const Segmentation& s) {
  int max_id = 0;
  for (const Room& room : s.rooms) max_id = std::max(max_id, room.id);
  return max_id;
}

// Every room's deepest cell (deepest_cells() over the whole labels), by id.
std::vector<cv::Point> every_deepest_cell(const Segmentation& s) {
  const auto ids = static_cast<std::size_t>(max_room_id(s)) + 1;
  std::vector<cv::Point> best(ids, cv::Point(-1, -1));
  deepest_cells(s.labels, cv::Rect(), WantedIds(ids, 1), best);
  return best;
}

std::vector<RoomPlacement> placements_of(const Segmentation& s, const std::vector<cv::Point>& deepest) {
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

// in_frame() with each room's deepest cell given (by id; (-1, -1): none, its centroid is its place).
GridSegmentation placed_in_frame(Segmentation segmentation, const GridFrame& frame, const std::vector<cv::Point>& deepest) {
  GridSegmentation out;
  out.frame = frame;
  out.placements = placements_of(segmentation, deepest);
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

// The ids of the rooms with a cell on the labels' edge, sorted: such a cell is never interior, and
// may be once the map has grown past it.
std::vector<int> ids_on_edge(const cv::Mat& labels) {
  std::vector<int> ids;
  if (labels.empty()) return ids;
  const auto add_row = [&](int r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < labels.cols; ++c)
      if (row[c] > 0) ids.push_back(row[c]);
  };
  add_row(0);
  add_row(labels.rows - 1);
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    if (row[0] > 0) ids.push_back(row[0]);
    if (row[labels.cols - 1] > 0) ids.push_back(row[labels.cols - 1]);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

bool holds(const std::vector<int>& sorted, int id) { return std::binary_search(sorted.begin(), sorted.end(), id); }

}  // namespace

GridSegmentation in_frame(Segmentation segmentation, const GridFrame& frame) {
  const std::vector<cv::Point> deepest = every_deepest_cell(segmentation);
  return placed_in_frame(std::move(segmentation), frame, deepest);
}

GridSegmentation segment_grid(const OccupancyGrid& grid, const GridFrame& frame, const SegmentOptions& options,
                              SegmentationInput* input) {
  return in_frame(segment(grid, options, input), frame);
}

GridSegmentation update_grid(IncrementalSegmenter& segmenter, const OccupancyGrid& grid, const GridFrame& frame) {
  return in_frame(segmenter.update(grid), frame);
}

const FramedUpdates::Kept* FramedUpdates::kept_cell(int id) const {
  const auto it = std::lower_bound(cells_.begin(), cells_.end(), id, [](const Kept& k, int value) { return k.id < value; });
  return it != cells_.end() && it->id == id ? &*it : nullptr;
}

// A room keeps its deepest cell, moved by the frame's shift, when the update left its cells as they
// were (the report does not list it) and, if the frame changed, when it has no cell on the old
// edge or the new one (where a cell that could not be interior may now be). Every other room is
// measured again: within the report's box of the listed rooms when they are all it has to measure,
// else over the whole labels.
GridSegmentation FramedUpdates::place(const IncrementalSegmenter& segmenter, const GridFrame& frame) {
  const Segmentation& result = segmenter.result();
  const IncrementalUpdateReport& report = segmenter.last_update();
  const bool kept = segmenter_ == &segmenter && result_ + 1 == segmenter.results();
  const std::vector<int> edge = ids_on_edge(result.labels);
  const bool moved = report.shift != cv::Point() || result.labels.size() != size_;
  const auto ids = static_cast<std::size_t>(max_room_id(result)) + 1;
  std::vector<cv::Point> best(ids, cv::Point(-1, -1));
  WantedIds wanted(ids, 0);
  bool only_listed = true;
  reused_ = 0;
  for (const Room& room : result.rooms) {
    const int id = room.id;
    const bool listed = report.every_room_relabelled || holds(report.relabelled_rooms, id);
    const Kept* old = kept ? kept_cell(id) : nullptr;
    if (!listed && old != nullptr && (!moved || (!holds(edge_, id) && !holds(edge, id)))) {
      best[static_cast<std::size_t>(id)] = old->cell.x < 0 ? old->cell : old->cell + report.shift;
      ++reused_;
      continue;
    }
    wanted[static_cast<std::size_t>(id)] = 1;
    only_listed = only_listed && listed && !report.every_room_relabelled;
  }
  if (reused_ < static_cast<int>(result.rooms.size()))
    deepest_cells(result.labels, only_listed ? report.relabelled_box : cv::Rect(), wanted, best);
  cells_.clear();
  for (const Room& room : result.rooms) cells_.push_back({room.id, best[static_cast<std::size_t>(room.id)]});
  edge_ = edge;
  size_ = result.labels.size();
  segmenter_ = &segmenter;
  result_ = segmenter.results();
  return placed_in_frame(result, frame, best);
}

}  // namespace topocut
