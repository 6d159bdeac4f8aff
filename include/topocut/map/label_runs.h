#pragma once
// A label image as the runs of equal labels of each row (run-length encoding): room outlines and
// extents read a map's rooms run by run, at the cost of their boundaries rather than their cells,
// and pieces become runs without a map-sized image.
#include <cstddef>
#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"
#include "topocut/map/rasterize.h"

namespace topocut {

// Cells [begin, end) of a row, all labelled label (> 0).
struct LabelRun {
  int begin = 0, end = 0;
  int label = 0;
};

// Per row, the maximal runs of equal nonzero labels in column order (cells between them: label 0).
class LabelRuns {
 public:
  LabelRuns() = default;
  explicit LabelRuns(cv::Size size) : size_(size) {}

  cv::Size size() const { return size_; }
  std::span<const LabelRun> row(int y) const {
    const std::size_t first = index_of_row(y);
    return {runs_.data() + first, row_end_[static_cast<std::size_t>(y)] - first};
  }
  std::span<const LabelRun> all() const { return runs_; }
  std::size_t index_of_row(int y) const { return y == 0 ? 0 : row_end_[static_cast<std::size_t>(y) - 1]; }
  // The label of cell (x, y) of the image, 0 without one.
  int at(int y, int x) const;
  // The row of run index of all().
  int row_of(std::size_t index) const { return row_of_[index]; }
  // The labels that have runs, ascending, and the indices into all() of a label's runs, row after row
  // (none for a label without cells).
  std::span<const int> labels() const { return labels_; }
  std::span<const std::size_t> runs_of(int label) const;

  // Building row after row: the runs of the row begun last (maximal, in column order), then end_row();
  // index() once every row is in.
  void push(const LabelRun& run) {
    runs_.push_back(run);
    row_of_.push_back(static_cast<int>(row_end_.size()));
  }
  void end_row() { row_end_.push_back(runs_.size()); }
  void index();

 private:
  cv::Size size_;
  std::vector<LabelRun> runs_;
  std::vector<std::size_t> row_end_;             // per row: one past its last run
  std::vector<int> row_of_;                      // per run: its row
  std::vector<int> labels_;                      // the labels with runs, ascending
  std::vector<std::size_t> label_begin_, order_;  // order_[label_begin_[k]..label_begin_[k + 1]): label k's runs
};

// The runs of a label image (CV_32SC1; labels <= 0 are no label).
LabelRuns label_runs(const cv::Mat& labels);

// One past the last cell of the run of value that starts at row[c] (c < n, row[c] == value), n if it
// reaches the row's end: label images are mostly long runs, which this walks four cells at a compare
// where SSE2 is there.
int run_end(const int* row, int c, int n, int value);

// The runs of rasterize_polygons(polygons, size) without the image: polygon i's cells labelled i + 1,
// the earlier polygon keeping a cell two of them claim.
LabelRuns polygon_label_runs(const std::vector<PolygonWithHoles>& polygons, cv::Size size);

// polygon_label_runs() from the polygons' spans (polygon_spans(polygons, size)), for a caller that
// has rasterized them already.
LabelRuns polygon_label_runs(const std::vector<CellSpan>& spans, cv::Size size);

}  // namespace topocut
