#include "topocut/segmentation/segment_times.h"

#include <numeric>

namespace topocut {

std::string stage_name(SegmentStage stage) {
  switch (stage) {
    case SegmentStage::kFrontEnd: return "front end";
    case SegmentStage::kCuts: return "cuts";
    case SegmentStage::kDecomposition: return "decomposition";
    case SegmentStage::kMerging: return "merging";
    case SegmentStage::kOpenRooms: return "open rooms";
    case SegmentStage::kLabelling: return "labelling";
    case SegmentStage::kOutputs: return "outputs";
  }
  return "?";
}

double SegmentTimes::total() const { return std::accumulate(ms.begin(), ms.end(), 0.0); }

StageTimer::StageTimer(SegmentTimes* times, SegmentStage stage) : times_(times), stage_(stage) {
  if (times_) start_ = times_->clock();
}

StageTimer::~StageTimer() {
  if (times_) (*times_)[stage_] += times_->clock() - start_;
}

void StageTimer::next(SegmentStage stage) {
  if (!times_) {
    stage_ = stage;
    return;
  }
  const double now = times_->clock();
  (*times_)[stage_] += now - start_;
  stage_ = stage;
  start_ = now;
}

}  // namespace topocut
