#pragma once
// How stable the rooms of a growing map are, update by update: a robot user wants a room to keep
// its id and its borders while the map grows around it. Fed with every label image an incremental
// run produces (growing or moving frames included), it measures
//  - churn per update: of the cells labelled before and still labelled (still free), the share
//    whose room id changed;
//  - per room: in how many updates its id changed (its surviving cells went to other ids) or more
//    than a tenth of its cells changed room;
//  - the distinct ids ever used against the final room count.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"

namespace topocut {

struct StabilityOptions {
  // A room "changed" in an update when more than this share of its surviving cells changed room.
  double cell_change_fraction = 0.1;
};

// One room's history (by id).
struct RoomHistory {
  int updates = 0;       // updates it was present before and after (so could have changed)
  int id_changes = 0;    // updates in which none of its surviving cells kept its id
  int cell_changes = 0;  // updates in which it kept its id but more than the fraction of cells changed room
};

struct StabilityReport {
  std::vector<double> churn;              // one value per update after the first, in [0, 1]
  double churn_median = 0.0, churn_p95 = 0.0, churn_max = 0.0;  // nearest-rank p95, 0 when empty
  int updates_with_churn = 0;             // updates with churn > 0
  std::map<int, RoomHistory> rooms;       // every id ever seen
  int rooms_changed = 0;                  // rooms with at least one id or cell change
  int room_changes = 0;                   // id and cell changes summed over rooms
  int distinct_ids = 0;                   // ids ever used
  int final_rooms = 0;                    // rooms (non-zero ids) in the last label image
};

// Accumulates the figures over a sequence of label images (CV_32SC1, 0 = no room, as the
// segmenters produce them). Keeps a copy of the previous labels.
class StabilityTracker {
 public:
  explicit StabilityTracker(const StabilityOptions& options = {});

  // Adds the labels of the next update, whose grid has this origin (world metres of the lower-left
  // corner) and resolution; cells are matched with the previous update's through the origins, so
  // the frame may grow or move. A changed resolution matches nothing (no churn is counted for that
  // update). Throws Error on labels that are not CV_32SC1 or a non-positive resolution.
  void add(const cv::Mat& labels, const Point2& origin, double resolution);

  // The figures so far.
  StabilityReport report() const;

 private:
  StabilityOptions options_;
  cv::Mat previous_;
  Point2 previous_origin_;
  double previous_resolution_ = 0.0;
  StabilityReport report_;
  std::vector<int> ids_seen_;  // sorted
};

}  // namespace topocut
