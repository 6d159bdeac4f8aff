#include "topocut/map/label_runs.h"

#include <algorithm>
#include <numeric>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "topocut/core/error.h"
#include "topocut/map/rasterize.h"

namespace topocut {

namespace {

// Appends runs (disjoint) in column order to out, adjacent runs of one label joined.
void push_joined(std::vector<LabelRun>& runs, LabelRuns& out) {
  std::sort(runs.begin(), runs.end(), [](const LabelRun& a, const LabelRun& b) { return a.begin < b.begin; });
  for (std::size_t i = 0; i < runs.size();) {
    LabelRun run = runs[i++];
    while (i < runs.size() && runs[i].begin == run.end && runs[i].label == run.label) run.end = runs[i++].end;
    out.push(run);
  }
}

// The cells of spans (in the order they are painted) that no earlier span covers: each span clipped
// to the gaps the ones before it left.
std::vector<LabelRun> first_claims(const std::vector<LabelRun>& spans) {
  std::vector<LabelRun> taken;  // disjoint, in column order
  std::vector<LabelRun> next;
  for (const LabelRun& span : spans) {
    next.clear();
    int from = span.begin;
    for (const LabelRun& t : taken) {
      if (t.end <= from || t.begin >= span.end) {
        next.push_back(t);
        continue;
      }
      if (t.begin > from) next.push_back({from, t.begin, span.label});
      next.push_back(t);
      from = std::max(from, t.end);
    }
    if (from < span.end) next.push_back({from, span.end, span.label});
    std::sort(next.begin(), next.end(), [](const LabelRun& a, const LabelRun& b) { return a.begin < b.begin; });
    std::swap(taken, next);
  }
  return taken;
}

}  // namespace

int LabelRuns::at(int y, int x) const {
  const std::span<const LabelRun> runs = row(y);
  const auto run = std::upper_bound(runs.begin(), runs.end(), x, [](int c, const LabelRun& r) { return c < r.end; });
  return run != runs.end() && run->begin <= x ? run->label : 0;
}

std::span<const std::size_t> LabelRuns::runs_of(int label) const {
  const auto found = std::lower_bound(labels_.begin(), labels_.end(), label);
  if (found == labels_.end() || *found != label) return {};
  const std::size_t k = static_cast<std::size_t>(found - labels_.begin());
  return {order_.data() + label_begin_[k], label_begin_[k + 1] - label_begin_[k]};
}

void LabelRuns::index() {
  order_.resize(runs_.size());
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return runs_[a].label < runs_[b].label; });
  labels_.clear();
  label_begin_.clear();
  for (std::size_t i = 0; i < order_.size(); ++i) {
    const int label = runs_[order_[i]].label;
    if (labels_.empty() || labels_.back() != label) {
      labels_.push_back(label);
      label_begin_.push_back(i);
    }
  }
  label_begin_.push_back(order_.size());
}

int run_end(const int* row, int c, int n, int value) {
  int end = c + 1;
#if defined(__SSE2__)
  // Four cells at a compare while they all hold it (fewer instructions than the compiler's own
  // vectorising of an eight-cell test gave the leave-out rows' passes over whole label images).
  const __m128i wanted = _mm_set1_epi32(value);
  while (end + 4 <= n &&
         _mm_movemask_epi8(_mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(row + end)), wanted)) == 0xFFFF)
    end += 4;
#endif
  while (end < n && row[end] == value) ++end;
  return end;
}

LabelRuns label_runs(const cv::Mat& labels) {
  if (labels.type() != CV_32SC1) throw Error("label runs need a CV_32SC1 label image");
  LabelRuns out(labels.size());
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < labels.cols;) {
      const int end = run_end(row, c, labels.cols, row[c]);
      if (row[c] > 0) out.push({c, end, row[c]});
      c = end;
    }
    out.end_row();
  }
  out.index();
  return out;
}

LabelRuns polygon_label_runs(const std::vector<PolygonWithHoles>& polygons, cv::Size size) {
  return polygon_label_runs(polygon_spans(polygons, size), size);
}

LabelRuns polygon_label_runs(const std::vector<CellSpan>& spans, cv::Size size) {
  // The spans by row, each row's in the order rasterize_polygons paints them.
  std::vector<std::size_t> row_begin(static_cast<std::size_t>(size.height) + 1, 0);
  for (const CellSpan& span : spans) ++row_begin[static_cast<std::size_t>(span.row) + 1];
  std::partial_sum(row_begin.begin(), row_begin.end(), row_begin.begin());
  std::vector<LabelRun> by_row(spans.size());
  {
    std::vector<std::size_t> next(row_begin.begin(), row_begin.end() - 1);
    for (const CellSpan& span : spans) by_row[next[static_cast<std::size_t>(span.row)]++] = {span.first, span.end, span.index + 1};
  }
  LabelRuns out(size);
  std::vector<LabelRun> row, sorted;
  for (int r = 0; r < size.height; ++r) {
    row.assign(by_row.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(r)]),
               by_row.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(r) + 1]));
    sorted = row;
    std::sort(sorted.begin(), sorted.end(), [](const LabelRun& a, const LabelRun& b) { return a.begin < b.begin; });
    bool overlap = false;
    for (std::size_t i = 1; i < sorted.size() && !overlap; ++i) overlap = sorted[i].begin < sorted[i - 1].end;
    // Pieces tile the map; where they overlap anyway (floating-point unions), the earlier one keeps a cell.
    if (overlap) sorted = first_claims(row);
    push_joined(sorted, out);
    out.end_row();
  }
  out.index();
  return out;
}

}  // namespace topocut
