#pragma once
// Robot-made maps of a dataset's plans: for each plan X and seed N, the map a robot would build of it
// (simulated_map.h) as X_sN.png and people's rooms carried over as X_sN_gt_segmentation.png, the
// Bormann layout, so that the dataset runner scores them like any other set (topocut simulate-map
// --dataset, the map suite, the merge model's training).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "topocut/core/option_table.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/exploration/simulated_map.h"
#include "topocut/io/map_loader.h"

namespace topocut {

struct RobotMadeDatasetOptions {
  SimulatedMapOptions simulate;
  MapLoadOptions load;             // how the plans are read
  std::uint32_t first_seed = 1;    // seeds first_seed .. first_seed + seeds - 1
  int seeds = 1;                   // >= 1
  std::function<void(const std::string&)> progress;  // one line per plan, if given
};

// The seeds as options: seed (first_seed; for one plan, its seed) and seeds (option_table.h rows).
const std::vector<OptionRow<RobotMadeDatasetOptions>>& robot_made_seed_rows();

struct RobotMadeDataset {
  int written = 0;                   // maps written
  std::vector<std::string> failed;   // "X: why" for every plan that failed (skipped, the rest go on)
};

// The file name stem of plan's robot-made map for seed: X_sN.
std::string robot_made_name(const std::string& plan, std::uint32_t seed);

// The plan's image (its plain variant) and people's rooms of the map's size; throws Error naming the
// ground truth when its header's size differs from the plan's (before decoding it).
OccupancyGrid load_plan(const DatasetMap& plan, const MapLoadOptions& load, cv::Mat& rooms);

// Writes the robot-made maps of plans into the folder out (created if missing; files replaced
// atomically). Throws Error on bad options or an output folder that cannot be made.
RobotMadeDataset make_robot_made_dataset(const std::vector<DatasetMap>& plans, const std::string& out,
                                         const RobotMadeDatasetOptions& options);

}  // namespace topocut
