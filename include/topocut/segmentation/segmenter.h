#pragma once
// Batch room segmentation (pipeline A): grid → free space → polygons → decomposition → rooms.
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"

namespace topocut {

struct SegmentOptions {
  double concavity = 2.5;  // tau, maximum concavity in metres (Fermin-Leon et al.: 2.5 m for all maps)
  bool decompose = true;   // false: the trivial baseline, each free-space component is one room
  // (map and decomposition options are added here by the foundation work)
};

// Segments the free space of grid into rooms; every free cell gets a room label.
Segmentation segment(const OccupancyGrid& grid, const SegmentOptions& options = {});

}  // namespace topocut
