#pragma once
// Segmentation results as a caller of the array API wants them (GridArray, ROS, Python): labels in
// the caller's row order, geometry in the map frame (the origin's yaw applied), and for every room a
// point inside it and its bounding box, so that a label can be drawn and a room looked up.
#include <cstdint>
#include <vector>

#include "topocut/core/grid_array.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

struct GridSegmentation {
  // labels in frame.row_order; room polygons and centroids, passage cuts in the map frame.
  // A passage's door flag tells a door (a narrow gap in a wall) from a wider opening.
  Segmentation segmentation;
  std::vector<RoomPlacement> placements;  // one per segmentation.rooms entry, same order
  GridFrame frame;
};

// Turns a segmentation of a top-down grid with yaw 0 (what segment() and IncrementalSegmenter give)
// into frame: labels flipped for kBottomUp, geometry rotated by frame.yaw about the origin.
GridSegmentation in_frame(Segmentation segmentation, const GridFrame& frame);

// segment() followed by in_frame(). Throws Error like segment().
GridSegmentation segment_grid(const OccupancyGrid& grid, const GridFrame& frame, const SegmentOptions& options = {},
                              SegmentationInput* input = nullptr);

// segmenter.update(grid) followed by in_frame() (ids stay those of the segmenter).
GridSegmentation update_grid(IncrementalSegmenter& segmenter, const OccupancyGrid& grid, const GridFrame& frame);

// in_frame() of an incremental segmenter's results, result after result, with the work of the
// placements following the change: a room whose cells the update left as they were
// (IncrementalUpdateReport::relabelled_rooms) keeps its deepest cell from the previous result,
// moved with the frame; the others are measured again. The placements are in_frame()'s bit for bit.
// For a live map (the ROS node, Python's IncrementalSegmenter).
class FramedUpdates {
 public:
  // in_frame(segmenter.result(), frame), keeping cells only when the previous call placed the
  // result right before this one (segmenter.results() one less) of the same segmenter.
  GridSegmentation place(const IncrementalSegmenter& segmenter, const GridFrame& frame);
  // Rooms whose deepest cell the last call kept rather than measured (for tests and benchmarks).
  int reused_rooms() const { return reused_; }

 private:
  struct Kept {
    int id = 0;
    cv::Point cell;  // its deepest cell, top-down ((-1, -1): none)
  };
  const Kept* kept_cell(int id) const;  // the room's entry in cells_, or null

  const IncrementalSegmenter* segmenter_ = nullptr;  // of the kept cells
  std::uint64_t result_ = 0;                        // its results() then
  std::vector<Kept> cells_;  // of that result's rooms, by id
  std::vector<int> edge_;    // the rooms with a cell on its labels' edge, sorted
  cv::Size size_;            // its labels' size
  int reused_ = 0;
};

}  // namespace topocut
