#pragma once
// Pipeline C end to end: posed scans → per-scan wall segments → merged walls → occupancy grid.
// Segmenting the grid into rooms is the caller's step (wall_map_segment_options() in segmentation).
#include <span>
#include <string>
#include <vector>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"
#include "topocut/walls/posed_scan.h"
#include "topocut/walls/wall_extraction.h"
#include "topocut/walls/wall_map.h"
#include "topocut/walls/wall_merging.h"

namespace topocut {

struct WallsOptions {
  WallExtractionOptions extraction;
  WallMergeOptions merge;
  WallMapOptions map;
};

struct WallsResult {
  std::vector<WallSegment> segments;  // every scan's wall segments, in scan order
  std::vector<Wall> walls;            // merged (Wall::members index segments)
  OccupancyGrid grid;                 // walls occupied, seen space free, the rest unknown
};

// Throws Error naming the first option of any stage outside its range, so that a command can
// refuse bad options before it reads a log.
void validate(const WallsOptions& options);

// The options as people give them (the walls command): resolution, thickness and the labeling's rows
// (labeling_option_rows()); the line extractor is a name (parse_line_method()).
const std::vector<OptionRow<WallsOptions>>& walls_option_rows();

// Runs the pipeline on the scans. Throws Error if there are no scans or on invalid options.
WallsResult walls_from_scans(std::span<const PosedScan> scans, const WallsOptions& options = {});

}  // namespace topocut
