#pragma once
// Wall segments seen by one scan: sparse labeling splits the scan's points into segments (objects
// apart from each other), a line extractor runs on each segment, and the lines go to the world
// frame through the laser pose.
#include <cstddef>
#include <limits>
#include <vector>

#include "topocut/labeling/sparse_labeling.h"
#include "topocut/lines/extract.h"
#include "topocut/scan/scan.h"
#include "topocut/walls/wall_merging.h"

namespace topocut {

struct WallExtractionOptions {
  // Labeling of the scan's points. Coarser than the labeling default: at 1° beam spacing the points
  // on a wall 8 m away are 14 cm apart and must still form one segment.
  LabelingOptions labeling = [] {
    LabelingOptions o;
    o.cell_size = 0.10;
    o.dilation = 1;
    return o;
  }();
  // Line extraction on every segment (its min_points replaced by ours); IEPF: the best wall precision
  // and coverage together on the logs (benchmarks/README.md, "Walls from laser logs").
  LineExtractionOptions lines = [] {
    LineExtractionOptions o;
    o.method = LineMethod::kIepf;
    return o;
  }();
  // Lines with fewer supporting beams are dropped; 3, the fewest that make more than a chord, keeps
  // small furniture and far, sparse walls (benchmarks/README.md, "Walls from laser logs").
  std::size_t min_points = 3;
  // A line is cut where consecutive support points (along the line) are farther apart than this:
  // a wall is only claimed where it was seen. Some extractors (SMF) join collinear pieces across a
  // door; below a door's width, so doors stay open.
  double max_gap = 0.5;  // metres
  // Beams farther than this are left out of the walls (their bearing error grows with range).
  double max_range = std::numeric_limits<double>::infinity();
};

// Throws Error naming the first option outside its range.
void validate(const WallExtractionOptions& options);

// The world-frame wall segments of one scan taken from `pose`, in the order of their first beam,
// each tagged with scan_index. Throws Error on an inconsistent scan or invalid options.
std::vector<WallSegment> extract_wall_segments(const Scan& scan, const Pose2& pose,
                                               const WallExtractionOptions& options = {}, int scan_index = 0);

}  // namespace topocut
