// topocut walls: pipeline C — a CARMEN laser log to walls, an occupancy grid and (optionally) rooms.
#include <iostream>
#include <sstream>

#include "cli/command.h"
#include "cli/frames.h"
#include "cli/library_options.h"
#include "topocut/core/error.h"
#include "topocut/evaluation/exploration_report.h"
#include "topocut/exploration/grid_replay.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/output_files.h"
#include "topocut/io/carmen_log.h"
#include "topocut/io/map_saver.h"
#include "topocut/io/overlay.h"
#include "topocut/io/rooms_json.h"
#include "topocut/segmentation/segmenter.h"
#include "topocut/segmentation/wall_map_segment_options.h"
#include "topocut/walls/wall_map_replay.h"
#include "topocut/walls/walls_json.h"
#include "topocut/walls/walls_pipeline.h"

namespace topocut::cli {
namespace {

std::string skipped_summary(const CarmenLog& log) {
  std::ostringstream out;
  bool first = true;
  for (const auto& [name, count] : log.skipped_messages) {
    out << (first ? "" : ", ") << name << " x" << count;
    first = false;
  }
  return first ? "nothing else" : out.str();
}

// --incremental: the log replayed scan by scan (the walls module's grid after each scan) into the
// incremental segmenter.
struct ReplayArguments {
  bool compare_batch = false;
  int batch_every = 1;
  std::string frames;
  int frame_every = 1;
};

void replay(const std::vector<PosedScan>& scans, const WallsOptions& walls, const SegmentOptions& segment_options,
            const ReplayArguments& arguments, const std::string& out_map, const std::string& out_color,
            const std::string& out_rooms) {
  GridReplayOptions options;
  options.incremental.segment = segment_options;
  options.incremental.segment.clean = false;  // not incremental (IncrementalOptions)
  options.compare_batch = arguments.compare_batch;
  options.batch_every = arguments.batch_every;
  options.progress = [](const std::string& line) { progress(line); };
  // A real laser reaches tens of metres: its range circle would hide the map.
  FrameWriter frames(arguments.frames, arguments.frame_every, 0.0);
  options.on_update = [&](const ReplayFrame& f) { frames.update(f.update, f.scan, f.grid, f.segmentation, f.path, f.pose); };
  WallMapReplay log_map(scans, walls);
  const GridReplay run = replay_grids(steps_of(log_map), options);
  if (!run.updates.empty()) {  // end on the finished map
    const int scan = run.updates.back().scan;
    frames.finish(static_cast<int>(run.updates.size()), scan, run.final_map, run.incremental,
                  {run.path.begin(), run.path.begin() + scan}, scans[scan - 1].pose);
  }
  const OccupancyGrid& grid = run.final_map;
  std::cout << "map: " << grid.width() << " x " << grid.height() << " cells at " << grid.resolution << " m, origin ("
            << grid.origin.x << ", " << grid.origin.y << "); built scan by scan, walls not merged\n";
  std::cout << "scans: " << run.scans << ", updates: " << run.updates.size() << "\n";
  std::cout << format_update_times(run.updates);
  std::cout << "stability: " << format_stability(run.stability) << "\n";
  std::cout << "final rooms: incremental " << run.incremental.rooms.size() << ", batch " << run.batch.rooms.size() << "\n";
  if (!arguments.frames.empty()) std::cout << "frames: " << frames.written() << " written to " << arguments.frames << "\n";
  if (!out_map.empty()) save_map(out_map, grid);
  if (!out_color.empty()) write_overlay(out_color, grid, run.incremental);
  if (!out_rooms.empty()) write_rooms_json(out_rooms, run.incremental);
}

int run(const std::vector<std::string>& args) {
  std::string log_path, method = "iepf", element = "cross";
  std::string out_map, out_walls, out_color, out_rooms;
  WallsOptions options;
  CarmenReadOptions read;
  const SegmentSettings segment_defaults{wall_map_segment_options(), {}};
  ReplayArguments replay_arguments;
  po::options_description described("Walls");
  described.add_options()
      ("log", po::value<std::string>(&log_path)->required(), "CARMEN log with FLASER messages (plain or .gz)")
      ("resolution", number_value(options.map.resolution), "grid resolution in metres per cell")
      ("method", po::value<std::string>(&method)->default_value(method), "line extractor: sef, lt, iepf, smf or ale")
      ("cell", number_value(options.extraction.labeling.cell_size), "labeling cell size in metres")
      ("dilate", po::value<int>(&options.extraction.labeling.dilation)->default_value(options.extraction.labeling.dilation), "labeling dilation iterations")
      ("element", po::value<std::string>(&element)->default_value(element), "labeling structuring element: cross or square")
      ("thickness", number_value(options.map.wall_thickness), "wall thickness in metres")
      ("max-range", po::value<double>(&read.max_range)->default_value(0.0), "readings at or beyond this range (m) are no return; 0 detects the laser's saturation value")
      ("out-map", po::value<std::string>(&out_map), "write the grid as a ROS map_server map (YAML + PGM next to it)")
      ("out-walls", po::value<std::string>(&out_walls), "write the merged walls as JSON")
      ("segment", "segment the grid into rooms (pipeline A)")
      ("out-color", po::value<std::string>(&out_color), "write the rooms as a colour overlay (implies --segment)")
      ("out-rooms", po::value<std::string>(&out_rooms), "write the rooms as JSON (implies --segment)")
      ("incremental", "replay the log: build the grid scan by scan and segment every change incrementally")
      ("compare-batch", po::bool_switch(&replay_arguments.compare_batch), "with --incremental: also run the batch segmenter on every update, timed")
      ("batch-every", po::value<int>(&replay_arguments.batch_every)->default_value(1), "with --compare-batch: only every N-th update (and the last)")
      ("frames", po::value<std::string>(&replay_arguments.frames), "with --incremental: write a PNG frame of every update into this folder")
      ("frame-every", po::value<int>(&replay_arguments.frame_every)->default_value(1), "with --frames: only every N-th update (and the last)");
  po::options_description segmentation("Segmentation (with --segment, --out-color, --out-rooms or --incremental)");
  add_segment_options(segmentation, segment_defaults);
  described.add(segmentation);
  po::positional_options_description positional;
  positional.add("log", 1);
  const auto vm = parse_options(
      "topocut walls LOG [options]",
      "Builds walls from a CARMEN laser log: each scan is labelled into segments, lines are extracted\n"
      "on every segment and placed in the world by the logged pose, and the segments of all scans are\n"
      "merged into walls. The walls (occupied) and the space the rays crossed (free) make an occupancy\n"
      "grid; with --segment the grid is segmented into rooms.\n\n"
      "--incremental replays the log as the robot saw it: after every scan the grid holds the rays\n"
      "and wall segments seen so far (segments are not merged, since merging needs later scans), and\n"
      "every scan that changes it goes to the incremental segmenter. Prints the time per update\n"
      "(median, p95, max), with --compare-batch batch segmentation on the same updates, and the\n"
      "stability of the room ids (churn: share of labelled cells whose room changed per update).",
      described, positional, args);
  if (!vm) return 0;
  const SegmentOptions segment_options = read_segment_options(*vm, segment_defaults);
  try {
    options.extraction.lines.method = parse_line_method(method);
  } catch (const Error& e) {
    throw UsageError(std::string("--method: ") + e.what());
  }
  if (element == "cross") options.extraction.labeling.element = StructuringElement::kCross;
  else if (element == "square") options.extraction.labeling.element = StructuringElement::kSquare;
  else throw UsageError("--element must be 'cross' or 'square', got '" + element + "'");
  const bool incremental = vm->count("incremental") > 0;
  if (!incremental && (replay_arguments.compare_batch || !replay_arguments.frames.empty()))
    throw UsageError("--compare-batch and --frames need --incremental");
  if (incremental && !out_walls.empty()) throw UsageError("--out-walls needs merged walls: not with --incremental");
  if (replay_arguments.batch_every < 1) throw UsageError("--batch-every must be at least 1");
  if (replay_arguments.frame_every < 1) throw UsageError("--frame-every must be at least 1");
  const bool segment_rooms = vm->count("segment") || !out_color.empty() || !out_rooms.empty();
  std::vector<std::string> outputs;
  for (const std::string& path : {out_map, out_walls, out_color, out_rooms})
    if (!path.empty()) outputs.push_back(path);
  if (!out_map.empty()) outputs.push_back(map_image_path(out_map));
  check_outputs(outputs, {log_path});
  check_usage([&] { validate(options); });  // every stage's options, before the log is read
  if (!replay_arguments.frames.empty()) prepare_frames_folder(replay_arguments.frames, {log_path});

  const CarmenLog log = read_carmen_log(log_path, read);
  if (log.truncated_last_line) std::cerr << "topocut walls: warning: the last line of '" << log_path << "' is incomplete and was skipped\n";
  if (!log.dropped_lines.empty())
    std::cerr << "topocut walls: warning: " << log.dropped_lines.size() << " FLASER message(s) with a non-finite pose were skipped (first on line "
              << log.dropped_lines.front() << ")\n";
  if (log.scans.empty())
    throw Error("'" + log_path + "' contains no usable FLASER laser scans (" + std::to_string(log.lines) + " lines; found " +
                skipped_summary(log) + ")");
  const std::vector<PosedScan> scans = posed_scans(log);
  std::cout << "log: " << log_path << ": " << scans.size() << " scans, no-return range " << log.max_range << " m"
            << (log.max_range_detected ? " (detected)" : "") << "\n";
  if (incremental) {
    replay(scans, options, segment_options, replay_arguments, out_map, out_color, out_rooms);
    return 0;
  }
  const WallsResult result = walls_from_scans(scans, options);
  std::cout << "walls: " << result.segments.size() << " segments merged into " << result.walls.size() << " walls ("
            << method << ")\n";
  const OccupancyGrid& grid = result.grid;
  std::cout << "map: " << grid.width() << " x " << grid.height() << " cells at " << grid.resolution << " m, origin ("
            << grid.origin.x << ", " << grid.origin.y << ")\n";
  if (!out_walls.empty()) write_file_atomically(out_walls, walls_to_json(result, scans.size(), options.map.wall_thickness));
  if (!out_map.empty()) save_map(out_map, grid);
  if (segment_rooms) {
    const Segmentation rooms = segment(grid, segment_options);
    std::cout << "rooms: " << rooms.rooms.size() << "\n";
    if (!out_color.empty()) write_overlay(out_color, grid, rooms);
    if (!out_rooms.empty()) write_rooms_json(out_rooms, rooms);
  }
  return 0;
}

const bool registered = register_command({"walls", "build walls, a map and rooms from a CARMEN laser log", &run});

}  // namespace
}  // namespace topocut::cli
