#include "topocut/segmentation/wall_map_segment_options.h"

namespace topocut {

SegmentOptions wall_map_segment_options() {
  SegmentOptions options;
  options.binarize.opening_size = 0.15;
  return options;
}

}  // namespace topocut
