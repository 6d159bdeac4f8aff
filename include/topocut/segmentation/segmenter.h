#pragma once
// Batch room segmentation (pipeline A): grid → free space → polygons → decomposition → rooms.
// The stages are separate functions so that the incremental segmenter can run them on the parts
// of a map that changed and reuse the rest.
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/map/binarize.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut {

struct SegmentOptions {
  double concavity = 2.5;  // tau, maximum concavity in metres (Fermin-Leon et al.: 2.5 m for all maps)
  bool decompose = true;   // false: the trivial baseline, each free-space component is one room
  BinarizeOptions binarize;  // defaults: raw free space (no inflation, no filtering)
  ContourOptions contours;   // minimum component and hole areas (m²)
  // Passed to decompose(); its tau is replaced by concavity / resolution (the polygons are in cells).
  DecompositionOptions decomposition;
};

// Segments the free space of grid into rooms; every free cell gets a room label. Rooms are
// numbered by their first cell in raster order. Throws Error on an invalid grid or options, or a
// map without free space.
Segmentation segment(const OccupancyGrid& grid, const SegmentOptions& options = {});

// Stage 1: the free-space mask segment() decomposes (options.binarize applied); throws Error if
// it is empty.
cv::Mat segmentation_free_space(const OccupancyGrid& grid, const SegmentOptions& options);

// Stage 3: the pieces of one free-space component (grid coordinates) and the cuts between them:
// decompose() at tau = options.concavity / resolution, or the component itself when
// options.decompose is false. Errors name the component's first cell.
PieceSet decompose_component(const FreeSpaceComponent& component, double resolution, const SegmentOptions& options);

// Throws Error unless the options are usable (finite, positive concavity and so on).
void validate(const SegmentOptions& options);

}  // namespace topocut
