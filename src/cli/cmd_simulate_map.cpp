// topocut simulate-map: the map a robot would build of a plan with people's rooms, and those rooms
// in its frame; for one plan, or for every map of a Bormann-format folder with several seeds.
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/library_options.h"
#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/robot_made_dataset.h"
#include "topocut/exploration/simulated_map.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/image_input.h"
#include "topocut/io/map_loader.h"
#include "topocut/io/map_saver.h"
#include "topocut/io/output_files.h"

namespace topocut::cli {
namespace {

namespace fs = std::filesystem;

const char* const kDescription =
    "Turns a plan with people's rooms (a map image or ROS YAML: free floor, walls, anything outside;\n"
    "its ground truth in the Bormann layout: white rooms, black elsewhere) into the map a robot would\n"
    "build of it, with the rooms carried over:\n"
    "  - the exterior (space reached from the border farther than --outer-wall from the floor,\n"
    "    whatever the plan drew there) becomes open ground with trees, posts and cars; windows open\n"
    "    spans of the outer wall to the laser (not to the robot), so beams leave the building and\n"
    "    draw fans outside;\n"
    "  - walls are thinned or thickened by a cell, doors between rooms are closed at random (rooms\n"
    "    behind them may stay unseen), furniture stands against walls, tables and chairs show legs;\n"
    "  - the robot explores from a random start inside with the frontier explorer (topocut explore)\n"
    "    while a 360° lidar (range limit and angular step drawn per seed, Gaussian range noise, no\n"
    "    return beyond the range) maps it from slightly drifting poses: each cell counts the beams\n"
    "    that ended there and those that passed, never-seen cells stay unknown;\n"
    "  - people's rooms are kept on the cells the robot saw as free.\n"
    "The same plan, ground truth, options and seed give the same files, byte for byte.\n\n"
    "Outputs: the map as an image (0 occupied, 255 free, 205 unknown) or, for a .yaml name, a ROS\n"
    "map_server map (YAML + PGM); the ground truth as a PNG (255 rooms, 0 elsewhere). The map is\n"
    "framed around the building with --outside metres to spare (at least 0.5 m), at the plan's\n"
    "resolution.\n\n"
    "--dataset DIR converts a Bormann-format folder (every X.png with X_gt_segmentation.png) into\n"
    "--out DIR (created if missing) as X_sN.png and X_sN_gt_segmentation.png for --seeds seeds N from\n"
    "--seed on, so that 'topocut evaluate --dataset OUT --variant plain' scores it. A plan that fails\n"
    "is reported and skipped (exit code 1 at the end); progress goes to stderr.\n\n"
    "Examples:\n"
    "  topocut simulate-map ../shared/datasets/r2v/X.png --seed 3 --out-map m.png --out-gt m_gt.png\n"
    "  topocut simulate-map --dataset ../shared/datasets/r2v --seeds 3 --limit 20 --out /tmp/sim";

struct Arguments {
  std::string plan, gt, out_map, out_gt, out_world, dataset, out;
  std::vector<std::string> maps;
  int limit = 0;                  // with --dataset: only the first limit plans; 0: all
  RobotMadeDatasetOptions made;   // the simulation, the plans' loading and the seeds
};

// The files read and written, and which plans of a dataset.
const std::vector<TextRow<Arguments>>& file_rows() {
  using A = Arguments;
  static const std::vector<TextRow<A>> rows = {
      path_row("plan", "PLAN", TextKind::kInput, &A::plan, "the plan: a map image or ROS YAML"),
      path_row("gt", "FILE", TextKind::kInput, &A::gt, "its people's rooms, Bormann layout (default: X_gt_segmentation.png beside X.png)"),
      path_row("out-map", "FILE", TextKind::kOutput, &A::out_map, "write the robot's map here (.png, .pgm, ...; .yaml: ROS map_server map)"),
      path_row("out-gt", "FILE", TextKind::kOutput, &A::out_gt, "write people's rooms in the map's frame here (PNG: 255 rooms, 0 elsewhere)"),
      path_row("out-world", "FILE", TextKind::kOutput, &A::out_world,
               "also write the world the robot was in (PNG, map's frame): floor the robot drives on white (light grey near walls), open ground grey, windows dark grey, walls and furniture black"),
      path_row("dataset", "DIR", TextKind::kInput, &A::dataset, "convert every map of this Bormann-format folder instead of one plan"),
      path_row("out", "DIR", TextKind::kOutput, &A::out, "with --dataset: the folder written (X_sN.png, X_sN_gt_segmentation.png)"),
      text_row<A>("map", "NAME", [](A& a, const std::string& name) { a.maps.push_back(name); },
                  "with --dataset: only this plan (repeatable)", true)};
  return rows;
}

const std::vector<OptionRow<Arguments>>& selection_rows() {
  static const std::vector<OptionRow<Arguments>> rows = {
      field_row("limit", "N", OptionRange::kWholeNumber, &Arguments::limit, "with --dataset: only the first N plans (by name; 0: all)")};
  return rows;
}

Arguments parse(const std::vector<std::string>& args, bool& help) {
  Arguments a;
  po::options_description described("Simulation");
  add_text_rows(described, file_rows());
  add_option_rows(described, robot_made_seed_rows(), a.made);
  add_option_rows(described, selection_rows(), a);
  add_option_rows(described, simulated_map_option_rows(), SimulatedMapOptions{});
  add_map_load_options(described, MapLoadOptions{});
  po::positional_options_description positional;
  positional.add("plan", 1);
  const auto vm = parse_options(
      "topocut simulate-map PLAN [--gt GT] [--seed N] --out-map M --out-gt G [options]\n"
      "       topocut simulate-map --dataset DIR [--seeds N] [--seed FIRST] [--limit N] [--map NAME ...] --out DIR [options]",
      kDescription, described, positional, args);
  help = !vm;
  if (!vm) return a;
  read_text_rows(*vm, file_rows(), a);
  read_option_rows(*vm, robot_made_seed_rows(), a.made);
  read_option_rows(*vm, selection_rows(), a);
  read_option_rows(*vm, simulated_map_option_rows(), a.made.simulate);
  check_usage([&] { validate(a.made.simulate); });
  a.made.load = read_map_load_options(*vm, MapLoadOptions{});
  if (a.dataset.empty()) {
    if (a.plan.empty()) throw UsageError("give a PLAN (or --dataset DIR)");
    if (a.out_map.empty() || a.out_gt.empty()) throw UsageError("give both --out-map and --out-gt");
    if (!a.out.empty() || !a.maps.empty() || !(*vm)["seeds"].defaulted() || !(*vm)["limit"].defaulted())
      throw UsageError("--out, --seeds, --limit and --map go with --dataset");
  } else {
    if (!a.plan.empty() || !a.gt.empty() || !a.out_map.empty() || !a.out_gt.empty() || !a.out_world.empty())
      throw UsageError("--dataset converts a folder: give no PLAN, --gt, --out-map, --out-gt or --out-world with it");
    if (a.out.empty()) throw UsageError("--dataset needs --out DIR");
    if (a.made.first_seed + static_cast<std::uint64_t>(a.made.seeds) - 1 > 0xffffffffull)
      throw UsageError("--seed + --seeds - 1 must fit in 32 bits");
  }
  return a;
}

bool is_yaml(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e == ".yaml" || e == ".yml";
}

void write_map(const std::string& path, const SimulatedMap& simulated) {
  if (is_yaml(path)) {
    save_map(path, simulated.map);
  } else {
    write_image_atomically(path, map_image(simulated));
  }
}

std::string summary(const SimulatedMap& s) {
  int rooms = 0;
  double high = 0.0;
  cv::minMaxLoc(s.rooms, nullptr, &high);
  std::vector<char> seen(static_cast<std::size_t>(high) + 1, 0);
  for (auto it = s.rooms.begin<int>(); it != s.rooms.end<int>(); ++it)
    if (*it > 0 && !seen[static_cast<std::size_t>(*it)]) seen[static_cast<std::size_t>(*it)] = 1, ++rooms;
  return format("%d x %d cells, range %.1f m, step %.2f°, walls %+d cell, doors %d (%d closed), windows %d, "
                "%d scans, %.1f m driven, %d rooms seen",
                s.map.width(), s.map.height(), s.range, s.angular_step * 180.0 / std::numbers::pi, s.wall_change, s.doors,
                s.closed_doors, s.windows, s.scans, s.path_length, rooms);
}

int run_one(const Arguments& a) {
  std::string gt = a.gt.empty() ? find_ground_truth(a.plan) : a.gt;
  if (gt.empty()) throw Error("no ground truth beside " + a.plan + " (X_gt_segmentation.png): give --gt");
  std::vector<std::string> outputs{a.out_map, a.out_gt};
  if (!a.out_world.empty()) outputs.push_back(a.out_world);
  if (is_yaml(a.out_map)) outputs.push_back(map_image_path(a.out_map));
  std::vector<std::string> inputs = map_files(a.plan);
  inputs.push_back(gt);
  check_outputs(outputs, inputs);
  cv::Mat rooms;
  const OccupancyGrid plan = load_plan(DatasetMap{a.plan, a.plan, "", gt}, a.made.load, rooms);
  const SimulatedMap simulated = simulate_map(plan, rooms, a.made.simulate, a.made.first_seed);
  write_map(a.out_map, simulated);
  write_image_atomically(a.out_gt, rooms_image(simulated));
  if (!a.out_world.empty()) write_image_atomically(a.out_world, world_image(simulated));
  std::cout << "simulated " << terminal_text(a.plan) << " seed " << a.made.first_seed << ": " << summary(simulated) << "\n";
  return 0;
}

int run_dataset(const Arguments& a) {
  std::vector<DatasetMap> maps = select_maps(discover_dataset(a.dataset), a.maps);
  if (a.limit > 0 && static_cast<std::size_t>(a.limit) < maps.size()) maps.resize(static_cast<std::size_t>(a.limit));
  std::error_code error;  // the folder first: the outputs' check wants their folder to exist
  fs::create_directories(a.out, error);
  if (error || !fs::is_directory(a.out)) throw Error("cannot create the output folder " + a.out);
  std::vector<std::string> outputs, inputs;
  for (const DatasetMap& m : maps) {
    inputs.push_back(m.plain);
    inputs.push_back(m.ground_truth);
    for (int k = 0; k < a.made.seeds; ++k) {
      const std::string stem = (fs::path(a.out) / robot_made_name(m.name, a.made.first_seed + static_cast<std::uint32_t>(k))).string();
      outputs.push_back(stem + ".png");
      outputs.push_back(stem + "_gt_segmentation.png");
    }
  }
  check_outputs(outputs, inputs);
  RobotMadeDatasetOptions options = a.made;
  options.progress = [](const std::string& line) { progress("simulate-map: " + line); };
  const RobotMadeDataset made = make_robot_made_dataset(maps, a.out, options);
  for (const std::string& failure : made.failed)
    std::cerr << "topocut simulate-map: FAILED: " << terminal_text(one_line_message(failure)) << "\n";
  const std::size_t failed = made.failed.size();
  std::cout << "simulated " << made.written << " maps of " << maps.size() - failed << " plans into " << terminal_text(a.out);
  if (failed > 0) std::cout << "; " << failed << " plans FAILED";
  std::cout << "\n";
  return failed > 0 ? 1 : 0;
}

int run(const std::vector<std::string>& args) {
  bool help = false;
  const Arguments a = parse(args, help);
  if (help) return 0;
  return a.dataset.empty() ? run_one(a) : run_dataset(a);
}

const bool registered =
    register_command({"simulate-map", "turn a plan with people's rooms into the map a robot would build of it", &run});

}  // namespace
}  // namespace topocut::cli
