#include "topocut/segmentation/wall_map_segment_options.h"

namespace topocut {

SegmentOptions wall_map_segment_options() {
  SegmentOptions options;
  options.binarize.opening_size = 0.15;
  return options;
}

IncrementalOptions wall_map_incremental_options(const SegmentOptions& segment) {
  IncrementalOptions options;
  options.segment = segment;
  options.segment.clean = false;
  options.split_after = 3;
  return options;
}

}  // namespace topocut
