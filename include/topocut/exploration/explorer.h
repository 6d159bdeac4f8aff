#pragma once
// A simulated robot exploring a ground-truth map (pipeline B): 360° laser scans ray-cast on the
// ground truth (scan module), a known map built from the scans alone (unknown / free / occupied),
// and frontier exploration: the robot walks in fixed steps toward the nearest reachable frontier
// until none is left. Everything is deterministic for a given seed.
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"
#include "topocut/core/option_text.h"
#include "topocut/scan/scan.h"

namespace topocut {

struct ExplorationOptions {
  double range = 5.0;                                   // laser range, metres
  double angular_resolution = std::numbers::pi / 180.0; // radians between beams (1°), full circle
  double step = 0.5;                                    // metres walked between two scans
  // Start position (world metres), which must be free in the ground truth. Without it the seed
  // chooses: seed 0 takes the free cell farthest from any obstacle; another seed draws a cell with
  // at least 0.3 m clearance (less if the map has none) uniformly from the largest free component.
  std::optional<Point2> start;
  std::uint32_t seed = 0;
  // Frontier clusters (8-connected known free cells next to unknown ones) with fewer cells than
  // this length in metres are ignored: gaps between beams on far walls, single unseen cells.
  double min_frontier = 0.25;
  int max_scans = 20000;  // cap, so that exploration always ends
  // Publish the known map as a grid that grows with what has been seen (ROS style: new size and
  // origin, in chunks of growth_margin), instead of the ground truth's full frame.
  bool growing_map = false;
  double growth_margin = 2.5;  // metres of unknown kept around the seen cells when growing
};

// The fields of ExplorationOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<ExplorationOptions>>& exploration_option_rows();
// The start position, a point given as text (X,Y in metres).
const std::vector<TextRow<ExplorationOptions>>& exploration_text_rows();

// Throws Error unless the options are usable (positive range, resolution, step; non-negative
// frontier size; at least one scan; positive growth margin).
void validate(const ExplorationOptions& options);

class Explorer {
 public:
  // Keeps a copy of the ground truth. Throws Error on an invalid grid or options, a map without
  // free space, or a start position that is not free.
  Explorer(const OccupancyGrid& ground_truth, const ExplorationOptions& options = {});
  // The same robot kept to the cells where drivable (CV_8UC1, the ground truth's size) is non-zero:
  // the laser still sees every free cell (through glass, over ground the robot may not enter), but
  // routes, frontier targets and the start stay on drivable free cells. Throws Error as above, on a
  // mask of another size or type, or when no free cell is drivable.
  Explorer(const OccupancyGrid& ground_truth, const cv::Mat& drivable, const ExplorationOptions& options);

  // Takes the next scan: the first call scans at the start; every later call first moves the robot
  // one step along its path to the nearest reachable frontier (choosing a new one when the old one
  // is gone). Returns false, changing nothing, once no frontier is reachable or the cap is reached.
  bool next();

  // The known map as published (full ground-truth frame, or the grown window).
  const OccupancyGrid& known_map() const { return published_; }
  // Cells changed by the last scan, in known_map()'s frame (empty if the scan saw nothing new).
  cv::Rect changed() const { return changed_published_; }
  // Where known_map() lies in the ground truth's frame (cells).
  cv::Rect window() const { return window_; }
  // The known map in the ground truth's frame.
  const cv::Mat& known_cells() const { return known_; }
  const OccupancyGrid& ground_truth() const { return truth_; }

  Pose2 pose() const { return pose_; }
  const std::vector<Point2>& path() const { return path_; }  // every scan position, in order
  double path_length() const { return path_length_; }        // metres walked
  int scans() const { return scans_; }
  bool finished() const { return finished_; }
  const std::string& stop_reason() const { return stop_reason_; }
  const ExplorationOptions& options() const { return options_; }

 private:
  void scan();
  bool plan();
  bool target_still_frontier() const;
  bool is_frontier(int index) const;
  int frontier_cluster_size(int index, int limit, std::vector<std::uint32_t>* mark, std::uint32_t stamp) const;
  void publish();

  OccupancyGrid truth_;
  cv::Mat drivable_;  // CV_8UC1, non-zero where the robot may stand; empty: every free cell
  ExplorationOptions options_;
  cv::Mat known_;  // CV_8UC1, ground-truth frame
  OccupancyGrid published_;
  cv::Rect window_;
  cv::Rect seen_box_;  // known (not unknown) cells, ground-truth frame
  cv::Rect changed_published_;
  Pose2 pose_;
  int robot_cell_ = -1;  // row * width + column
  std::vector<Point2> path_;
  double path_length_ = 0.0;
  int scans_ = 0;
  bool finished_ = false;
  std::string stop_reason_;
  int min_frontier_cells_ = 1;
  // Planning state: the route (cell indices) to the current target, and the position along it.
  std::vector<int> route_;
  std::size_t route_position_ = 0;
  std::vector<std::uint32_t> visited_;  // generation stamps, so searches never clear the array
  std::vector<std::uint32_t> rejected_;
  std::vector<int> parent_;
  std::uint32_t generation_ = 0;
};

// The cells of the ground truth that exploration can ever see: the 4-connected free component of
// the start cell. Used to report how much of the map was explored.
int reachable_free_cells(const OccupancyGrid& ground_truth, const Point2& start);

}  // namespace topocut
