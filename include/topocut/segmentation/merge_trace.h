#pragma once
// How the pieces of a map merged into rooms, for fitting the merge model to people's rooms
// (scripts/train_merge_model.py) and for looking at what merging weighed.
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/segmentation/merge_features.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

struct MergeTrace {
  std::vector<PolygonWithHoles> pieces;  // every component's pieces, grid coordinates of the whole grid
  std::vector<MergeStep> steps;          // every candidate merge weighed; sides index into pieces
};

// Runs segment()'s stages on grid up to the rooms' polygons and records every candidate merge that
// the learned criterion weighs (options.merge.learned must be on; its model decides, so a model with
// a threshold above 1 records the first candidates only). Throws Error as segment() does.
MergeTrace trace_merges(const OccupancyGrid& grid, const SegmentOptions& options);

}  // namespace topocut
