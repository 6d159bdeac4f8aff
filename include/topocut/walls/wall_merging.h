#pragma once
// Merging wall segments seen by many scans into walls: segments that are collinear (within angle
// and distance tolerances) and overlap or nearly touch along their line become one wall, whose line
// is the total-least-squares fit of all its segments (each taken as a uniform mass along its
// length) and whose extent covers theirs.
#include <cstddef>
#include <span>
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut {

// A wall piece seen in one scan, in the world frame.
struct WallSegment {
  Segment2 segment;        // metres
  int scan = 0;            // index of the scan that saw it
  std::size_t points = 0;  // laser points supporting it
};

struct Wall {
  Segment2 segment;        // metres: the fitted line between the extreme projections of its segments
  double weight = 0.0;     // total length of the merged segments (metres)
  int observations = 0;    // number of segments merged
  std::vector<int> members;  // indices of the merged segments, ascending
};

struct WallMergeOptions {
  double angle_tolerance = 0.0873;     // radians (5°) between a segment and a wall's direction
  double distance_tolerance = 0.10;    // metres: both end points must lie this close to the wall's line
  double gap_tolerance = 0.30;         // metres between the extents along the line (below a door's width)
  // Segments shorter than this have no reliable direction: only their end points' distances count.
  double short_length = 0.30;          // metres
  int max_rounds = 4;                  // wall-with-wall merge rounds after the first pass
  double index_cell = 1.0;             // metres, cell of the spatial hash of walls
};

// Merges the segments into walls, greedily and deterministically: longest first (ties by input order),
// each into the closest compatible wall or a new one, then walls with walls until nothing changes.
// Degenerate segments are skipped; walls in order of their first member. Throws Error on bad options.
// Throws Error naming the first option outside its range.
void validate(const WallMergeOptions& options);

std::vector<Wall> merge_wall_segments(std::span<const WallSegment> segments, const WallMergeOptions& options = {});

}  // namespace topocut
