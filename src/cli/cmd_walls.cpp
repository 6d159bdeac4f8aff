// topocut walls: pipeline C — a CARMEN laser log to walls, an occupancy grid and (optionally) rooms.
#include <iostream>
#include <sstream>

#include "cli/command.h"
#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/output_files.h"
#include "topocut/io/carmen_log.h"
#include "topocut/io/map_saver.h"
#include "topocut/io/overlay.h"
#include "topocut/io/rooms_json.h"
#include "topocut/segmentation/segmenter.h"
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

int run(const std::vector<std::string>& args) {
  std::string log_path, method = "iepf", element = "cross";
  std::string out_map, out_walls, out_color, out_rooms;
  WallsOptions options;
  CarmenReadOptions read;
  SegmentOptions segment_options;
  // Single rays through doors leave one-cell-wide free spurs; opening them away keeps them out of
  // the rooms (the benchmark uses the same value).
  segment_options.binarize.opening_size = 0.15;
  po::options_description described("Walls");
  described.add_options()
      ("log", po::value<std::string>(&log_path)->required(), "CARMEN log with FLASER messages (plain or .gz)")
      ("resolution", po::value<double>(&options.map.resolution)->default_value(options.map.resolution, "0.05"), "grid resolution in metres per cell")
      ("method", po::value<std::string>(&method)->default_value(method), "line extractor: sef, lt, iepf, smf or ale")
      ("cell", po::value<double>(&options.extraction.labeling.cell_size)->default_value(options.extraction.labeling.cell_size, "0.10"), "labeling cell size in metres")
      ("dilate", po::value<int>(&options.extraction.labeling.dilation)->default_value(options.extraction.labeling.dilation), "labeling dilation iterations")
      ("element", po::value<std::string>(&element)->default_value(element), "labeling structuring element: cross or square")
      ("thickness", po::value<double>(&options.map.wall_thickness)->default_value(options.map.wall_thickness, "0.10"), "wall thickness in metres")
      ("max-range", po::value<double>(&read.max_range)->default_value(0.0), "readings at or beyond this range (m) are no return; 0 detects the laser's saturation value")
      ("out-map", po::value<std::string>(&out_map), "write the grid as a ROS map_server map (YAML + PGM next to it)")
      ("out-walls", po::value<std::string>(&out_walls), "write the merged walls as JSON")
      ("segment", "segment the grid into rooms (pipeline A)")
      ("concavity", po::value<double>(&segment_options.concavity)->default_value(segment_options.concavity, "2.5"), "tau for --segment, metres")
      ("opening", po::value<double>(&segment_options.binarize.opening_size)->default_value(segment_options.binarize.opening_size, "0.15"), "for --segment: open the free space with a square of this side (m) to drop single-ray spurs; 0: off")
      ("out-color", po::value<std::string>(&out_color), "write the rooms as a colour overlay (implies --segment)")
      ("out-rooms", po::value<std::string>(&out_rooms), "write the rooms as JSON (implies --segment)");
  po::positional_options_description positional;
  positional.add("log", 1);
  const auto vm = parse_options(
      "topocut walls LOG [options]",
      "Builds walls from a CARMEN laser log: each scan is labelled into segments, lines are extracted\n"
      "on every segment and placed in the world by the logged pose, and the segments of all scans are\n"
      "merged into walls. The walls (occupied) and the space the rays crossed (free) make an occupancy\n"
      "grid; with --segment the grid is segmented into rooms.",
      described, positional, args);
  if (!vm) return 0;
  try {
    options.extraction.lines.method = parse_line_method(method);
  } catch (const Error& e) {
    throw UsageError(std::string("--method: ") + e.what());
  }
  if (element == "cross") options.extraction.labeling.element = StructuringElement::kCross;
  else if (element == "square") options.extraction.labeling.element = StructuringElement::kSquare;
  else throw UsageError("--element must be 'cross' or 'square', got '" + element + "'");
  const bool segment_rooms = vm->count("segment") || !out_color.empty() || !out_rooms.empty();
  std::vector<std::string> outputs;
  for (const std::string& path : {out_map, out_walls, out_color, out_rooms})
    if (!path.empty()) outputs.push_back(path);
  if (!out_map.empty()) outputs.push_back(map_image_path(out_map));
  check_outputs(outputs, {log_path});

  const CarmenLog log = read_carmen_log(log_path, read);
  if (log.truncated_last_line) std::cerr << "topocut walls: warning: the last line of '" << log_path << "' is incomplete and was skipped\n";
  if (!log.dropped_lines.empty())
    std::cerr << "topocut walls: warning: " << log.dropped_lines.size() << " FLASER message(s) with a non-finite pose were skipped (first on line "
              << log.dropped_lines.front() << ")\n";
  if (log.scans.empty())
    throw Error("'" + log_path + "' contains no usable FLASER laser scans (" + std::to_string(log.lines) + " lines; found " +
                skipped_summary(log) + ")");
  const std::vector<PosedScan> scans = posed_scans(log);
  const WallsResult result = walls_from_scans(scans, options);

  std::cout << "log: " << log_path << ": " << scans.size() << " scans, no-return range " << log.max_range << " m"
            << (log.max_range_detected ? " (detected)" : "") << "\n";
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
