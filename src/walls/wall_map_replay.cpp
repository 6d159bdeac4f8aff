#include "topocut/walls/wall_map_replay.h"

#include "topocut/core/error.h"
#include "topocut/walls/wall_extraction.h"

namespace topocut {

namespace {

std::span<const PosedScan> not_empty(std::span<const PosedScan> scans) {
  if (scans.empty()) throw Error("there are no laser scans to replay");
  return scans;
}

// Every scan's wall segments, extracted before the replay: the grid's frame must cover them all.
std::vector<std::vector<WallSegment>> segments_per_scan(std::span<const PosedScan> scans, const WallsOptions& options) {
  std::vector<std::vector<WallSegment>> out;
  out.reserve(scans.size());
  for (std::size_t i = 0; i < scans.size(); ++i)
    out.push_back(extract_wall_segments(scans[i].scan, scans[i].pose, options.extraction, static_cast<int>(i)));
  return out;
}

std::vector<WallSegment> concatenated(const std::vector<std::vector<WallSegment>>& segments) {
  std::vector<WallSegment> all;
  for (const auto& s : segments) all.insert(all.end(), s.begin(), s.end());
  return all;
}

}  // namespace

WallMapReplay::WallMapReplay(std::span<const PosedScan> scans, const WallsOptions& options,
                             const std::optional<OccupancyEvidenceOptions>& evidence)
    : scans_(not_empty(scans)),
      segments_(segments_per_scan(scans_, options)),
      map_(scans_, concatenated(segments_), options.map, evidence) {}

bool WallMapReplay::next() {
  if (next_ >= scans_.size()) return false;
  last_ = next_++;
  changed_ = map_.add(scans_[last_], segments_[last_]);
  return true;
}

}  // namespace topocut
