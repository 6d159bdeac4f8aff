#include "topocut/segmentation/carried_ids.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "topocut/core/error.h"

namespace topocut {

namespace detail {

std::vector<IdOverlap> id_overlaps(const cv::Mat& old_ids, const cv::Mat& next, const cv::Mat& mask, int labels,
                                   std::vector<long long>* sizes) {
  std::unordered_map<long long, long long> count;
  if (sizes) sizes->assign(static_cast<std::size_t>(labels) + 1, 0);
  auto key = [](int label, int old) { return (static_cast<long long>(label) << 32) | static_cast<unsigned>(old); };
  // Run by run along the rows: a hash per run, not per cell.
  for (int r = 0; r < next.rows; ++r) {
    const int* n = next.ptr<int>(r);
    const int* p = old_ids.ptr<int>(r);
    const unsigned char* m = mask.empty() ? nullptr : mask.ptr<unsigned char>(r);
    int c = 0;
    while (c < next.cols) {
      if (n[c] <= 0 || n[c] > labels || (m && !m[c])) {
        ++c;
        continue;
      }
      const int label = n[c], old = p[c], start = c;
      while (c < next.cols && n[c] == label && p[c] == old && (!m || m[c])) ++c;
      if (sizes) (*sizes)[static_cast<std::size_t>(label)] += c - start;
      if (old > 0) count[key(label, old)] += c - start;
    }
  }
  std::vector<IdOverlap> out;
  out.reserve(count.size());
  for (const auto& [k, cells] : count) out.push_back({cells, static_cast<int>(k >> 32), static_cast<int>(k & 0xffffffff)});
  std::sort(out.begin(), out.end(), [](const IdOverlap& a, const IdOverlap& b) {
    return std::tie(b.cells, a.label, a.old) < std::tie(a.cells, b.label, b.old);
  });
  return out;
}

}  // namespace detail

std::vector<int> carried_ids(const cv::Mat& previous, const cv::Mat& next, int labels, int& next_id,
                             const cv::Mat& retired, const std::vector<long long>* retired_cells) {
  auto fits = [&](const cv::Mat& m) { return m.empty() || (m.type() == CV_32SC1 && m.size() == next.size()); };
  if (next.type() != CV_32SC1 || !fits(previous) || !fits(retired))
    throw Error("internal: ids are carried between label images (CV_32SC1) of one size");
  std::vector<int> ids(static_cast<std::size_t>(labels) + 1, 0);
  std::unordered_set<int> taken;
  if (!previous.empty()) {
    for (const detail::IdOverlap& o : detail::id_overlaps(previous, next, cv::Mat(), labels)) {
      if (ids[static_cast<std::size_t>(o.label)] != 0 || taken.count(o.old)) continue;
      ids[static_cast<std::size_t>(o.label)] = o.old;
      taken.insert(o.old);
    }
  }
  revived_ids(retired, next, cv::Mat(), ids, [&](int id) { return !taken.count(id) && id < next_id; }, retired_cells);
  for (int l = 1; l <= labels; ++l)
    if (ids[static_cast<std::size_t>(l)] == 0) ids[static_cast<std::size_t>(l)] = next_id++;
  return ids;
}

Segmentation renamed(Segmentation s, const std::vector<int>& ids) {
  auto id_of = [&](int label) {
    if (label <= 0) return 0;
    if (static_cast<std::size_t>(label) >= ids.size()) throw Error("internal: a label has no carried id");
    return ids[static_cast<std::size_t>(label)];
  };
  cv::Mat labels(s.labels.size(), CV_32SC1);
  for (int r = 0; r < labels.rows; ++r) {
    const int* in = s.labels.ptr<int>(r);
    int* out = labels.ptr<int>(r);
    for (int c = 0; c < labels.cols; ++c) out[c] = id_of(in[c]);
  }
  s.labels = labels;
  for (Room& room : s.rooms) room.id = id_of(room.id);
  std::sort(s.rooms.begin(), s.rooms.end(), [](const Room& a, const Room& b) { return a.id < b.id; });
  for (Passage& p : s.passages) {
    const int a = id_of(p.room_a), b = id_of(p.room_b);
    p.room_a = std::min(a, b);
    p.room_b = std::max(a, b);
  }
  std::stable_sort(s.passages.begin(), s.passages.end(), [](const Passage& x, const Passage& y) {
    return std::tie(x.room_a, x.room_b, x.cut.a.x, x.cut.a.y, x.cut.b.x, x.cut.b.y) <
           std::tie(y.room_a, y.room_b, y.cut.a.x, y.cut.a.y, y.cut.b.x, y.cut.b.y);
  });
  return s;
}

bool frame_shift(const Point2& from, int rows_from, const Point2& to, int rows_to, double resolution, cv::Point& shift) {
  const double columns = (from.x - to.x) / resolution;
  const double rows = rows_to - rows_from - (from.y - to.y) / resolution;
  auto whole = [](double v) { return std::isfinite(v) && std::abs(v - std::round(v)) < 1e-3 && std::abs(v) < 1e9; };
  if (!whole(columns) || !whole(rows)) return false;
  shift = cv::Point(static_cast<int>(std::lround(columns)), static_cast<int>(std::lround(rows)));
  return true;
}

Segmentation IdCarrier::carry(const Segmentation& next) {
  cv::Mat previous;  // the previous labels in next's frame
  cv::Point shift;
  if (!previous_.empty() && std::abs(resolution_ - next.resolution) <= 1e-12 * next.resolution &&
      frame_shift(origin_, previous_.rows, next.origin, next.labels.rows, next.resolution, shift)) {
    previous = cv::Mat::zeros(next.labels.size(), CV_32SC1);
    const cv::Rect kept = cv::Rect(shift.x, shift.y, previous_.cols, previous_.rows) & cv::Rect(cv::Point(), previous.size());
    if (!kept.empty()) previous_(kept - shift).copyTo(previous(kept));
  }
  const int labels = next.rooms.empty() ? 0 : next.rooms.back().id;
  Segmentation out = renamed(next, carried_ids(previous, next.labels, labels, next_id_));
  previous_ = out.labels;
  origin_ = next.origin;
  resolution_ = next.resolution;
  return out;
}

}  // namespace topocut
