#pragma once
// Room ids carried from one segmentation of a growing map to the next by overlap: each old id goes
// to the new room sharing the most cells with it (largest overlaps first, one id per room); a new
// room that carries none may take back the id of a room that disappeared earlier where it lies, or
// that disappeared mostly inside it (revived_ids()); every other new room gets an id never used
// before. What the incremental segmenter does when it segments the whole map, and the reference a
// live map's churn is measured against (batch's own churn).
#include <algorithm>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/segmentation.h"

namespace topocut {

// The carried id of each label of next (index = label value, entry 0 unused), given previous labels in
// next's frame (both CV_32SC1, the same size, 0 = no room; previous ids below next_id). Labels of next
// sharing no cell with an old room, or losing every old id to a larger overlap, get next_id, next_id + 1,
// ... in label order (for segment()'s labels: raster order of their first cells), and next_id moves past
// them. Ties go to the lower new label, then the lower old id.
// With retired (CV_32SC1 in next's frame: where each room that disappeared last lay, 0 elsewhere),
// labels carrying no old id first try revived_ids() with every id not carried here (retired_cells:
// as there).
std::vector<int> carried_ids(const cv::Mat& previous, const cv::Mat& next, int labels, int& next_id,
                             const cv::Mat& retired = cv::Mat(), const std::vector<long long>* retired_cells = nullptr);

// Gives labels without an id (ids[l] == 0, l = 1..ids.size() - 1) the id of a room that disappeared
// (retired, CV_32SC1, the same size as next: the id where that room last lay) when more than half
// their cells lie where it was, or (retired_cells given: by id, the cells retired holds of it in
// the whole map, which may reach beyond next's window) when they cover more than half of where it
// was: the room came back (a merge undone, a cut found again, or found again grown by newly seen
// space), and takes its id back rather than a new one. Largest overlaps first, each id at most once
// and only if available(id). Only next's cells where mask is non-zero count (mask may be empty: all).
template <class Available>
void revived_ids(const cv::Mat& retired, const cv::Mat& next, const cv::Mat& mask, std::vector<int>& ids,
                 const Available& available, const std::vector<long long>* retired_cells = nullptr);

namespace detail {
struct IdOverlap {
  long long cells;
  int label;  // of the new labels
  int old;    // an earlier id
};
// The cells each (label, old id) pair shares, largest first (ties: lower label, then lower id),
// and the cells of each label (index = label, size labels + 1), over mask's non-zero cells (empty: all).
std::vector<IdOverlap> id_overlaps(const cv::Mat& old, const cv::Mat& next, const cv::Mat& mask, int labels,
                                   std::vector<long long>* sizes = nullptr);
}  // namespace detail

template <class Available>
void revived_ids(const cv::Mat& retired, const cv::Mat& next, const cv::Mat& mask, std::vector<int>& ids,
                 const Available& available, const std::vector<long long>* retired_cells) {
  // Nothing to name (every label has its id): the overlaps, a pass over next, would be read for nothing.
  if (retired.empty() || ids.size() < 2 || std::find(ids.begin() + 1, ids.end(), 0) == ids.end()) return;
  const int labels = static_cast<int>(ids.size()) - 1;
  std::vector<long long> sizes;
  std::vector<int> used;
  // Whether o's cells are more than half of where the retired room lay (in the whole map).
  auto covers_it = [&](const detail::IdOverlap& o) {
    const std::size_t id = static_cast<std::size_t>(o.old);
    return retired_cells != nullptr && id < retired_cells->size() && 2 * o.cells > (*retired_cells)[id];
  };
  for (const detail::IdOverlap& o : detail::id_overlaps(retired, next, mask, labels, &sizes)) {
    const std::size_t l = static_cast<std::size_t>(o.label);
    if (ids[l] != 0 || (2 * o.cells <= sizes[l] && !covers_it(o)) || !available(o.old)) continue;
    if (std::find(used.begin(), used.end(), o.old) != used.end()) continue;
    ids[l] = o.old;
    used.push_back(o.old);
  }
}

// s with every label value l renamed ids[l]: labels, rooms (sorted by id again) and passages (rooms
// ordered within each, sorted by rooms then cut as segment() sorts them).
Segmentation renamed(Segmentation s, const std::vector<int>& ids);

// The shift in cells (columns right, rows down) that places a grid of rows_from rows with origin from
// into one of rows_to rows with origin to, at the same resolution (metres per cell); false unless it is a
// whole number of cells (within a thousandth of a cell: ROS carries resolutions as float32).
bool frame_shift(const Point2& from, int rows_from, const Point2& to, int rows_to, double resolution, cv::Point& shift);

// A sequence of segmentations of one growing map (frames may grow and move by whole cells, as ROS maps
// do) with ids carried from each to the next: batch's own ids, for comparing an incremental run's
// stability with what batch decides update by update.
class IdCarrier {
 public:
  // next with its ids carried over from the previous call's result (fresh ids 1..N on the first call,
  // or after a change of resolution or a shift by a fraction of a cell).
  Segmentation carry(const Segmentation& next);

 private:
  cv::Mat previous_;
  Point2 origin_;
  double resolution_ = 0.0;
  int next_id_ = 1;
};

}  // namespace topocut
