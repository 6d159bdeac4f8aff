#include "topocut/walls/walls_pipeline.h"

#include <cmath>

#include "topocut/core/error.h"

namespace topocut {

void validate(const WallsOptions& options) {
  validate(options.extraction);
  validate(options.merge);
  validate(options.map);
}

WallsResult walls_from_scans(std::span<const PosedScan> scans, const WallsOptions& options) {
  if (scans.empty()) throw Error("there are no laser scans to build walls from");
  WallsResult result;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const auto found = extract_wall_segments(scans[i].scan, scans[i].pose, options.extraction, static_cast<int>(i));
    result.segments.insert(result.segments.end(), found.begin(), found.end());
  }
  result.walls = merge_wall_segments(result.segments, options.merge);
  result.grid = build_wall_map(scans, result.walls, options.map);
  return result;
}

}  // namespace topocut
