// topocut segment: map -> rooms (pipeline A). Loads a map, segments it, writes the requested
// outputs (label image, colour overlay, rooms JSON, SVG) and prints a short summary.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>


#include "cli/command.h"
#include "cli/input_options.h"
#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/image_codec.h"
#include "topocut/io/output_files.h"
#include "topocut/io/label_image.h"
#include "topocut/io/map_loader.h"
#include "topocut/io/overlay.h"
#include "topocut/io/rooms_geojson.h"
#include "topocut/io/rooms_json.h"
#include "topocut/io/rooms_svg.h"
#include "topocut/segmentation/grid_segmentation.h"
#include "topocut/segmentation/segment_switches.h"

namespace topocut::cli {
namespace {

void require_positive(double value, const std::string& option) {
  if (!std::isfinite(value) || value <= 0.0) throw UsageError(option + " must be a positive number");
}

void require_non_negative(double value, const std::string& option) {
  if (!std::isfinite(value) || value < 0.0) throw UsageError(option + " must be a non-negative number");
}

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

int run(const std::vector<std::string>& args) {
  std::string map_path, out_labels, out_color, out_json, out_svg, out_geojson;
  double resolution = 0.05;
  SegmentOptions options;
  MapLoadOptions load;
  SegmentSwitches switches;
  bool fixed_thresholds = false;
  std::string out_clean;
  po::options_description described("Segmentation");
  described.add_options()
      ("map", po::value<std::string>(&map_path)->required(), "map: ROS map_server YAML, or an image (PNG, PGM, ...)")
      ("resolution", po::value<double>(&resolution)->default_value(resolution),
       "metres per cell of a plain image (a YAML's own resolution always wins)")
      ("concavity", po::value<double>(&options.concavity)->default_value(options.concavity),
       "maximum concavity tau in metres: larger values give fewer, less convex rooms")
      ("trivial", po::bool_switch(&switches.trivial), "no decomposition: one room per free-space component (baseline)")
      ("parity", po::bool_switch(&switches.parity),
       "the reference behaviour: DuDe's pieces are the rooms (no door cuts, merging or simplification)")
      ("door-width", po::value<double>(&options.doors.max_width)->default_value(options.doors.max_width),
       "widest passage in metres taken for a door (cut before the decomposition)")
      ("no-doors", po::bool_switch(&switches.no_doors), "no door cuts before the decomposition")
      ("no-wall-openings", po::bool_switch(&switches.no_wall_openings),
       "door cuts only at narrow passages, not where a thin wall stops short of the next obstacle")
      ("no-merge", po::bool_switch(&switches.no_merge), "keep DuDe's pieces as rooms instead of merging them across wide cuts")
      ("fold-area", po::value<double>(&options.merge.min_room_area)->default_value(options.merge.min_room_area),
       "rooms smaller than this (m²) are folded into the neighbour they share the longest cut with")
      ("no-simplify", po::bool_switch(&switches.no_simplify), "decompose the exact pixel-edge polygons (slower)")
      ("cover-obstacles", po::bool_switch(&options.labels.cover_absorbed_obstacles),
       "label the obstacles a room absorbed (furniture) with the room, not with 0")
      ("robot-radius", po::value<double>(&options.binarize.robot_radius)->default_value(0.0),
       "inflate obstacles by this radius in metres before decomposing (0: raw free space)")
      ("min-room-area", po::value<double>(&options.contours.min_component_area)->default_value(options.contours.min_component_area),
       "free-space components smaller than this (m²) are not rooms; their cells join the nearest room")
      ("min-hole-area", po::value<double>(&options.contours.min_hole_area)->default_value(options.contours.min_hole_area),
       "obstacles inside free space smaller than this (m²) are ignored by the decomposition")
      ("no-clean", po::bool_switch(&switches.no_clean),
       "decompose the free space as it is: keep laser-ray fans, slivers, free and obstacle specks")
      ("fixed-thresholds", po::bool_switch(&fixed_thresholds),
       "plain images: use --free-threshold and --occupied-threshold instead of reading the palette from the image")
      ("free-threshold", po::value<int>(&load.free_min)->default_value(load.free_min),
       "plain images with --fixed-thresholds (or no readable palette): grey values above this are free")
      ("occupied-threshold", po::value<int>(&load.occupied_max)->default_value(load.occupied_max),
       "plain images with --fixed-thresholds: grey values below this are occupied (between the two: unknown)")
      ("out-labels", po::value<std::string>(&out_labels), "write the room labels as a 16-bit PNG (0 = no room, rooms 1..N)")
      ("out-color", po::value<std::string>(&out_color), "write a colour overlay of the rooms over the map (PNG, JPEG, ...)")
      ("out-json", po::value<std::string>(&out_json), "write rooms and passages as JSON (metres)")
      ("out-svg", po::value<std::string>(&out_svg), "write rooms and passages as SVG (metres)")
      ("out-geojson", po::value<std::string>(&out_geojson),
       "write rooms (Polygons with holes) and passages (LineStrings) as a GeoJSON FeatureCollection (map frame, metres)")
      ("no-width-steps", po::bool_switch(&switches.no_width_steps),
       "merge a room into a much wider space it opens onto across its whole width (no width-step rule)")
      ("no-furniture-rule", po::bool_switch(&switches.no_furniture_rule),
       "cuts that end on furniture-sized obstacles (at most 2.5 m a side) may separate rooms")
      ("out-clean", po::value<std::string>(&out_clean),
       "write the map as the segmenter saw it (PNG): free, occupied, unknown, and what the cleaning removed in colour");
  add_image_limit_option(described, load.limits);
  po::positional_options_description positional;
  positional.add("map", 1);
  const auto vm = parse_options(
      "topocut segment MAP [options]",
      "Segments the free space of a map into rooms: free space -> cleaning (laser-ray fans, slivers\n"
      "and specks out, obstacle specks in; --out-clean shows it) -> polygons with holes -> door cuts\n"
      "(narrow passages, and openings where a thin wall stops short) -> dual-space decomposition\n"
      "(DuDe) of each part with maximum concavity tau -> pieces merged across cuts that are not\n"
      "door-like (and not width steps) -> rooms, and passages between them (the room graph). Every\n"
      "free cell inside the building gets a room; obstacles, unknown cells and free cells the\n"
      "cleaning put outside the building get none (absorbed obstacles get one with --cover-obstacles).\n"
      "--parity runs the reference behaviour (DuDe's pieces are the rooms).\n"
      "A ROS map_server YAML supplies its own resolution, origin and thresholds; for a plain image\n"
      "the palette is read from the image (free: the brightest grey; unknown: the grey covering the\n"
      "border; occupied: the darkest other grey; transparency is unknown) unless --fixed-thresholds.\n"
      "Prints a summary (rooms, passages, time) and writes each requested output atomically.\n\n"
      "Example:\n  topocut segment maps/floorplan.yaml --out-color rooms.png --out-json rooms.json",
      described, positional, args);
  if (!vm) return 0;

  require_positive(resolution, "--resolution");
  require_positive(options.concavity, "--concavity");
  require_non_negative(options.binarize.robot_radius, "--robot-radius");
  require_non_negative(options.contours.min_component_area, "--min-room-area");
  require_non_negative(options.merge.min_room_area, "--fold-area");
  require_positive(options.doors.max_width, "--door-width");
  require_non_negative(options.contours.min_hole_area, "--min-hole-area");
  if (load.free_min < 0 || load.free_min > 255 || load.occupied_max < 0 || load.occupied_max > 255)
    throw UsageError("--free-threshold and --occupied-threshold must lie in 0..255");
  if (load.occupied_max > load.free_min) throw UsageError("--occupied-threshold must not exceed --free-threshold");
  switches.min_room_area_given = !vm->at("min-room-area").defaulted();
  check_usage([&] { apply(switches, options); });
  if (fixed_thresholds || !vm->at("free-threshold").defaulted() || !vm->at("occupied-threshold").defaulted())
    load.detect_palette = false;
  load.resolution = resolution;
  check_image_limit_option(load.limits);
  check_usage([&] { validate(options); });  // the library's ranges, reported before any work

  // Every output is checked before the work starts, so a typo costs no time and leaves nothing behind.
  const std::pair<const char*, const std::string*> outputs[] = {
      {"out-labels", &out_labels}, {"out-color", &out_color}, {"out-json", &out_json}, {"out-svg", &out_svg}, {"out-clean", &out_clean},
      {"out-geojson", &out_geojson}};
  std::vector<std::string> paths;
  for (const auto& [option, path] : outputs) {
    if (vm->count(option) && path->empty()) throw UsageError("--" + std::string(option) + " was given an empty file name");
    if (!path->empty()) paths.push_back(*path);
  }
  check_outputs(paths, map_files(map_path));
  if (!out_labels.empty() && lower_extension(out_labels) != ".png")
    throw Error("the label image '" + out_labels + "' must be a .png file (16-bit PNG)");
  if (!out_color.empty() && !can_encode_image(out_color))
    throw Error("cannot write the overlay '" + out_color + "': unknown image format (use .png or .jpg)");
  if (!out_clean.empty() && lower_extension(out_clean) != ".png")
    throw Error("the cleaned map '" + out_clean + "' must be a .png file");

  const auto start = std::chrono::steady_clock::now();
  std::string palette;
  const OccupancyGrid grid = load_map(map_path, load, &palette);
  const auto loaded = std::chrono::steady_clock::now();
  SegmentationInput input;
  // The array API's call, in the file's frame (an image's rows are top-down; load_map ignores yaw).
  const GridSegmentation result = segment_grid(grid, GridFrame{}, options, out_clean.empty() ? nullptr : &input);
  const Segmentation& segmentation = result.segmentation;
  const auto done = std::chrono::steady_clock::now();

  if (!out_clean.empty()) write_image_atomically(out_clean, render_cleaned_map(grid.cells, input.cleaned));
  if (!out_labels.empty()) write_label_image(out_labels, segmentation.labels);
  if (!out_color.empty()) write_overlay(out_color, grid, segmentation);
  if (!out_json.empty()) write_rooms_json(out_json, segmentation);
  if (!out_svg.empty()) write_rooms_svg(out_svg, grid, segmentation);
  if (!out_geojson.empty()) write_rooms_geojson(out_geojson, segmentation, result.placements);

  const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  std::ostringstream summary;
  summary << map_path << ": " << grid.width() << " x " << grid.height() << " cells at " << grid.resolution << " m; "
          << segmentation.rooms.size() << (segmentation.rooms.size() == 1 ? " room, " : " rooms, ")
          << segmentation.passages.size() << (segmentation.passages.size() == 1 ? " passage" : " passages") << " ("
          << (switches.trivial ? "trivial: one room per component"
                      : std::string(switches.parity ? "DuDe pieces, parity" : options.clean ? "cleaning + doors + DuDe + merging" : "doors + DuDe + merging") + ", concavity " + [&] {
                          std::ostringstream t;
                          t << options.concavity;
                          return t.str();
                        }() + " m")
          << ") in " << std::fixed << std::setprecision(1) << ms(loaded, done) << " ms (loading " << ms(start, loaded)
          << " ms)\n" << std::defaultfloat;
  summary << "map cells: " << palette << "\n";
  if (is_yaml_path(map_path) && !vm->at("resolution").defaulted())
    summary << "note: --resolution is ignored, the YAML gives " << grid.resolution << " m\n";
  if (!out_labels.empty()) summary << "wrote labels:  " << out_labels << " (16-bit PNG, 0 = no room, rooms 1.." << segmentation.rooms.size() << ")\n";
  if (!out_color.empty()) summary << "wrote overlay: " << out_color << "\n";
  if (!out_json.empty()) summary << "wrote JSON:    " << out_json << "\n";
  if (!out_svg.empty()) summary << "wrote SVG:     " << out_svg << "\n";
  if (!out_geojson.empty()) summary << "wrote GeoJSON: " << out_geojson << "\n";
  if (!out_clean.empty()) summary << "wrote cleaned map: " << out_clean << "\n";
  std::cout << summary.str() << std::flush;
  return 0;
}

const bool registered = register_command({"segment", "segment a map into rooms (labels, overlay, JSON, SVG)", &run});

}  // namespace
}  // namespace topocut::cli
