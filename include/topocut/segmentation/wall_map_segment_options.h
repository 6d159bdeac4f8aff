#pragma once
// The segmenter options for occupancy grids built from laser rays and walls (the walls module's
// grids, pipeline C): a preset here, beside segment(), so that the walls module only builds grids
// and whoever segments them (the CLI, the bindings, a log replay) picks the same options.
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

// Single rays through doors leave one-cell-wide free spurs, so the free space is opened with a
// 0.15 m square to keep them out of the rooms.
SegmentOptions wall_map_segment_options();

// The incremental options for such a grid built scan by scan from a real log (walls --incremental):
// segment's stages as given (the cleaning too, so that the map at rest gets segment()'s rooms),
// splits and merges held back, only touched rooms decomposed, large ones near the change, since a
// real scan's decompositions differ from scan to scan (benchmarks/README.md, log replay).
IncrementalOptions wall_map_incremental_options(const SegmentOptions& segment = wall_map_segment_options());

}  // namespace topocut
