#include "topocut/segmentation/merge_trace.h"

#include "topocut/core/error.h"
#include "topocut/segmentation/room_merging.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace topocut {

MergeTrace trace_merges(const OccupancyGrid& grid, const SegmentOptions& options) {
  validate(options);
  if (!options.merge.enabled || !options.merge.learned) throw Error("tracing merges needs the learned merge criterion");
  const SegmentationInput input = segmentation_input(grid, options);
  const FreeSpacePolygons polygons = free_space_polygons(input.floor, grid.resolution, options.contours);
  MergeTrace trace;
  for (const FreeSpaceComponent& component : polygons.components) {
    const PieceSet pieces = decompose_pieces(component, grid.resolution, options);
    const int offset = static_cast<int>(trace.pieces.size());
    trace.pieces.insert(trace.pieces.end(), pieces.pieces.begin(), pieces.pieces.end());
    std::vector<MergeStep> steps;
    merge_rooms(component, pieces, input.labelled.cells, grid.resolution, options, segmentation_rules(), &steps);
    for (MergeStep& step : steps) {
      for (int& piece : step.side_a) piece += offset;
      for (int& piece : step.side_b) piece += offset;
      trace.steps.push_back(std::move(step));
    }
  }
  return trace;
}

}  // namespace topocut
