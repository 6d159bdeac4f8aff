#pragma once
// Robot-made maps from plans with people's rooms: the plan becomes a world a robot could be in (open
// ground outside with trees and cars, windows in the outer wall, some doors closed, furniture and
// clutter, walls a cell thinner or thicker), the Explorer drives through it while a 2-D lidar with a
// range limit, an angular step and range noise maps it from slightly drifting pose estimates by
// counting hits and misses per cell, and people's rooms are carried into the map's frame, kept on
// what the robot saw as free. Deterministic per seed, bit for bit, with every standard library.
#include <cstdint>
#include <numbers>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"

namespace topocut {

// The defaults are those of common indoor robots: a lidar of the SICK LMS 2xx / Hokuyo UTM-30LX /
// RPLIDAR class (data sheets: 8 to 30 m range, 0.25 to 1 degree steps, 1 to 3 cm range noise) and
// gmapping's occupancy threshold (occ_thresh 0.25: a cell is occupied when a quarter of the beams
// that reached it ended there). A beam without a return draws nothing, as in gmapping and as the raw
// maps of the shared real_maps/ show (fans of single rays to what lies outside); Cartographer instead
// clears its missing_data_ray_length, 5 m (no_return_length). Every realism has a value that switches
// it off (0, or from = to).
struct SimulatedMapOptions {
  // Lidar. The range limit and the angular step are drawn per seed, uniformly between from and to.
  double range_from = 8.0;                                  // metres
  double range_to = 30.0;                                   // metres
  double angular_step_from = 0.25 * std::numbers::pi / 180; // radians between beams, 360° scans
  double angular_step_to = 1.0 * std::numbers::pi / 180;
  double range_noise = 0.02;      // metres, standard deviation of the Gaussian noise on each return
  double no_return_length = 0.0;  // metres of free space a beam without a return clears (0: none)
  double occupied_ratio = 0.25;   // a seen cell is occupied when hits / (hits + misses) reaches this
  // Robot: it drives the Explorer's frontier exploration (its own 360° laser of explore_range for
  // choosing where to go) on cells at least robot_radius from everything solid, and maps a scan
  // every scan_step metres.
  double explore_range = 5.0;  // metres
  double scan_step = 0.5;      // metres
  double robot_radius = 0.15;  // metres
  // Pose drift: the error of the pose each scan is mapped with wanders (a random walk pulled back
  // toward zero, as loop closures do) within these bounds, so walls seen from afar come out doubled
  // or blurred while people's rooms stay within a cell or two of the map's.
  double drift = 0.05;                                // metres, largest position error
  double drift_angle = 0.3 * std::numbers::pi / 180;  // radians, largest heading error
  // The building. The exterior (space reached from the image border through cells farther than
  // outer_wall from the floor, whatever the plan drew there) becomes open ground, `outside` metres of
  // it around the building; windows (glass doors, open outer doors) open that share of the outer
  // wall's length to the laser (not to the robot), so beams leave and draw fans outside.
  double outside = 3.0;            // metres of open ground around the building (0: a solid exterior)
  double outer_wall = 0.25;        // metres: outer walls are kept at most this thick
  double windows = 0.1;            // share of the outer wall the laser sees through
  double outside_obstacles = 8.0;  // trees, bushes, posts and cars per 100 m² of open ground
  // Inside. Doors are the openings people's rooms are cut at (free in the plan, in no room, between
  // two rooms, at most max_door_width across); each is closed with probability closed_doors.
  double closed_doors = 0.25;
  double max_door_width = 1.6;  // metres
  double furniture = 0.12;      // share of each room's floor under beds, sofas, shelves, desks
  double clutter = 1.0;         // tables (seen as legs) with chairs, bins and boxes, per 10 m² of floor
  double door_clearance = 0.5;  // metres around every door kept free of furniture and clutter
  int wall_change = 1;          // walls thinned or thickened by up to this many cells, drawn per seed
  // People's rooms: free map cells in no room within this distance of a room take its label (the
  // band drift and thinned walls leave along walls).
  double room_fill = 0.1;  // metres
  int max_scans = 20000;   // the Explorer's cap
};

// Throws Error unless the options are usable (ranges ordered and positive, shares in [0, 1], ...).
void validate(const SimulatedMapOptions& options);

// The options as people give them (simulate-map's flags, Python keywords): angles in degrees.
const std::vector<OptionRow<SimulatedMapOptions>>& simulated_map_option_rows();

struct SimulatedMap {
  // The robot's map (kOccupied, kFree, kUnknown for never seen or undecided), at the plan's resolution,
  // framed around the building with `outside` (at least 0.5 m) to spare; origin keeps world positions.
  OccupancyGrid map;
  cv::Mat rooms;      // CV_32SC1, map's frame: people's room labels (the input's) on the map's free cells, 0 elsewhere;
                      // cells 8-touching another room are 0, so an 8-connected flood fill finds the rooms again
  cv::Point offset;   // the plan's cell (0, 0) in map's frame (negative: the plan was cropped)
  // What the robot was in, in map's frame: the world it scanned (kFree, kOccupied), where it could
  // drive, the exterior (open ground and its obstacles) and the windows (CV_8UC1, 255 on the cells).
  OccupancyGrid world;
  cv::Mat drivable;
  cv::Mat exterior;
  cv::Mat glass;
  // What the seed drew and what happened.
  double range = 0.0;          // metres
  double angular_step = 0.0;   // radians
  int wall_change = 0;         // cells: + thicker, - thinner
  int doors = 0;
  int closed_doors = 0;
  int windows = 0;
  int scans = 0;
  double path_length = 0.0;    // metres
};

// The map a robot would build of plan (kFree, kOccupied, kUnknown cells; the building's free space
// inside, anything outside) whose people's rooms are rooms (CV_32SC1 of plan's size, 0 = no room,
// e.g. ground_truth_rooms() of a Bormann-style ground truth), for this seed. Throws Error on a bad
// grid, options or room image, or a plan with no room inside a building.
SimulatedMap simulate_map(const OccupancyGrid& plan, const cv::Mat& rooms, const SimulatedMapOptions& options,
                          std::uint32_t seed);

// The map as an image (CV_8UC1) the way r2v and ROS map_saver draw one: 0 occupied, 255 free, 205
// unknown (never seen, or seen too rarely to decide).
cv::Mat map_image(const SimulatedMap& simulated);

// People's rooms in the Bormann layout (CV_8UC1): 255 on a room's cells, 0 elsewhere; an 8-connected
// flood fill of the 255 cells gives the rooms back.
cv::Mat rooms_image(const SimulatedMap& simulated);

// The world the robot was in, for people (CV_8UC1): 255 where the laser passes and the robot may
// drive, 230 the rest of the floor (near walls), 160 open ground, 90 glass (windows), 0 solid (walls,
// closed doors, furniture, obstacles).
cv::Mat world_image(const SimulatedMap& simulated);

}  // namespace topocut
