#pragma once
// Scans with the pose of the laser that took them: the input of pipeline C.
#include <vector>

#include "topocut/io/carmen_log.h"
#include "topocut/scan/scan.h"

namespace topocut {

struct PosedScan {
  Scan scan;  // sensor frame; +inf ranges are "no return", NaN or <= 0 invalid
  Pose2 pose;  // laser pose in the world
};

// The FLASER scans of a CARMEN log with their corrected poses. Beam i lies at
// start_angle + i * angle_step; readings at or beyond the log's max_range become +inf ("no
// return"), and range_max is set to max_range so they never count as hits.
std::vector<PosedScan> posed_scans(const CarmenLog& log);

}  // namespace topocut
