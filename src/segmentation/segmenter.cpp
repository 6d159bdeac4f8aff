#include "topocut/segmentation/segmenter.h"

#include <cmath>
#include <string>

#include "topocut/core/error.h"

namespace topocut {

void validate(const SegmentOptions& options) {
  if (!std::isfinite(options.concavity) || options.concavity <= 0.0)
    throw Error("the concavity must be a positive number of metres");
  if (options.decomposition.max_rounds < 1) throw Error("the decomposition needs at least one round");
}

cv::Mat segmentation_free_space(const OccupancyGrid& grid, const SegmentOptions& options) {
  validate(grid);
  if (cv::countNonZero(grid.cells == kFree) == 0) throw Error("the map has no free space (no cell is free)");
  cv::Mat free = free_space_mask(grid, options.binarize);
  if (cv::countNonZero(free) == 0)
    throw Error("no free space is left after inflating obstacles by the robot radius and filtering");
  return free;
}

PieceSet decompose_component(const FreeSpaceComponent& component, double resolution, const SegmentOptions& options) {
  PieceSet set;
  if (!options.decompose) {
    set.pieces.push_back(component.polygon);
    return set;
  }
  DecompositionOptions decomposition = options.decomposition;
  decomposition.tau = options.concavity / resolution;
  try {
    const Decomposition result = decompose(component.polygon, decomposition);
    set.pieces = result.pieces;
    set.cuts.reserve(result.cuts.size());
    for (const Cut& cut : result.cuts) set.cuts.push_back(cut.segment);
  } catch (const Error& e) {
    throw Error("decomposing the free-space component at cell (" + std::to_string(component.first_pixel.x) + ", " +
                std::to_string(component.first_pixel.y) + ") failed: " + e.what());
  }
  return set;
}

Segmentation segment(const OccupancyGrid& grid, const SegmentOptions& options) {
  validate(options);
  const cv::Mat free = segmentation_free_space(grid, options);
  const FreeSpacePolygons polygons = free_space_polygons(free, grid.resolution, options.contours);
  PieceSet pieces;
  for (const FreeSpaceComponent& component : polygons.components)
    pieces.append(decompose_component(component, grid.resolution, options));
  return rooms_from_pieces(grid, pieces);
}

}  // namespace topocut
