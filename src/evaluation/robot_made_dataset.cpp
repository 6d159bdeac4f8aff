#include "topocut/evaluation/robot_made_dataset.h"

#include <filesystem>

#include "topocut/core/error.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/image_input.h"

namespace topocut {

const std::vector<OptionRow<RobotMadeDatasetOptions>>& robot_made_seed_rows() {
  using R = RobotMadeDatasetOptions;
  static const std::vector<OptionRow<R>> rows = {
      field_row("seed", "N", OptionRange::kSeed, &R::first_seed, "the seed (with --dataset: the first of --seeds seeds)"),
      field_row("seeds", "N", OptionRange::kCount, &R::seeds, "with --dataset: maps per plan, seeds --seed .. --seed + N - 1"),
  };
  return rows;
}

std::string robot_made_name(const std::string& plan, std::uint32_t seed) { return plan + "_s" + std::to_string(seed); }

OccupancyGrid load_plan(const DatasetMap& plan, const MapLoadOptions& load, cv::Mat& rooms) {
  OccupancyGrid grid = load_map(plan.plain, load);
  // The ground truth's header is checked against the plan's size before it is decoded.
  const ExpectedSize size{static_cast<std::uint64_t>(grid.width()), static_cast<std::uint64_t>(grid.height()), "the plan"};
  rooms = ground_truth_rooms(load_ground_truth(plan.ground_truth, load.limits, &size));
  return grid;
}

RobotMadeDataset make_robot_made_dataset(const std::vector<DatasetMap>& plans, const std::string& out,
                                         const RobotMadeDatasetOptions& options) {
  validate(options.simulate);
  if (options.seeds < 1) throw Error("the number of seeds must be at least 1");
  if (options.first_seed + static_cast<std::uint64_t>(options.seeds) - 1 > 0xffffffffull)
    throw Error("the first seed + the number of seeds - 1 must fit in 32 bits");
  std::error_code error;
  std::filesystem::create_directories(out, error);
  if (error || !std::filesystem::is_directory(out)) throw Error("cannot create the output folder " + out);
  RobotMadeDataset made;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    const DatasetMap& plan = plans[i];
    if (options.progress) options.progress(std::to_string(i + 1) + "/" + std::to_string(plans.size()) + " " + plan.name);
    try {
      cv::Mat rooms;
      const OccupancyGrid grid = load_plan(plan, options.load, rooms);
      for (int k = 0; k < options.seeds; ++k) {
        const std::uint32_t seed = options.first_seed + static_cast<std::uint32_t>(k);
        const SimulatedMap simulated = simulate_map(grid, rooms, options.simulate, seed);
        const std::filesystem::path stem = std::filesystem::path(out) / robot_made_name(plan.name, seed);
        write_image_atomically(stem.string() + ".png", map_image(simulated));
        write_image_atomically(stem.string() + "_gt_segmentation.png", rooms_image(simulated));
        ++made.written;
      }
    } catch (const Error& e) {
      made.failed.push_back(plan.name + ": " + e.what());
    }
  }
  return made;
}

}  // namespace topocut
