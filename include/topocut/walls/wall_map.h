#pragma once
// From walls and the rays of the scans to an occupancy grid that pipeline A segments: cells crossed
// by a laser ray are free, cells under a wall polygon are occupied (walls win), the rest unknown.
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"
#include "topocut/walls/occupancy_evidence.h"
#include "topocut/walls/posed_scan.h"
#include "topocut/walls/wall_merging.h"

namespace topocut {

struct WallMapOptions {
  double resolution = 0.05;      // metres per cell
  double wall_thickness = 0.10;  // metres: walls become rectangles this thick around their line
  // Beams without a return (+inf range) prove free space too, but glass and dark surfaces also give
  // no return: they are traced only this far (0: not at all).
  double no_return_free_range = 3.0;  // metres
  // Hits farther than this are traced as free only up to this distance (their bearing error grows).
  double max_free_range = 30.0;  // metres
  double margin = 1.0;           // metres of unknown around everything seen
  std::size_t max_cells = 100'000'000;  // larger grids are refused (absurd poses or ranges)
};

// The wall as a counter-clockwise rectangle of the given thickness around its segment (a square of
// side `thickness` for a zero-length segment).
Ring wall_polygon(const Segment2& wall, double thickness);

// The grid covering the scans' poses and traced rays and the walls (plus the margin): every cell a
// ray passes before its hit is free, every cell under a wall polygon occupied (a wall's centre line
// is also drawn 4-connected so no free path crosses it diagonally), the rest unknown. Throws Error
// on invalid options or when the grid would exceed max_cells.
// Throws Error naming the first option outside its range.
void validate(const WallMapOptions& options);

// The fields of WallMapOptions as options (the walls command's grid): name, unit, range, help
// (option_table.h); max_cells is a limit, not an option.
const std::vector<OptionRow<WallMapOptions>>& wall_map_option_rows();

OccupancyGrid build_wall_map(std::span<const PosedScan> scans, std::span<const Wall> walls,
                             const WallMapOptions& options = {});

// The same grid built scan by scan, as a robot replaying its log would see it. Without evidence
// options: after adding scans 0..k with their wall segments, grid() equals build_wall_map() of those
// scans with each segment taken as a wall (merging needs the walls of the future, so none happens),
// in the fixed frame that covers every scan and segment given to the constructor. With them, each
// scan is occupancy evidence instead (OccupancyEvidence: its wall cells hits, the cells its rays
// cross misses) and grid() shows each cell's settled state, as a SLAM map does.
class IncrementalWallMap {
 public:
  // The frame of all scans and segments, every cell unknown. Throws Error like build_wall_map() and
  // on invalid evidence options.
  IncrementalWallMap(std::span<const PosedScan> scans, std::span<const WallSegment> segments,
                     const WallMapOptions& options = {},
                     const std::optional<OccupancyEvidenceOptions>& evidence = std::nullopt);

  // Adds one scan's free rays and wall segments; returns the bounding box of the cells that
  // changed (empty when none did). Parts outside the frame are clipped.
  cv::Rect add(const PosedScan& scan, std::span<const WallSegment> segments);

  const OccupancyGrid& grid() const { return grid_; }

 private:
  WallMapOptions options_;
  OccupancyGrid grid_;
  cv::Mat seen_;  // scratch: the current scan's rays, cleared after each add
  cv::Mat hits_;  // scratch (with evidence): the current scan's wall cells, cleared after each add
  std::optional<OccupancyEvidence> evidence_;
  double miss_margin_ = 0.0;
};

}  // namespace topocut
