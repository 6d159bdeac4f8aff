#pragma once
// The world a simulated robot is put in to map a plan (simulated_map.h): the plan framed around its
// building, the exterior turned into open ground with obstacles, windows cut into the outer wall,
// walls thinned or thickened, some doors closed, furniture and clutter placed in people's rooms.
#include <cstdint>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/exploration/simulated_map.h"

namespace topocut {

struct SimulatedWorld {
  OccupancyGrid world;  // kFree where the laser passes (floor, glass, open ground), kOccupied elsewhere
  cv::Mat drivable;     // CV_8UC1, 255 on floor at least robot_radius from anything else
  cv::Mat exterior;     // CV_8UC1, 255 on the exterior (open ground and its obstacles, or solid)
  cv::Mat glass;        // CV_8UC1, 255 on windows: the laser passes, the robot does not
  cv::Mat rooms;        // CV_32SC1, people's rooms in the world's frame
  cv::Point offset;     // the plan's cell (0, 0) in the world's frame
  int wall_change = 0;
  int doors = 0;
  int closed_doors = 0;
  int windows = 0;
};

// Builds the world for plan and rooms (checked by the caller: same size, CV_32SC1) from options and
// seed. Throws Error when no free cell of the plan inside a building lies in a room.
SimulatedWorld build_simulated_world(const OccupancyGrid& plan, const cv::Mat& rooms, const SimulatedMapOptions& options,
                                     std::uint32_t seed);

}  // namespace topocut
