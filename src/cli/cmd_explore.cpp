// topocut explore: a simulated robot explores a map with a 360° laser while the incremental
// segmenter keeps its rooms up to date; prints per-update times and the final quality.
#include <iostream>

#include <cstdint>

#include "cli/command.h"
#include "cli/frames.h"
#include "cli/library_options.h"
#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/exploration_report.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/exploration/exploration_run.h"
#include "topocut/io/map_loader.h"

namespace topocut::cli {
namespace {

// The map explored and its ground truth (found beside the map when not given).
struct ExploreFiles {
  std::string map, gt;
};

const std::vector<TextRow<ExploreFiles>>& file_rows() {
  static const std::vector<TextRow<ExploreFiles>> rows = {
      path_row("map", "MAP", TextKind::kInput, &ExploreFiles::map, "ground-truth map the robot explores (image or ROS YAML)", true),
      path_row("gt", "FILE", TextKind::kInput, &ExploreFiles::gt,
               "ground-truth segmentation image (default: X_gt_segmentation.png next to the map)")};
  return rows;
}

// The map, and the rooms of its ground truth: gt_path, else the one found next to the map (gt_path
// is set to it), else none (empty). The ground truth must have the map's size.
OccupancyGrid load_inputs(const std::string& map_path, const MapLoadOptions& load, std::string& gt_path,
                          cv::Mat& gt_rooms) {
  OccupancyGrid world = load_map(map_path, load);
  if (gt_path.empty()) gt_path = find_ground_truth(map_path);
  if (gt_path.empty()) return world;
  // Its header is checked against the map's size before it is decoded.
  const ExpectedSize size{static_cast<std::uint64_t>(world.width()), static_cast<std::uint64_t>(world.height()), "the map"};
  gt_rooms = ground_truth_rooms(load_ground_truth(gt_path, load.limits, &size));
  return world;
}

int run(const std::vector<std::string>& args) {
  ExploreFiles files;
  ExplorationRunOptions options;
  ExplorationOptions& exploration = options.exploration;
  FrameSequenceOptions frames;
  po::options_description described("Exploration");
  add_text_rows(described, file_rows());
  add_text_rows(described, exploration_text_rows());
  add_option_rows(described, exploration_run_option_rows(), options);
  add_text_rows(described, frame_folder_rows());
  add_option_rows(described, batch_comparison_rows<ExplorationRunOptions>(), options);
  add_option_rows(described, frame_option_rows(), frames);
  add_option_rows(described, exploration_option_rows(), exploration);
  const SegmentSettings segment_defaults{options.incremental.segment, {}};
  add_segment_options(described, segment_defaults);
  po::options_description incremental("Incremental segmenter");
  add_incremental_options(incremental, options.incremental);
  described.add(incremental);
  add_map_load_options(described, MapLoadOptions{});
  po::positional_options_description positional;
  positional.add("map", 1);
  const auto vm = parse_options(
      "topocut explore MAP [--range 5] [--step 0.5] [--seed N] [--compare-batch] [--frames DIR] [options]",
      "Simulates a robot exploring MAP: from the start it takes 360° laser scans (1° beams) ray-cast\n"
      "on the map, builds a known map (unknown / free / occupied) from the scans, and walks in steps\n"
      "toward the nearest reachable frontier until none is left. Every changed known map goes to the\n"
      "incremental segmenter (which decomposes again only the rooms the change touched).\n\n"
      "Prints the number of updates, the incremental time per update (median, p95, max), with\n"
      "--compare-batch the batch time on the same updates, and, when the map has a ground truth\n"
      "(X_gt_segmentation.png next to X.png or X_furnitures.png, or --gt), the final recall and\n"
      "precision of the incremental result and of batch segmentation of the same final map.\n"
      "--frames writes frame_NNNNN.png per update: unknown grey, rooms in their colours with ids,\n"
      "the robot's path and laser range. Progress goes to stderr.",
      described, positional, args);
  if (!vm) return 0;
  read_text_rows(*vm, file_rows(), files);
  read_text_rows(*vm, exploration_text_rows(), exploration);
  read_option_rows(*vm, exploration_run_option_rows(), options);
  read_text_rows(*vm, frame_folder_rows(), frames);
  read_option_rows(*vm, batch_comparison_rows<ExplorationRunOptions>(), options);
  read_option_rows(*vm, frame_option_rows(), frames);
  read_option_rows(*vm, exploration_option_rows(), exploration);
  options.incremental = read_incremental_options(*vm, options.incremental);
  options.incremental.segment = read_segment_options(*vm, segment_defaults);
  check_usage([&] {
    validate(exploration);
    validate(options.incremental.segment);
  });
  const MapLoadOptions load = read_map_load_options(*vm, MapLoadOptions{});

  cv::Mat gt_rooms;
  const OccupancyGrid world = load_inputs(files.map, load, files.gt, gt_rooms);
  if (!frames.folder.empty()) prepare_frames_folder(frames.folder, {files.map, files.gt});
  FrameWriter writer(frames, exploration.range);
  options.on_update = [&](const ExplorationFrame& f) {
    writer.update(f.update, f.explorer.scans(), f.grid, f.segmentation, f.explorer.path(), f.explorer.pose());
  };
  options.progress = [](const std::string& line) { progress(line); };

  const ExplorationRun run = run_exploration(world, options);
  // End the sequence on the finished map: the final map is the last update's grid.
  writer.finish(static_cast<int>(run.updates.size()), run.scans, run.final_map, run.incremental, run.path, run.final_pose);
  std::cout << "map: " << terminal_text(files.map) << " (" << world.width() << " x " << world.height() << " cells, "
            << format("%g m/cell)\n", world.resolution);
  std::cout << format_exploration_summary(run, gt_rooms, files.gt);
  if (!frames.folder.empty()) std::cout << "frames: " << writer.written() << " written to " << terminal_text(frames.folder) << "\n";
  return 0;
}

const bool registered =
    register_command({"explore", "simulate a robot exploring a map, segmenting it incrementally after every scan", &run});

}  // namespace
}  // namespace topocut::cli
