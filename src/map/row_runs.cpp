#include "map/row_runs.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace topocut {

namespace {

// Bit i: whether cell i of the 64 at p is set, a cell being set when it equals pattern (or, with
// set_when_equal false, when it differs).
std::uint64_t set_bits(const unsigned char* p, unsigned char pattern, bool set_when_equal) {
  std::uint64_t equal = 0;
#if defined(__SSE2__)
  const __m128i broadcast = _mm_set1_epi8(static_cast<char>(pattern));
  for (int k = 0; k < 4; ++k) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16 * k));
    equal |= static_cast<std::uint64_t>(static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(v, broadcast)))) << (16 * k);
  }
#else
  for (int i = 0; i < 64; ++i) equal |= static_cast<std::uint64_t>(p[i] == pattern) << i;
#endif
  return set_when_equal ? equal : ~equal;
}

// Appends the runs of one row's set cells, 64 cells at a time: a block that continues the current
// state is skipped, in a mixed one the state changes are its set bits' edges. The row's last cells
// (fewer than 64) are copied into a block whose remaining cells are not set, so a run that reaches
// the row's end closes there.
void scan_row(const unsigned char* p, int w, unsigned char pattern, bool set_when_equal, RowRuns& out) {
  bool in = false;
  int start = 0;
  unsigned char tail[64];
  for (int x = 0; x < w; x += 64) {
    const unsigned char* block = p + x;
    if (x + 64 > w) {
      std::memset(tail, set_when_equal ? pattern ^ 1 : pattern, sizeof tail);
      std::memcpy(tail, p + x, static_cast<std::size_t>(w - x));
      block = tail;
    }
    const std::uint64_t bits = set_bits(block, pattern, set_when_equal);
    if (bits == (in ? ~std::uint64_t{0} : 0)) continue;
    // Bit i of changes: cell x+i differs from the cell before it.
    std::uint64_t changes = bits ^ ((bits << 1) | (in ? 1 : 0));
    while (changes != 0) {
      const int i = std::countr_zero(changes);
      changes &= changes - 1;
      if (in) out.push({start, x + i});
      else start = x + i;
      in = !in;
    }
  }
  if (in) out.push({start, w});  // a row of a multiple of 64 cells ending in a run
  out.end_row();
}

RowRuns scan(const cv::Mat& image, unsigned char pattern, bool set_when_equal) {
  CV_Assert(image.type() == CV_8UC1);
  RowRuns runs(image.cols);
  runs.reserve(static_cast<std::size_t>(image.rows) * 4, image.rows);
  for (int y = 0; y < image.rows; ++y) scan_row(image.ptr<unsigned char>(y), image.cols, pattern, set_when_equal, runs);
  return runs;
}

// a ∪ b of one row, appended to out (canonical).
void unite_into(std::span<const CellRun> a, std::span<const CellRun> b, std::vector<CellRun>& out) {
  const std::size_t first = out.size();
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    const CellRun next = j == b.size() || (i < a.size() && a[i].begin <= b[j].begin) ? a[i++] : b[j++];
    if (out.size() > first && next.begin <= out.back().end) {
      out.back().end = std::max(out.back().end, next.end);
    } else {
      out.push_back(next);
    }
  }
}

// a ∩ b of one row, appended to out.
void intersect_into(std::span<const CellRun> a, std::span<const CellRun> b, std::vector<CellRun>& out) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const int lo = std::max(a[i].begin, b[j].begin), hi = std::min(a[i].end, b[j].end);
    if (lo < hi) out.push_back({lo, hi});
    if (a[i].end < b[j].end) ++i;
    else ++j;
  }
}

// Appends run to out, joining it to the last run when they overlap or touch (runs come in order of
// their first cell).
void append_joined(std::vector<CellRun>& out, CellRun run) {
  if (!out.empty() && run.begin <= out.back().end) {
    out.back().end = std::max(out.back().end, run.end);
  } else {
    out.push_back(run);
  }
}

// acc ∪ (the runs of row, each grown by g cells at both ends, clipped to [0, w)), into out.
void unite_grown(std::span<const CellRun> acc, std::span<const CellRun> row, int g, int w, std::vector<CellRun>& out) {
  out.clear();
  std::size_t i = 0, j = 0;
  while (i < acc.size() || j < row.size()) {
    if (j == row.size() || (i < acc.size() && acc[i].begin <= row[j].begin - g)) {
      append_joined(out, acc[i++]);
    } else {
      append_joined(out, {std::max(0, row[j].begin - g), std::min(w, row[j].end + g)});
      ++j;
    }
  }
}

// The runs of one row from the first not yet passed to its end.
struct RunCursor {
  const CellRun* at;
  const CellRun* end;
};

// Every run of an image shrunk (or grown) by each distinct half width of a disc, at the run's own
// index of all(): copy(k) holds the runs changed by half_widths[k], row after row as in the image.
// A run that shrinking removes becomes one ending before every cell (the cursors pass over it), so
// no row is built.
class ChangedRuns {
 public:
  ChangedRuns(const RowRuns& runs, const std::vector<int>& half_widths, bool shrink) : runs_(runs) {
    const std::span<const CellRun> all = runs.all();
    std::vector<std::size_t> copy_of_k;
    for (std::size_t k = 0; k < half_widths.size(); ++k) {
      const int c = half_widths[k];
      if (c != 0 && (k == 0 || c != half_widths[k - 1])) {
        copies_.emplace_back(all.size());
        std::vector<CellRun>& copy = copies_.back();
        for (std::size_t i = 0; i < all.size(); ++i) {
          const CellRun& r = all[i];
          copy[i] = !shrink ? CellRun{r.begin - c, r.end + c} : r.end - r.begin > 2 * c ? CellRun{r.begin + c, r.end - c} : kPassed;
        }
      }
      copy_of_k.push_back(c == 0 ? kUnchanged : copies_.size() - 1);
    }
    for (const std::size_t c : copy_of_k) of_k_.push_back(c == kUnchanged ? all.data() : copies_[c].data());
  }

  // Row y's runs changed by half_widths[k].
  RunCursor row(int k, int y) const {
    const CellRun* first = of_k_[static_cast<std::size_t>(k)] + runs_.index_of_row(y);
    return {first, first + runs_.row(y).size()};
  }

 private:
  static constexpr std::size_t kUnchanged = std::numeric_limits<std::size_t>::max();  // a half width 0
  static constexpr CellRun kPassed{std::numeric_limits<int>::min(), std::numeric_limits<int>::min()};
  const RowRuns& runs_;
  std::vector<std::vector<CellRun>> copies_;
  std::vector<const CellRun*> of_k_;
};

// The intersection of the rows (of shrunk runs), appended to out; the cursors are used up. All
// rows at once, leapfrogging: the rows are visited in turn, each passing its runs that end by lo; a
// run beginning after lo moves lo there, and once every row's run holds lo, the cells from lo to
// the nearest end are in the intersection. No row of partial results is written.
void intersect_rows(std::vector<RunCursor>& rows, std::vector<CellRun>& out) {
  const std::size_t k = rows.size();
  int lo = -1, hi = std::numeric_limits<int>::max();
  std::size_t holding = 0;  // rows visited in turn since lo last moved, each holding lo
  for (std::size_t i = 0;; i = i + 1 == k ? 0 : i + 1) {
    RunCursor& c = rows[i];
    while (c.at != c.end && c.at->end <= lo) ++c.at;
    if (c.at == c.end) return;
    if (c.at->begin > lo) {
      lo = c.at->begin;
      hi = c.at->end;
      holding = 1;
    } else {
      hi = std::min(hi, c.at->end);
      ++holding;
    }
    if (holding == k) {
      out.push_back({lo, hi});
      lo = hi;
      hi = std::numeric_limits<int>::max();
      holding = 0;
    }
  }
}

// The union of the rows (of grown runs) within [0, w), appended to out (runs that meet joined);
// the cursors are used up. From the leftmost first cell, the rows are visited in turn, each
// passing its runs that begin within the run so far and extending it; once every row has been
// visited without extending it, the run is complete, and the rows' next runs give the next one's
// first cell.
void unite_rows(std::vector<RunCursor>& rows, int w, std::vector<CellRun>& out) {
  constexpr int kNone = std::numeric_limits<int>::max();
  const std::size_t k = rows.size();
  int lo = kNone;
  for (const RunCursor& c : rows)
    if (c.at != c.end) lo = std::min(lo, c.at->begin);
  while (lo != kNone) {
    int hi = lo, next = kNone;
    std::size_t quiet = 0;  // rows visited in turn since hi last moved
    for (std::size_t i = 0; quiet < k; i = i + 1 == k ? 0 : i + 1) {
      RunCursor& c = rows[i];
      bool extended = false;
      for (; c.at != c.end && c.at->begin <= hi; ++c.at) {
        if (c.at->end > hi) {
          hi = c.at->end;
          extended = true;
        }
      }
      const int after = c.at != c.end ? c.at->begin : kNone;
      if (extended) {
        quiet = 1;
        next = after;
      } else {
        ++quiet;
        next = std::min(next, after);
      }
    }
    out.push_back({std::max(0, lo), std::min(w, hi)});
    lo = next;
  }
}

bool same_runs(std::span<const CellRun> a, std::span<const CellRun> b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const CellRun& x, const CellRun& y) {
           return x.begin == y.begin && x.end == y.end;
         });
}

// Per row: how many rows up to it (itself included) each equal the row before them. A row whose
// rows in reach all repeat is the row before it, which spares maps drawn by hand most of the work.
std::vector<int> equal_row_streaks(const RowRuns& runs) {
  std::vector<int> streak(static_cast<std::size_t>(runs.height()), 0);
  for (int y = 1; y < runs.height(); ++y)
    if (same_runs(runs.row(y), runs.row(y - 1))) streak[static_cast<std::size_t>(y)] = streak[static_cast<std::size_t>(y) - 1] + 1;
  return streak;
}

// Whether row y's output equals row y - 1's: the rows [y - reach, y + reach] lie in the image and
// each equals the row before it.
bool repeats(const std::vector<int>& streak, int y, int reach) {
  return y > reach && y + reach < static_cast<int>(streak.size()) &&
         streak[static_cast<std::size_t>(y + reach)] >= 2 * reach + 1;
}

// Whether row y + dy (dy != 0) equals the row next to it towards row y. An element's row dy then
// adds nothing to an erosion or dilation of row y: its half width is at most the nearer row's, so
// its shrunk runs hold the nearer row's and its grown runs are within them.
bool repeats_nearer(const std::vector<int>& streak, int y, int dy) {
  return streak[static_cast<std::size_t>(dy > 0 ? y + dy : y + dy + 1)] >= 1;
}

// Per row: the next row that differs from the row before it (the start of the next band of equal
// rows; the height if there is none).
std::vector<int> next_bands(const std::vector<int>& streak) {
  const int h = static_cast<int>(streak.size());
  std::vector<int> next(streak.size(), h);
  for (int y = h - 2; y >= 0; --y)
    next[static_cast<std::size_t>(y)] = streak[static_cast<std::size_t>(y) + 1] == 0 ? y + 1 : next[static_cast<std::size_t>(y) + 1];
  return next;
}

// Calls visit(dy) for row y and for each row y + dy within r rows and the image that does not
// repeat its neighbour towards row y (repeats_nearer): the last row of each band of equal rows
// above and the first of each below, found band by band.
template <class Visit>
void for_each_row_adding(const std::vector<int>& streak, const std::vector<int>& next_band, int y, int r, Visit visit) {
  const auto at = [](const std::vector<int>& v, int i) { return v[static_cast<std::size_t>(i)]; };
  visit(0);
  for (int b = y - at(streak, y) - 1; b >= std::max(0, y - r); b -= at(streak, b) + 1) visit(b - y);
  const int last = std::min(static_cast<int>(streak.size()) - 1, y + r);
  for (int b = at(next_band, y); b <= last; b = at(next_band, b)) visit(b - y);
}

// Runs of each row shrunk by n at both ends, except at the image's edges (a set border).
RowRuns shrink_rows_set_border(const RowRuns& runs, int n) {
  const int w = runs.width();
  RowRuns out(w);
  out.reserve(runs.all().size(), runs.height());
  for (int y = 0; y < runs.height(); ++y) {
    for (const CellRun& r : runs.row(y)) {
      const int b = r.begin == 0 ? 0 : r.begin + n, e = r.end == w ? w : r.end - n;
      if (b < e) out.push({b, e});
    }
    out.end_row();
  }
  return out;
}

// Row y of the result is the intersection of the rows [y - n, y + n] within the image (van Herk /
// Gil-Werman: within blocks of 2n + 1 rows, running intersections from each block's top and from
// its bottom; a window is one block's suffix and the next block's prefix).
RowRuns intersect_sliding_rows(const RowRuns& runs, int n) {
  const int h = runs.height(), w = runs.width(), block = 2 * n + 1;
  // A row equal to the one before it leaves a running intersection as it is, and a window whose
  // rows differ from the last window's only by such repeats has the same intersection.
  const std::vector<int> streak = equal_row_streaks(runs);
  const auto repeated = [&streak](int y) { return streak[static_cast<std::size_t>(y)] >= 1; };
  RowRuns prefix(w), suffix_reversed(w), out(w);  // the suffix of row y is row h - 1 - y of suffix_reversed
  for (RowRuns* image : {&prefix, &suffix_reversed, &out}) image->reserve(runs.all().size(), h);
  std::vector<CellRun> row;
  for (int y = 0; y < h; ++y) {
    if (y % block == 0) {
      prefix.append_row(runs.row(y));
    } else if (repeated(y)) {
      prefix.repeat_row();
    } else {
      row.clear();
      intersect_into(prefix.row(y - 1), runs.row(y), row);
      prefix.append_row(row);
    }
  }
  for (int y = h - 1; y >= 0; --y) {
    if (y % block == block - 1 || y == h - 1) {
      suffix_reversed.append_row(runs.row(y));
    } else if (repeated(y + 1)) {
      suffix_reversed.repeat_row();
    } else {
      row.clear();
      intersect_into(runs.row(y), suffix_reversed.row(h - 2 - y), row);
      suffix_reversed.append_row(row);
    }
  }
  for (int y = 0; y < h; ++y) {
    const int lo = std::max(0, y - n), hi = std::min(h - 1, y + n);
    if (y > 0 && (hi == y - 1 + n || repeated(hi)) && (lo == std::max(0, y - 1 - n) || repeated(lo))) {
      out.repeat_row();
    } else if (lo / block == hi / block) {
      // Within one block the window starts it (the image's top) or ends where the image does.
      out.append_row(lo % block == 0 ? prefix.row(hi) : suffix_reversed.row(h - 1 - lo));
    } else {
      row.clear();
      intersect_into(suffix_reversed.row(h - 1 - lo), prefix.row(hi), row);
      out.append_row(row);
    }
  }
  return out;
}

// Erosion by a (2n+1)-cell square with a set border: separable into rows, then columns.
RowRuns erode_square_set_border(const RowRuns& runs, int n) {
  return intersect_sliding_rows(shrink_rows_set_border(runs, n), n);
}

// a \ b of one row, appended to out.
void subtract_into(std::span<const CellRun> a, std::span<const CellRun> b, std::vector<CellRun>& out) {
  std::size_t j = 0;
  for (const CellRun& r : a) {
    int from = r.begin;
    while (j < b.size() && b[j].end <= from) ++j;
    for (std::size_t k = j; k < b.size() && b[k].begin < r.end; ++k) {
      if (b[k].begin > from) out.push_back({from, b[k].begin});
      from = std::max(from, b[k].end);
    }
    if (from < r.end) out.push_back({from, r.end});
  }
}

template <class Op>
RowRuns row_by_row(const RowRuns& a, const RowRuns& b, Op op) {
  CV_Assert(a.width() == b.width() && a.height() == b.height());
  RowRuns out(a.width());
  out.reserve(a.all().size() + b.all().size(), a.height());
  for (int y = 0; y < a.height(); ++y) out.add_row([&](std::vector<CellRun>& runs) { op(a.row(y), b.row(y), runs); });
  return out;
}

// Union-find over run indices; a component's root is its first run.
struct RunForest {
  std::vector<int> parent;
  explicit RunForest(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      int& p = parent[static_cast<std::size_t>(i)];
      p = parent[static_cast<std::size_t>(p)];
      i = p;
    }
    return i;
  }
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a < b) parent[static_cast<std::size_t>(b)] = a;
    else if (b < a) parent[static_cast<std::size_t>(a)] = b;
  }
};

}  // namespace

RowRuns no_runs(const RowRuns& like) {
  RowRuns out(like.width());
  for (int y = 0; y < like.height(); ++y) out.end_row();
  return out;
}

RowRuns runs_of(const cv::Mat& mask) { return scan(mask, 0, false); }

RowRuns runs_of_value(const cv::Mat& image, unsigned char value) { return scan(image, value, true); }

long long cell_count(const RowRuns& runs) {
  long long n = 0;
  for (const CellRun& r : runs.all()) n += r.end - r.begin;
  return n;
}

void paint(const RowRuns& runs, cv::Mat& image, unsigned char value) {
  CV_Assert(image.type() == CV_8UC1 && image.cols == runs.width() && image.rows == runs.height());
  for (int y = 0; y < runs.height(); ++y) {
    unsigned char* row = image.ptr<unsigned char>(y);
    for (const CellRun& r : runs.row(y)) std::memset(row + r.begin, value, static_cast<std::size_t>(r.end - r.begin));
  }
}

void write_mask(const RowRuns& runs, cv::Mat& image, unsigned char set, unsigned char unset) {
  CV_Assert(image.type() == CV_8UC1 && image.cols == runs.width() && image.rows == runs.height());
  for (int y = 0; y < runs.height(); ++y) {
    unsigned char* row = image.ptr<unsigned char>(y);
    int x = 0;
    for (const CellRun& r : runs.row(y)) {
      std::memset(row + x, unset, static_cast<std::size_t>(r.begin - x));
      std::memset(row + r.begin, set, static_cast<std::size_t>(r.end - r.begin));
      x = r.end;
    }
    std::memset(row + x, unset, static_cast<std::size_t>(runs.width() - x));
  }
}

// The operations as lambdas, not function pointers, so that they are inlined into the row loop.
RowRuns unite(const RowRuns& a, const RowRuns& b) {
  return row_by_row(a, b, [](std::span<const CellRun> x, std::span<const CellRun> y, std::vector<CellRun>& out) { unite_into(x, y, out); });
}
RowRuns intersect(const RowRuns& a, const RowRuns& b) {
  return row_by_row(a, b, [](std::span<const CellRun> x, std::span<const CellRun> y, std::vector<CellRun>& out) { intersect_into(x, y, out); });
}
RowRuns subtract(const RowRuns& a, const RowRuns& b) {
  return row_by_row(a, b, [](std::span<const CellRun> x, std::span<const CellRun> y, std::vector<CellRun>& out) { subtract_into(x, y, out); });
}

RowRuns complement(const RowRuns& a) {
  const int w = a.width();
  RowRuns out(w);
  out.reserve(a.all().size() + static_cast<std::size_t>(a.height()), a.height());
  for (int y = 0; y < a.height(); ++y) {
    int x = 0;
    for (const CellRun& r : a.row(y)) {
      if (r.begin > x) out.push({x, r.begin});
      x = r.end;
    }
    if (x < w) out.push({x, w});
    out.end_row();
  }
  return out;
}

std::vector<int> disc_half_widths(int r) {
  CV_Assert(r >= 1 && r <= 46340);  // r * r fits an int, as in OpenCV
  // getStructuringElement's own arithmetic for a (2r+1)-square ellipse, without its (2r+1)² cells.
  const double inv_r2 = 1.0 / (static_cast<double>(r) * r);
  std::vector<int> half(static_cast<std::size_t>(r) + 1);
  for (int dy = 0; dy <= r; ++dy)
    half[static_cast<std::size_t>(dy)] = cv::saturate_cast<int>(r * std::sqrt((r * r - dy * dy) * inv_r2));
  return half;
}

RowRuns erode(const RowRuns& runs, const std::vector<int>& half_widths) {
  const int r = static_cast<int>(half_widths.size()) - 1, h = runs.height();
  const std::vector<int> streak = equal_row_streaks(runs), next_band = next_bands(streak);
  const ChangedRuns shrunk(runs, half_widths, true);
  RowRuns out(runs.width());
  out.reserve(runs.all().size(), h);
  std::vector<RunCursor> rows;
  for (int y = 0; y < h; ++y) {
    if (y < r || y + r >= h) {  // an empty row beyond the image is in reach
      out.end_row();
      continue;
    }
    if (repeats(streak, y, r)) {
      out.repeat_row();
      continue;
    }
    rows.clear();
    for_each_row_adding(streak, next_band, y, r, [&](int dy) { rows.push_back(shrunk.row(std::abs(dy), y + dy)); });
    out.add_row([&rows](std::vector<CellRun>& into) { intersect_rows(rows, into); });
  }
  return out;
}

RowRuns dilate(const RowRuns& runs, const std::vector<int>& half_widths) {
  const int r = static_cast<int>(half_widths.size()) - 1, h = runs.height(), w = runs.width();
  const std::vector<int> streak = equal_row_streaks(runs), next_band = next_bands(streak);
  const ChangedRuns grown(runs, half_widths, false);
  RowRuns out(w);
  out.reserve(runs.all().size(), h);
  std::vector<RunCursor> rows;
  for (int y = 0; y < h; ++y) {
    if (repeats(streak, y, r)) {
      out.repeat_row();
      continue;
    }
    rows.clear();
    for_each_row_adding(streak, next_band, y, r, [&](int dy) {
      if (!runs.row(y + dy).empty()) rows.push_back(grown.row(std::abs(dy), y + dy));
    });
    out.add_row([&rows, w](std::vector<CellRun>& into) { unite_rows(rows, w, into); });
  }
  return out;
}

// The dilation (zero border) is the complement of the complement's erosion with a set border.
RowRuns close_square(const RowRuns& runs, int n) {
  return erode_square_set_border(complement(erode_square_set_border(complement(runs), n)), n);
}

RowRuns grow_within(const RowRuns& seed, const RowRuns& within, int steps) {
  CV_Assert(seed.width() == within.width() && seed.height() == within.height());
  const int h = seed.height(), w = seed.width();
  const std::vector<int> within_streak = equal_row_streaks(within);
  RowRuns current = seed;
  std::vector<CellRun> around, next;
  // Rows the last step changed (all, before the first): a row none of whose three rows changed
  // gives what it gave last time, which is the row as it is.
  std::vector<unsigned char> changed(static_cast<std::size_t>(h), 1), changed_now(static_cast<std::size_t>(h));
  const auto near_change = [&](int y) {
    return changed[static_cast<std::size_t>(y)] || (y > 0 && changed[static_cast<std::size_t>(y) - 1]) ||
           (y + 1 < h && changed[static_cast<std::size_t>(y) + 1]);
  };
  for (int step = 0; step < steps; ++step) {
    const std::vector<int> streak = equal_row_streaks(current);
    RowRuns grown(w);
    grown.reserve(current.all().size(), h);
    for (int y = 0; y < h; ++y) {
      changed_now[static_cast<std::size_t>(y)] = 0;
      if (!near_change(y)) {
        grown.append_row(current.row(y));
        continue;
      }
      if (repeats(streak, y, 1) && within_streak[static_cast<std::size_t>(y)] >= 1) {
        grown.repeat_row();
        changed_now[static_cast<std::size_t>(y)] = changed_now[static_cast<std::size_t>(y) - 1];
        continue;
      }
      // A row already all of within's cannot grow (a room's rows away from its thin parts).
      if (same_runs(current.row(y), within.row(y))) {
        grown.append_row(within.row(y));
        continue;
      }
      around.clear();
      for (int dy = -1; dy <= 1; ++dy) {
        if (y + dy < 0 || y + dy >= h || (dy != 0 && repeats_nearer(streak, y, dy))) continue;
        unite_grown(around, current.row(y + dy), 1, w, next);
        std::swap(around, next);
      }
      next.clear();
      intersect_into(around, within.row(y), next);
      changed_now[static_cast<std::size_t>(y)] = !same_runs(next, current.row(y));
      grown.append_row(next);
    }
    current = std::move(grown);
    std::swap(changed, changed_now);
  }
  return current;
}

std::vector<int> run_components(const RowRuns& runs, bool eight_connected, int& count) {
  const std::span<const CellRun> all = runs.all();
  RunForest forest(all.size());
  const int reach = eight_connected ? 1 : 0;  // a run touches the next row's runs this far beyond its ends
  for (int y = 1; y < runs.height(); ++y) {
    const std::size_t b0 = runs.index_of_row(y), b1 = y + 1 < runs.height() ? runs.index_of_row(y + 1) : all.size();
    std::size_t i = runs.index_of_row(y - 1), j = b0;
    while (i < b0 && j < b1) {
      if (all[i].begin < all[j].end + reach && all[j].begin < all[i].end + reach)
        forest.join(static_cast<int>(i), static_cast<int>(j));
      if (all[i].end < all[j].end) ++i;
      else ++j;
    }
  }
  std::vector<int> component(all.size());
  count = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const int root = forest.find(static_cast<int>(i));
    component[i] = root == static_cast<int>(i) ? count++ : component[static_cast<std::size_t>(root)];
  }
  return component;
}

RowRuns select_runs(const RowRuns& runs, const std::vector<unsigned char>& keep_run) {
  RowRuns out(runs.width());
  out.reserve(runs.all().size(), runs.height());
  const std::span<const CellRun> all = runs.all();
  for (int y = 0; y < runs.height(); ++y) {
    const std::size_t end = y + 1 < runs.height() ? runs.index_of_row(y + 1) : all.size();
    for (std::size_t i = runs.index_of_row(y); i < end; ++i)
      if (keep_run[i]) out.push(all[i]);
    out.end_row();
  }
  return out;
}

RowRuns reached_from_edge(const RowRuns& runs) {
  int count = 0;
  const std::vector<int> component = run_components(runs, false, count);
  std::vector<unsigned char> reached(static_cast<std::size_t>(count), 0);
  const int h = runs.height(), w = runs.width();
  std::size_t i = 0;
  for (int y = 0; y < h; ++y) {
    for (const CellRun& run : runs.row(y)) {
      if (run.begin == 0 || run.end == w || y == 0 || y == h - 1) reached[static_cast<std::size_t>(component[i])] = 1;
      ++i;
    }
  }
  std::vector<unsigned char> keep(component.size());
  for (std::size_t k = 0; k < keep.size(); ++k) keep[k] = reached[static_cast<std::size_t>(component[k])];
  return select_runs(runs, keep);
}

}  // namespace topocut
