#pragma once
// Pictures of an exploration in progress, for people: the known map (unknown grey, obstacles dark),
// rooms tinted in their stable colours with their ids, the robot's path, the robot and its laser
// range. A sequence of them shows the segmentation growing scan by scan.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/scan/scan.h"

namespace topocut {

struct FrameOptions {
  int scale = 0;               // pixels per cell; 0: as render_overlay chooses (long side >= 800 px)
  bool draw_ids = true;
  bool draw_passages = false;  // the room graph clutters a growing map
  double range = 5.0;          // laser range drawn around the robot (metres); 0: none
  std::string caption;         // written in the top-left corner, e.g. "update 12"
};

// Renders one frame (CV_8UC3, BGR). path holds world positions in order; robot is the current pose.
// Throws Error if the segmentation does not fit the grid.
cv::Mat render_exploration_frame(const OccupancyGrid& grid, const Segmentation& segmentation,
                                 const std::vector<Point2>& path, const Pose2& robot, const FrameOptions& options = {});

}  // namespace topocut
