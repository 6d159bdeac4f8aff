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
  // Held back three decompositions, only touched rooms decomposed: calmer and faster on the logs
  // (benchmarks/README.md, "Incremental on real laser logs").
  options.split_after = 3;
  options.merge_after = 3;
  options.neighbours_across_doors = false;
  options.neighbours_across_cuts = false;
  // Rooms over 50 m² (corridors, halls) decomposed only within 3 m of the change, which is at one end
  // (benchmarks/HISTORY.md, partial decomposition).
  options.partial_area = 50.0;
  options.partial_margin = 3.0;
  return options;
}

}  // namespace topocut
