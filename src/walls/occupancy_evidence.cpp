#include "topocut/walls/occupancy_evidence.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "topocut/core/error.h"
#include "topocut/core/occupancy_grid.h"

namespace topocut {

namespace {

float log_odds(double p) { return static_cast<float>(std::log(p / (1.0 - p))); }

void check_probability(double p, const std::string& what) {
  if (!(p > 0.0 && p < 1.0)) throw Error(what + " must be a probability strictly between 0 and 1, got " + std::to_string(p));
}

}  // namespace

void validate(const OccupancyEvidenceOptions& o) {
  check_probability(o.hit_probability, "the hit probability");
  check_probability(o.miss_probability, "the miss probability");
  check_probability(o.clamp_min, "the lower clamping probability");
  check_probability(o.clamp_max, "the upper clamping probability");
  check_probability(o.occupied_at, "the occupied threshold");
  check_probability(o.free_at, "the free threshold");
  if (!(o.hit_probability > 0.5)) throw Error("the hit probability must be above 0.5 (a hit is evidence of an obstacle)");
  if (!(o.miss_probability < 0.5)) throw Error("the miss probability must be below 0.5 (a miss is evidence of free space)");
  if (!(o.clamp_min < o.free_at && o.free_at < o.occupied_at && o.occupied_at < o.clamp_max))
    throw Error("the occupancy thresholds must satisfy clamp_min < free_at < occupied_at < clamp_max");
  if (!std::isfinite(o.miss_margin) || o.miss_margin < 0.0) throw Error("the miss margin must be a non-negative number of metres");
}

OccupancyEvidence::OccupancyEvidence(cv::Size size, const OccupancyEvidenceOptions& options) {
  validate(options);
  log_odds_ = cv::Mat::zeros(size, CV_32FC1);
  hit_ = log_odds(options.hit_probability);
  miss_ = log_odds(options.miss_probability);
  min_ = log_odds(options.clamp_min);
  max_ = log_odds(options.clamp_max);
  occupied_ = log_odds(options.occupied_at);
  free_ = log_odds(options.free_at);
}

cv::Rect OccupancyEvidence::add(const cv::Rect& box, const cv::Mat& hits, const cv::Mat& misses, cv::Mat& published) {
  const cv::Rect window = box & cv::Rect(0, 0, log_odds_.cols, log_odds_.rows);
  int top = INT_MAX, bottom = -1, left = INT_MAX, right = -1;
  for (int r = window.y; r < window.y + window.height; ++r) {
    const unsigned char* hit = hits.ptr<unsigned char>(r);
    const unsigned char* miss = misses.ptr<unsigned char>(r);
    float* l = log_odds_.ptr<float>(r);
    unsigned char* state = published.ptr<unsigned char>(r);
    for (int c = window.x; c < window.x + window.width; ++c) {
      if (!hit[c] && !miss[c]) continue;
      l[c] = std::clamp(l[c] + (hit[c] ? hit_ : miss_), min_, max_);
      // Hysteresis: only evidence past the threshold on the far side of the current state flips it.
      unsigned char next = state[c];
      if (state[c] != kOccupied && l[c] >= occupied_) next = kOccupied;
      else if (state[c] != kFree && l[c] <= free_) next = kFree;
      if (next == state[c]) continue;
      state[c] = next;
      top = std::min(top, r);
      bottom = r;
      left = std::min(left, c);
      right = std::max(right, c);
    }
  }
  if (bottom < 0) return {};
  return {left, top, right - left + 1, bottom - top + 1};
}

}  // namespace topocut
