// topocut walls: pipeline C — a CARMEN laser log to walls, an occupancy grid and (optionally) rooms.
#include <iostream>
#include <sstream>

#include "cli/command.h"
#include "topocut/core/format.h"
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
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/segmentation/grid_segmentation.h"
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
  bool settle = false;
  FrameSequenceOptions frames;
  // The batch comparison and the real-log preset (wall_map_incremental_options()) with the command
  // line's options; its segment options are the command's.
  GridReplayOptions options = [] {
    GridReplayOptions preset;
    preset.incremental = wall_map_incremental_options(wall_map_segment_options());
    return preset;
  }();
};

void replay(const std::vector<PosedScan>& scans, const WallsOptions& walls, const SegmentOptions& segment_options,
            const ReplayArguments& arguments, const std::string& out_map, const std::string& out_color,
            const std::string& out_rooms) {
  GridReplayOptions options = arguments.options;
  options.incremental.segment = segment_options;
  options.progress = [](const std::string& line) { progress(line); };
  // A real laser reaches tens of metres: its range circle would hide the map.
  FrameWriter frames(arguments.frames, 0.0);
  options.on_update = [&](const ReplayFrame& f) { frames.update(f.update, f.scan, f.grid, f.segmentation, f.path, f.pose); };
  WallMapReplay log_map(scans, walls, arguments.settle ? std::optional(OccupancyEvidenceOptions{}) : std::nullopt);
  const GridReplay run = replay_grids(steps_of(log_map), options);
  if (!run.updates.empty()) {  // end on the finished map
    const int scan = run.updates.back().scan;
    frames.finish(static_cast<int>(run.updates.size()), scan, run.final_map, run.incremental,
                  {run.path.begin(), run.path.begin() + scan}, scans[scan - 1].pose);
  }
  const OccupancyGrid& grid = run.final_map;
  std::cout << "map: " << grid.width() << " x " << grid.height() << " cells at " << grid.resolution << " m, origin ("
            << grid.origin.x << ", " << grid.origin.y << "); built scan by scan, walls not merged"
            << (arguments.settle ? ", cells settled by occupancy evidence" : "") << "\n";
  std::cout << "scans: " << run.scans << ", updates: " << run.updates.size() << "\n";
  std::cout << format_update_times(run.updates);
  std::cout << "stability: " << format_stability(run.stability) << "\n";
  std::cout << format_batch_stability(run);
  std::cout << final_rooms_line(run);
  if (!arguments.frames.folder.empty()) std::cout << "frames: " << frames.written() << " written to " << terminal_text(arguments.frames.folder) << "\n";
  if (!out_map.empty()) save_map(out_map, grid);
  if (!out_color.empty()) write_overlay(out_color, grid, run.incremental);
  if (!out_rooms.empty()) write_rooms_json(out_rooms, run.incremental, in_frame(run.incremental, GridFrame{}).placements);
}

// What walls runs: rooms too, the replay, and how the replay draws its cells.
struct WallsRun {
  bool segment = false, incremental = false, settle = false;
};

// What the command line asks for, checked; `help` when it only asked for the help.
struct WallsRequest {
  bool help = false;
  std::string log_path;
  std::string out_map, out_walls, out_color, out_rooms;
  WallsOptions options;
  CarmenReadOptions read;
  SegmentOptions segment;
  ReplayArguments replay;
  WallsRun run;
  bool incremental = false;
  bool segment_rooms = false;  // --segment, or an output of rooms asked for
};

// The log read and the files written.
const std::vector<TextRow<WallsRequest>>& file_rows() {
  using R = WallsRequest;
  static const std::vector<TextRow<R>> rows = {
      path_row("log", "LOG", TextKind::kInput, &R::log_path, "CARMEN log with FLASER messages (plain or .gz)", true),
      path_row("out-map", "FILE", TextKind::kOutput, &R::out_map, "write the grid as a ROS map_server map (YAML + PGM next to it)"),
      path_row("out-walls", "FILE", TextKind::kOutput, &R::out_walls, "write the merged walls as JSON"),
      path_row("out-color", "FILE", TextKind::kOutput, &R::out_color, "write the rooms as a colour overlay (implies --segment)"),
      path_row("out-rooms", "FILE", TextKind::kOutput, &R::out_rooms, "write the rooms as JSON (implies --segment)")};
  return rows;
}

// --segment, --incremental, --settle.
const std::vector<OptionRow<WallsRun>>& run_rows() {
  using R = WallsRun;
  static const std::vector<OptionRow<R>> rows = {
      switch_row("segment", &R::segment, "segment the grid into rooms (pipeline A)"),
      switch_row("incremental", &R::incremental, "replay the log: build the grid scan by scan and segment every change incrementally"),
      switch_row("settle", &R::settle,
                 "with --incremental: settle each cell by occupancy evidence (log-odds, OctoMap's hit 0.7 / miss 0.4) instead of drawing every scan as it is")};
  return rows;
}

// The options of `walls` (its own, then the shared segmentation flags) bound to the request.
po::options_description walls_options(WallsRequest& r, const SegmentSettings& segment_defaults) {
  po::options_description described("Walls");
  add_text_rows(described, file_rows());
  add_choice_rows(described, line_choice_rows(), r.options.extraction.lines);
  add_choice_rows(described, labeling_choice_rows(), r.options.extraction.labeling);
  add_option_rows(described, walls_option_rows(), r.options);
  add_option_rows(described, carmen_read_option_rows(), r.read);
  add_option_rows(described, run_rows(), r.run);
  add_text_rows(described, frame_folder_rows());
  add_option_rows(described, batch_comparison_rows<GridReplayOptions>(), r.replay.options);
  add_option_rows(described, frame_option_rows(), r.replay.frames);
  po::options_description segmentation("Segmentation (with --segment, --out-color, --out-rooms or --incremental)");
  add_segment_options(segmentation, segment_defaults);
  described.add(segmentation);
  po::options_description incremental("Incremental segmenter (with --incremental; the real-log preset's defaults)");
  add_incremental_options(incremental, r.replay.options.incremental);
  described.add(incremental);
  return described;
}

// The command line parsed, and every option and output checked before the log is read.
WallsRequest parse_request(const std::vector<std::string>& args) {
  WallsRequest r;
  const SegmentSettings segment_defaults{wall_map_segment_options(), {}};
  po::positional_options_description positional;
  positional.add("log", 1);
  const auto vm = parse_options(
      "topocut walls LOG [options]",
      "Builds walls from a CARMEN laser log: each scan is labelled into segments, lines are extracted\n"
      "on every segment and placed in the world by the logged pose, and the segments of all scans are\n"
      "merged into walls. The walls (occupied) and the space the rays crossed (free) make an occupancy\n"
      "grid; with --segment the grid is segmented into rooms.\n\n"
      "--incremental replays the log as the robot saw it: after every scan the grid holds the rays\n"
      "and wall segments seen so far (segments are not merged, since merging needs later scans;\n"
      "with --settle they are occupancy evidence instead: log-odds, hit 0.7, miss 0.4, clamped to\n"
      "0.12..0.97, a cell turns occupied at 0.65 and free at 0.45), and every scan that changes it\n"
      "goes to the incremental segmenter. Prints the time per update\n"
      "(median, p95, max), with --compare-batch batch segmentation on the same updates, and the\n"
      "stability of the room ids (churn: share of labelled cells whose room changed per update).",
      walls_options(r, segment_defaults), positional, args);
  if (!vm) {
    r.help = true;
    return r;
  }
  read_text_rows(*vm, file_rows(), r);
  read_option_rows(*vm, run_rows(), r.run);
  r.incremental = r.run.incremental;
  r.replay.settle = r.run.settle;
  read_text_rows(*vm, frame_folder_rows(), r.replay.frames);
  read_option_rows(*vm, walls_option_rows(), r.options);
  read_option_rows(*vm, carmen_read_option_rows(), r.read);
  r.segment = read_segment_options(*vm, segment_defaults);
  r.replay.options.incremental = read_incremental_options(*vm, r.replay.options.incremental);
  read_option_rows(*vm, batch_comparison_rows<GridReplayOptions>(), r.replay.options);
  read_option_rows(*vm, frame_option_rows(), r.replay.frames);
  read_choice_rows(*vm, line_choice_rows(), r.options.extraction.lines);
  read_choice_rows(*vm, labeling_choice_rows(), r.options.extraction.labeling);
  if (!r.incremental && (r.replay.options.compare_batch || r.replay.settle || !r.replay.frames.folder.empty()))
    throw UsageError("--compare-batch, --settle and --frames need --incremental");
  if (r.incremental && !r.out_walls.empty()) throw UsageError("--out-walls needs merged walls: not with --incremental");
  r.segment_rooms = r.run.segment || !r.out_color.empty() || !r.out_rooms.empty();
  std::vector<std::string> outputs;
  for (const std::string& path : {r.out_map, r.out_walls, r.out_color, r.out_rooms})
    if (!path.empty()) outputs.push_back(path);
  if (!r.out_map.empty()) outputs.push_back(map_image_path(r.out_map));
  check_outputs(outputs, {r.log_path});
  check_usage([&] { validate(r.options); });  // every stage's options, before the log is read
  return r;
}

// The log's laser scans with their poses; warns about skipped lines, throws Error when none is left.
std::vector<PosedScan> read_scans(const std::string& log_path, const CarmenReadOptions& read) {
  const CarmenLog log = read_carmen_log(log_path, read);
  if (log.truncated_last_line) std::cerr << "topocut walls: warning: the last line of '" << log_path << "' is incomplete and was skipped\n";
  if (!log.dropped_lines.empty())
    std::cerr << "topocut walls: warning: " << log.dropped_lines.size() << " FLASER message(s) with a non-finite pose were skipped (first on line "
              << log.dropped_lines.front() << ")\n";
  if (log.scans.empty())
    throw Error("'" + log_path + "' contains no usable FLASER laser scans (" + std::to_string(log.lines) + " lines; found " +
                skipped_summary(log) + ")");
  std::vector<PosedScan> scans = posed_scans(log);
  std::cout << "log: " << terminal_text(log_path) << ": " << scans.size() << " scans, no-return range " << log.max_range << " m"
            << (log.max_range_detected ? " (detected)" : "") << "\n";
  return scans;
}

// The batch pipeline: merged walls, their grid and, when asked, its rooms, printed and written.
void run_batch(const WallsRequest& r, const std::vector<PosedScan>& scans) {
  const WallsResult result = walls_from_scans(scans, r.options);
  std::cout << "walls: " << result.segments.size() << " segments merged into " << result.walls.size() << " walls ("
            << to_string(r.options.extraction.lines.method) << ")\n";
  const OccupancyGrid& grid = result.grid;
  std::cout << "map: " << grid.width() << " x " << grid.height() << " cells at " << grid.resolution << " m, origin ("
            << grid.origin.x << ", " << grid.origin.y << ")\n";
  if (!r.out_walls.empty()) write_file_atomically(r.out_walls, walls_to_json(result, scans.size(), r.options.map.wall_thickness));
  if (!r.out_map.empty()) save_map(r.out_map, grid);
  if (!r.segment_rooms) return;
  const Segmentation rooms = segment(grid, r.segment);
  std::cout << "rooms: " << rooms.rooms.size() << "\n";
  if (!r.out_color.empty()) write_overlay(r.out_color, grid, rooms);
  if (!r.out_rooms.empty()) write_rooms_json(r.out_rooms, rooms, in_frame(rooms, GridFrame{}).placements);
}

int run(const std::vector<std::string>& args) {
  const WallsRequest r = parse_request(args);
  if (r.help) return 0;
  if (!r.replay.frames.folder.empty()) prepare_frames_folder(r.replay.frames.folder, {r.log_path});
  const std::vector<PosedScan> scans = read_scans(r.log_path, r.read);
  if (r.incremental) {
    replay(scans, r.options, r.segment, r.replay, r.out_map, r.out_color, r.out_rooms);
  } else {
    run_batch(r, scans);
  }
  return 0;
}

const bool registered = register_command({"walls", "build walls, a map and rooms from a CARMEN laser log", &run});

}  // namespace
}  // namespace topocut::cli
