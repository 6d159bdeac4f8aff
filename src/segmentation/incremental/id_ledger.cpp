#include "topocut/segmentation/id_ledger.h"

#include <algorithm>
#include <cmath>
#include <istream>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "topocut/core/error.h"
#include "topocut/core/value_ranges.h"

namespace topocut {

IdLedger::IdLedger(const cv::Size& size) { clear(size); }

IdLedger::IdLedger(int next_id, cv::Mat retired) : next_id_(next_id), retired_(std::move(retired)) { count_retired(); }

std::vector<int> IdLedger::carry(const cv::Mat& previous, const cv::Mat& next, int labels) {
  const std::vector<int> ids = carried_ids(previous, next, labels, next_id_, retired_, &retired_cells_);
  if (previous.empty()) return ids;
  std::vector<char> kept(static_cast<std::size_t>(next_id_), 0);
  for (const int id : ids)
    if (id > 0) kept[static_cast<std::size_t>(id)] = 1;
  for (int r = 0; r < retired_.rows; ++r) {
    const int* l = previous.ptr<int>(r);
    int* out = retired_.ptr<int>(r);
    for (int c = 0; c < retired_.cols; ++c)
      if (l[c] > 0 && !kept[static_cast<std::size_t>(l[c])]) set_retired(out + c, l[c]);
  }
  return ids;
}

void IdLedger::retire(int row, int begin, int end, int id) {
  int* cell = retired_.ptr<int>(row);
  for (int c = begin; c < end; ++c) set_retired(cell + c, id);
}

// One cell of retired_ now holds id, the counts following (the id it held loses the cell).
void IdLedger::set_retired(int* cell, int id) {
  if (*cell == id) return;
  if (*cell > 0) --retired_cells_[static_cast<std::size_t>(*cell)];
  *cell = id;
  if (static_cast<std::size_t>(id) >= retired_cells_.size()) retired_cells_.resize(static_cast<std::size_t>(id) + 1, 0);
  ++retired_cells_[static_cast<std::size_t>(id)];
}

// retired_cells_ from retired_ (a ledger read back, or a frame that moved and lost cells).
void IdLedger::count_retired() {
  retired_cells_.assign(static_cast<std::size_t>(std::max(next_id_, 1)), 0);
  for (int r = 0; r < retired_.rows; ++r) {
    const int* cell = retired_.ptr<int>(r);
    for (int c = 0; c < retired_.cols; ++c) {
      const std::size_t id = static_cast<std::size_t>(std::max(cell[c], 0));
      if (id >= retired_cells_.size()) retired_cells_.resize(id + 1, 0);
      if (id > 0) ++retired_cells_[id];
    }
  }
}

void IdLedger::move(const cv::Point& shift, const cv::Size& size) {
  cv::Mat moved = cv::Mat::zeros(size, CV_32SC1);
  const cv::Rect old_in_new(shift, retired_.size());
  const cv::Rect kept = old_in_new & cv::Rect(cv::Point(), size);
  if (!kept.empty()) retired_(kept - shift).copyTo(moved(kept));
  retired_ = moved;
  count_retired();
}

void IdLedger::clear(const cv::Size& size) {
  retired_ = cv::Mat::zeros(size, CV_32SC1);
  retired_cells_.assign(static_cast<std::size_t>(next_id_), 0);
}

namespace {

constexpr const char* kMagic = "topocut-id-ledger";
constexpr int kVersion = 1;

// One label image as text: a line per row of "value count" runs.
void write_runs(std::ostream& out, const cv::Mat& image) {
  for (int r = 0; r < image.rows; ++r) {
    const int* row = image.ptr<int>(r);
    int c = 0;
    while (c < image.cols) {
      const int start = c;
      while (c < image.cols && row[c] == row[start]) ++c;
      out << (start == 0 ? "" : " ") << row[start] << ' ' << (c - start);
    }
    out << '\n';
  }
}

// One label image's runs as read, each checked against the declared size, before any image is made:
// a damaged or truncated file that declares a huge map fails without allocating it (the runs held
// are never more than the file's own length).
struct Run {
  int value = 0;
  int count = 0;
};

std::vector<Run> read_runs(std::istream& in, const cv::Size& size, int max_id, const char* what) {
  std::vector<Run> runs;
  for (int r = 0; r < size.height; ++r) {
    int c = 0;
    while (c < size.width) {
      long long value = 0, count = 0;
      if (!(in >> value >> count) || value < 0 || value >= max_id || count <= 0 || count > size.width - c)
        throw Error(std::string("the id ledger's ") + what + " are damaged (row " + std::to_string(r) + ")");
      runs.push_back({static_cast<int>(value), static_cast<int>(count)});
      c += static_cast<int>(count);
    }
  }
  return runs;
}

// The image the runs of read_runs() describe, row after row.
cv::Mat image_of_runs(const std::vector<Run>& runs, const cv::Size& size) {
  cv::Mat image(size, CV_32SC1);
  int* cell = image.ptr<int>(0);  // a new Mat is continuous: the rows follow each other
  for (const Run& run : runs) cell = std::fill_n(cell, run.count, run.value);
  return image;
}

}  // namespace

void write_ledger(std::ostream& out, const IdLedger& ledger, const Segmentation& published) {
  const cv::Mat& labels = published.labels;
  if (labels.type() != CV_32SC1 || labels.size() != ledger.retired().size())
    throw Error("internal: a ledger is saved with labels of its own size");
  out.precision(17);
  out << kMagic << ' ' << kVersion << '\n'
      << "next_id " << ledger.next_id() << '\n'
      << "resolution " << published.resolution << '\n'
      << "origin " << published.origin.x << ' ' << published.origin.y << '\n'
      << "size " << labels.cols << ' ' << labels.rows << '\n'
      << "labels\n";
  write_runs(out, labels);
  out << "retired\n";
  write_runs(out, ledger.retired());
  if (!out) throw Error("the id ledger could not be written");
}

SavedLedger read_ledger(std::istream& in) {
  std::string magic, key;
  int version = 0;
  if (!(in >> magic >> version) || magic != kMagic) throw Error("not an id ledger (it must start with 'topocut-id-ledger')");
  if (version != kVersion) throw Error("id ledger version " + std::to_string(version) + " is not supported (only 1)");
  long long next_id = 0, width = 0, height = 0;
  double resolution = 0.0, x = 0.0, y = 0.0;
  auto expect = [&](const char* name) {
    if (!(in >> key) || key != name) throw Error(std::string("the id ledger lacks its '") + name + "' line");
  };
  expect("next_id");
  if (!(in >> next_id) || next_id < 1 || next_id > std::numeric_limits<int>::max())
    throw Error("the id ledger's next_id must be a whole number from 1 to 2147483647");
  expect("resolution");
  in >> resolution;
  expect("origin");
  in >> x >> y;
  expect("size");
  in >> width >> height;
  if (!in) throw Error("the id ledger's resolution, origin and size must be numbers");
  check_resolution(resolution, "the id ledger's resolution");
  check_world_coordinate(x, "the id ledger's origin x");
  check_world_coordinate(y, "the id ledger's origin y");
  // OpenCV's largest side, and a quarter of a gigacell: far beyond any map, short of memory trouble.
  if (width < 1 || height < 1 || width > (1 << 20) || height > (1 << 20) || width * height > (1LL << 28))
    throw Error("the id ledger's size must be 1 to 1048576 cells a side and at most 2^28 cells");
  const cv::Size size(static_cast<int>(width), static_cast<int>(height));
  SavedLedger saved;
  expect("labels");
  const std::vector<Run> label_runs = read_runs(in, size, static_cast<int>(next_id), "labels");
  expect("retired");
  const std::vector<Run> retired_runs = read_runs(in, size, static_cast<int>(next_id), "retired ids");
  saved.published.labels = image_of_runs(label_runs, size);
  const cv::Mat retired = image_of_runs(retired_runs, size);
  saved.published.resolution = resolution;
  saved.published.origin = {x, y};
  saved.ledger = IdLedger(static_cast<int>(next_id), retired);
  return saved;
}

}  // namespace topocut
