#include "topocut/exploration/room_stability.h"

#include <algorithm>
#include <cmath>

#include "topocut/core/error.h"
#include "topocut/core/time_statistics.h"

namespace topocut {

namespace {

// Ids index plain vectors (a hash per cell would dominate); this bounds their size.
constexpr double kMaxId = 1 << 24;

int max_label(const cv::Mat& labels) {
  if (labels.empty()) return 0;
  double low = 0.0, high = 0.0;
  cv::minMaxLoc(labels, &low, &high);
  if (low < 0.0) throw Error("room labels must not be negative");
  if (high > kMaxId) throw Error("room labels above 2^24 are not supported by the stability figures");
  return static_cast<int>(high);
}

// Per-id cell counts of one update, over the cells labelled in both images.
struct Transitions {
  std::vector<int> surviving, kept, gained;
  long long both = 0, changed = 0;
};

// The rectangle of new's frame that old's frame also covers, and the offset from new to old cells.
bool overlap(const cv::Mat& now, const Point2& origin, const cv::Mat& before, const Point2& before_origin,
             double resolution, cv::Rect* in_new, cv::Point* shift) {
  const double dc = std::round((origin.x - before_origin.x) / resolution);
  const double dr = before.rows - now.rows + std::round((before_origin.y - origin.y) / resolution);
  if (std::abs(dc) > 1e7 || std::abs(dr) > 1e7) return false;
  *shift = {static_cast<int>(dc), static_cast<int>(dr)};
  *in_new = cv::Rect(0, 0, now.cols, now.rows) & cv::Rect(-shift->x, -shift->y, before.cols, before.rows);
  return !in_new->empty();
}

Transitions count_transitions(const cv::Mat& now, const cv::Mat& before, const cv::Rect& in_new, const cv::Point& shift,
                              int ids) {
  Transitions t;
  t.surviving.assign(ids, 0);
  t.kept.assign(ids, 0);
  t.gained.assign(ids, 0);
  for (int r = in_new.y; r < in_new.br().y; ++r) {
    const int* n = now.ptr<int>(r);
    const int* p = before.ptr<int>(r + shift.y) + shift.x;
    for (int c = in_new.x; c < in_new.br().x; ++c) {
      const int a = p[c], b = n[c];
      if (a == 0 || b == 0) continue;
      ++t.both;
      ++t.surviving[a];
      if (a == b) {
        ++t.kept[a];
      } else {
        ++t.changed;
        ++t.gained[b];
      }
    }
  }
  return t;
}

}  // namespace

StabilityTracker::StabilityTracker(const StabilityOptions& options) : options_(options) {
  if (!(options.cell_change_fraction >= 0.0 && options.cell_change_fraction <= 1.0))
    throw Error("the cell change fraction of the stability figures must lie in [0, 1]");
}

void StabilityTracker::add(const cv::Mat& labels, const Point2& origin, double resolution) {
  if (labels.type() != CV_32SC1 && !labels.empty()) throw Error("the stability figures need CV_32SC1 room labels");
  if (!(std::isfinite(resolution) && resolution > 0.0)) throw Error("the stability figures need a positive resolution");
  const int ids = std::max(max_label(labels), max_label(previous_)) + 1;
  std::vector<char> present(ids, 0);
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < labels.cols; ++c) present[row[c]] = 1;
  }
  report_.final_rooms = 0;
  for (int id = 1; id < ids; ++id) {
    if (!present[id]) continue;
    ++report_.final_rooms;
    report_.rooms.try_emplace(id);
  }
  report_.distinct_ids = static_cast<int>(report_.rooms.size());

  cv::Rect in_new;
  cv::Point shift;
  if (!previous_.empty() && previous_resolution_ == resolution &&
      overlap(labels, origin, previous_, previous_origin_, resolution, &in_new, &shift)) {
    const Transitions t = count_transitions(labels, previous_, in_new, shift, ids);
    report_.churn.push_back(t.both > 0 ? static_cast<double>(t.changed) / static_cast<double>(t.both) : 0.0);
    for (int id = 1; id < ids; ++id) {
      if (t.surviving[id] == 0) continue;
      RoomHistory& room = report_.rooms[id];
      ++room.updates;
      const int moved = t.surviving[id] - t.kept[id] + t.gained[id];
      if (t.kept[id] == 0) {
        ++room.id_changes;
      } else if (moved > options_.cell_change_fraction * t.surviving[id]) {
        ++room.cell_changes;
      }
    }
  } else if (!previous_.empty()) {
    report_.churn.push_back(0.0);
  }
  previous_ = labels.clone();
  previous_origin_ = origin;
  previous_resolution_ = resolution;
}

StabilityReport StabilityTracker::report() const {
  StabilityReport out = report_;
  const TimeStatistics order = time_statistics(out.churn);  // the same median and nearest-rank p95 as for times
  out.churn_median = order.median;
  out.churn_p95 = order.p95;
  out.churn_max = order.max;
  out.updates_with_churn = static_cast<int>(std::count_if(out.churn.begin(), out.churn.end(), [](double v) { return v > 0.0; }));
  out.rooms_changed = out.room_changes = 0;
  for (const auto& [id, room] : out.rooms) {
    const int changes = room.id_changes + room.cell_changes;
    out.room_changes += changes;
    out.rooms_changed += changes > 0 ? 1 : 0;
  }
  return out;
}

}  // namespace topocut
