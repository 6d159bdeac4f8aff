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
  // Measured on the four CARMEN logs (benchmarks/README.md, log replay): holding merges back like
  // splits and decomposing only the touched rooms lower both the churn p95 and the update p95.
  options.split_after = 3;
  options.merge_after = 3;
  options.neighbours_across_doors = false;
  options.neighbours_across_cuts = false;
  // Rooms over 50 m² (corridors, halls) are decomposed only within 3 m of the change: lower churn
  // p95 and fewer ids on all four logs, final rooms as close to batch or closer, lower update p95 on
  // intel and fhw (benchmarks/README.md, partial decomposition).
  options.partial_area = 50.0;
  options.partial_margin = 3.0;
  return options;
}

}  // namespace topocut
