#pragma once
// A laser log's occupancy grid built scan by scan, as the robot saw it (IncrementalWallMap: each
// scan's rays free and its wall segments occupied, or, when asked, both as occupancy evidence that
// settles as in a SLAM map; segments not merged since merging needs later scans), in the one frame
// that covers the whole log. Each scan's grid is what an incremental segmenter is fed
// when a log is replayed.
#include <optional>
#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/walls/posed_scan.h"
#include "topocut/walls/wall_map.h"
#include "topocut/walls/walls_pipeline.h"

namespace topocut {

class WallMapReplay {
 public:
  // Extracts every scan's wall segments first (the frame must cover them all); keeps a view of
  // scans, which must outlive this object. evidence: std::nullopt draws every scan as it is (rays
  // free, walls occupied for good); given, cells settle by occupancy evidence (IncrementalWallMap).
  // Throws Error if there are no scans, on invalid options or a frame larger than options.map allows.
  WallMapReplay(std::span<const PosedScan> scans, const WallsOptions& options = {},
                const std::optional<OccupancyEvidenceOptions>& evidence = std::nullopt);

  // Adds the next scan's rays and wall segments; returns false, changing nothing, after the last.
  bool next();

  // The grid after the scans added so far (named like Explorer's, so that exploration's
  // steps_of() replays either).
  const OccupancyGrid& known_map() const { return map_.grid(); }
  // Cells the last scan changed, in known_map()'s frame (empty when none did).
  cv::Rect changed() const { return changed_; }
  // The pose of the last scan added (of the first scan before next() is called).
  const Pose2& pose() const { return scans_[last_].pose; }
  int scans_added() const { return static_cast<int>(next_); }

 private:
  std::span<const PosedScan> scans_;
  std::vector<std::vector<WallSegment>> segments_;  // per scan
  IncrementalWallMap map_;
  cv::Rect changed_;
  std::size_t next_ = 0;
  std::size_t last_ = 0;
};

}  // namespace topocut
