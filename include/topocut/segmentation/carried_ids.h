#pragma once
// Room ids carried from one segmentation of a growing map to the next by overlap: each old id goes
// to the new room sharing the most cells with it (largest overlaps first, one id per room), every
// other new room gets an id never used before. What the incremental segmenter does when it segments
// the whole map, and the reference a live map's churn is measured against (batch's own churn).
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/segmentation.h"

namespace topocut {

// The carried id of each label of next (index = label value, entry 0 unused), given previous labels in
// next's frame (both CV_32SC1, the same size, 0 = no room; previous ids below next_id). Labels of next
// sharing no cell with an old room, or losing every old id to a larger overlap, get next_id, next_id + 1,
// ... in label order (for segment()'s labels: raster order of their first cells), and next_id moves past
// them. Ties go to the lower new label, then the lower old id.
std::vector<int> carried_ids(const cv::Mat& previous, const cv::Mat& next, int labels, int& next_id);

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
