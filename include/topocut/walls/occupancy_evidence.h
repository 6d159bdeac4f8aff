#pragma once
// Occupancy evidence per cell, as a SLAM map keeps it: every scan adds a hit (the cell lies under one
// of its wall segments) or a miss (a ray crossed it) to the cell's log-odds, clamped so that old
// evidence can still be overturned, and the cell's published state (free, occupied, unknown) flips
// only when the evidence crosses a threshold on the far side of the current state (hysteresis). A
// cell seen sometimes as wall and sometimes as free, by noise of a few centimetres, settles on one
// state instead of flipping with every scan; a person or a chair seen a few times fades.
#include <opencv2/core.hpp>

namespace topocut {

// Probabilities, turned into log-odds inside. The sensor model and the clamping are OctoMap's
// defaults (Hornung et al. 2013: hit 0.7, miss 0.4, clamping 0.12 .. 0.97); the two thresholds
// around 0.5 give the hysteresis: a free cell seen well (clamped at 0.12) becomes occupied after
// four hits in a row, a wall seen well (0.97) becomes free after ten misses in a row, and a cell's
// first observation publishes it at once (0.7 >= 0.65, 0.4 <= 0.45).
struct OccupancyEvidenceOptions {
  double hit_probability = 0.7;
  double miss_probability = 0.4;
  double clamp_min = 0.12;
  double clamp_max = 0.97;
  double occupied_at = 0.65;  // a cell not published occupied becomes so when its probability reaches this
  double free_at = 0.45;      // a cell not published free becomes so when its probability falls to this
  // Metres a ray stops short of its hit, on top of the one cell every ray does: a wall measured a
  // few centimetres farther by this scan would otherwise count misses in another scan's wall.
  double miss_margin = 0.15;
};

// Throws Error naming the first option outside its range (probabilities in (0, 1), a hit above 0.5
// and a miss below it, clamp_min < free_at < occupied_at < clamp_max, a non-negative margin).
void validate(const OccupancyEvidenceOptions& options);

class OccupancyEvidence {
 public:
  // Every cell without evidence (probability 0.5, published unknown). Throws Error on invalid options.
  explicit OccupancyEvidence(cv::Size size, const OccupancyEvidenceOptions& options = {});

  // Adds one scan inside box: cells set in hits (CV_8UC1, the grid's size) get a hit, the other
  // cells set in misses a miss. Writes into published (CV_8UC1, kFree / kOccupied / kUnknown, the
  // grid's size) only the cells whose state flips; returns the bounding box of those (empty if none).
  cv::Rect add(const cv::Rect& box, const cv::Mat& hits, const cv::Mat& misses, cv::Mat& published);

 private:
  cv::Mat log_odds_;  // CV_32FC1
  float hit_, miss_, min_, max_, occupied_, free_;
};

}  // namespace topocut
