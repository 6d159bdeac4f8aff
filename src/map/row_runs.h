#pragma once
// A binary image as the runs of set cells of each row (run-length encoding). The cleaning's masks
// are large uniform areas with short boundaries: on runs, its steps cost what the boundaries cost,
// not what the cells cost. Runs of a row are sorted, non-empty and separated by at least one unset
// cell (so two equal images have equal runs).
#include <cstddef>
#include <span>
#include <vector>

#include <opencv2/core.hpp>

namespace topocut {

struct CellRun {
  int begin = 0, end = 0;  // cells [begin, end) of a row
};

class RowRuns {
 public:
  RowRuns() = default;
  explicit RowRuns(int width) : width_(width) {}

  int width() const { return width_; }
  int height() const { return static_cast<int>(row_start_.size()) - 1; }
  std::span<const CellRun> row(int y) const {
    const std::size_t first = row_start_[static_cast<std::size_t>(y)];
    return {runs_.data() + first, row_start_[static_cast<std::size_t>(y) + 1] - first};
  }
  // Every run, row after row; index_of_row(y) is the index of row y's first run.
  std::span<const CellRun> all() const { return runs_; }
  std::size_t index_of_row(int y) const { return row_start_[static_cast<std::size_t>(y)]; }
  bool empty() const { return runs_.empty(); }

  // Building row after row: runs of the row begun last (sorted, separated), then end_row().
  void push(CellRun run) { runs_.push_back(run); }
  void end_row() { row_start_.push_back(runs_.size()); }
  void append_row(std::span<const CellRun> runs) {
    // One push per run: a row holds a few runs, for which a range insert's set-up costs more.
    for (const CellRun& run : runs) runs_.push_back(run);
    end_row();
  }
  // Appends the row that fill(std::vector<CellRun>& runs) appends to runs (sorted, separated; the
  // runs before are the rows before: fill must not read this image's runs).
  template <class Fill>
  void add_row(Fill fill) {
    fill(runs_);
    end_row();
  }
  // Appends a copy of the last row (there is one).
  void repeat_row() {
    const std::size_t first = index_of_row(height() - 1), end = runs_.size();
    for (std::size_t i = first; i < end; ++i) {
      const CellRun run = runs_[i];  // a copy: the push may move the runs
      runs_.push_back(run);
    }
    end_row();
  }
  void reserve(std::size_t runs, int rows) {
    runs_.reserve(runs);
    row_start_.reserve(static_cast<std::size_t>(rows) + 1);
  }

 private:
  int width_ = 0;
  std::vector<CellRun> runs_;
  // Per row: the index of its first run in runs_, and one more: the end of the last row (so a row
  // is found with no test for the first).
  std::vector<std::size_t> row_start_ = {0};
};

// No runs, in an image of the size of like.
RowRuns no_runs(const RowRuns& like);

// The runs of an 8-bit image's nonzero cells (of value's cells with runs_of_value).
RowRuns runs_of(const cv::Mat& mask);
RowRuns runs_of_value(const cv::Mat& image, unsigned char value);

// Cells in the runs.
long long cell_count(const RowRuns& runs);

// Sets the runs' cells of an 8-bit image of the runs' size to value.
void paint(const RowRuns& runs, cv::Mat& image, unsigned char value);

// Writes the image (8-bit, the runs' size) whole: set inside the runs, unset elsewhere.
void write_mask(const RowRuns& runs, cv::Mat& image, unsigned char set, unsigned char unset);

// Row by row set operations on images of one size.
RowRuns unite(const RowRuns& a, const RowRuns& b);
RowRuns intersect(const RowRuns& a, const RowRuns& b);
RowRuns subtract(const RowRuns& a, const RowRuns& b);
RowRuns complement(const RowRuns& a);

// The half-widths of the rows of OpenCV's elliptic structuring element of size 2r+1 (the disc the
// cleaning opens with), by distance from its middle row: half_widths[|dy|], dy = -r..r; r >= 1.
std::vector<int> disc_half_widths(int r);

// Morphology with a structuring element symmetric about its centre whose row dy (|dy| <= r) holds
// the cells |dx| <= half_widths[|dy|] (a disc_half_widths() disc), as cv::erode and cv::dilate give it
// with a zero constant border: cells beyond the image are unset. Cost: every output row merges the
// runs of the 2r+1 rows around it at once, each row's runs shrunk or grown beforehand once per
// distinct half width; a row in reach equal to its neighbour towards the middle adds nothing and is
// left out, and a row whose rows in reach all repeat copies the row before. So it grows with the
// element's height times the runs at most (with the bands of equal rows in reach on maps drawn
// square), not with its area times the cells.
RowRuns erode(const RowRuns& runs, const std::vector<int>& half_widths);
RowRuns dilate(const RowRuns& runs, const std::vector<int>& half_widths);

// Closing with a (2n+1)-cell square, as cv::dilate with a zero border followed by cv::erode with a
// set border (the image's edge does not erode). The square is separable, and the sliding unions and
// intersections over rows are van Herk's (prefixes and suffixes of blocks of 2n+1 rows): about three
// row operations per row whatever n, a copy where rows repeat.
RowRuns close_square(const RowRuns& runs, int n);

// seed grown `steps` times by one cell (8-neighbours) and cut back to within after each step: the
// cells of within at most `steps` 8-connected steps inside within from seed (seed inside within).
RowRuns grow_within(const RowRuns& seed, const RowRuns& within, int steps);

// Connected components of the runs (8- or 4-connected cells): the component of every run of all(),
// numbered from 0 in the order of their first run; count receives the number of components.
std::vector<int> run_components(const RowRuns& runs, bool eight_connected, int& count);

// The runs whose flag (by run index of all()) is set.
RowRuns select_runs(const RowRuns& runs, const std::vector<unsigned char>& keep_run);

// The cells of runs that a 4-connected flood from beyond the image's edge reaches through them: their
// components with a cell on the edge.
RowRuns reached_from_edge(const RowRuns& runs);

}  // namespace topocut
