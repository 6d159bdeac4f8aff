// topocut segment: map -> rooms (pipeline A). Loads a map, segments it, writes the requested
// outputs (label image, colour overlay, rooms JSON, SVG) and prints a short summary.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>


#include "cli/command.h"
#include "cli/library_options.h"
#include "topocut/core/error.h"
#include "topocut/core/format.h"
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
#include "topocut/segmentation/room_at.h"
#include "topocut/segmentation/segment_switches.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace topocut::cli {
namespace {

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// The files the command writes; empty: not requested.
struct Outputs {
  std::string labels, color, json, svg, geojson, clean;
  bool color_by_kind = false;  // the overlay tints rooms by kind
};

// A point given with --at: its text as given, and where it is (map frame, metres).
struct QueryPoint {
  std::string text;
  Point2 point;
};

// What the command line asks for, checked.
struct Request {
  std::string map_path;
  Outputs out;
  std::vector<QueryPoint> at;
  SegmentSettings settings;  // as given, for the summary (trivial, parity)
  SegmentOptions options;    // the settings applied
  MapLoadOptions load;
  bool resolution_given = false;
};

const char* const kDescription =
    "Segments the free space of a map into rooms: free space -> cleaning (laser-ray fans, slivers\n"
    "and specks out, obstacle specks in; --out-clean shows it) -> polygons with holes -> door cuts\n"
    "(narrow passages, and openings where a thin wall stops short) and wall lines (straight walls\n"
    "continued across wide openings) -> dual-space decomposition (DuDe) of each part with maximum\n"
    "concavity tau -> pieces merged across cuts that are not\n"
    "door-like (and not width steps) -> rooms, and passages between them (the room graph). Every\n"
    "free cell inside the building gets a room; obstacles, unknown cells and free cells the\n"
    "cleaning put outside the building get none (absorbed obstacles get one with --cover-obstacles).\n"
    "--parity runs the reference behaviour (DuDe's pieces are the rooms): it sets --no-clean,\n"
    "--no-doors, --no-merge, --no-simplify and the reference's --min-room-area, so it is given\n"
    "alone or with numbers (--concavity, --min-room-area, --robot-radius, ...) and --trivial; with\n"
    "a switch it already sets, or --cover-obstacles, it is a usage error.\n"
    "`topocut rules` lists the pipeline's rows in order, with their --no-NAME switches.\n"
    "A ROS map_server YAML supplies its own resolution, origin and thresholds; for a plain image\n"
    "the palette is read from the image (free: the brightest grey; unknown: the grey covering the\n"
    "border; occupied: the darkest other grey; transparency is unknown) unless --fixed-thresholds.\n"
    "Prints a summary (rooms, passages, time) and writes each requested output atomically; a note\n"
    "says when an image's resolution was assumed (an image holds no scale) or nothing was asked for.\n"
    "--at X,Y (map frame, metres; repeatable) then prints 'at X,Y: room ID' for the room whose cell\n"
    "holds the point, or 'at X,Y: none' (an obstacle, unknown space, off the map).\n"
    "Every room has a kind, measured once the rooms are final: 'corridor' (long for its width,\n"
    "at most 1.1 m wide or an office hallway, and opening onto three or more rooms) or 'room'; the\n"
    "JSON and GeoJSON say it as \"kind\", --color-by-kind draws it.\n\n"
    "Example:\n  topocut segment maps/floorplan.yaml --out-color rooms.png --out-json rooms.json --at 2.0,1.5";

// What segment writes, one row per file (the command line and --config take them alike).
const std::vector<TextRow<Outputs>>& output_rows() {
  static const std::vector<TextRow<Outputs>> rows = {
      path_row("out-labels", "FILE", TextKind::kOutput, &Outputs::labels, "write the room labels as a 16-bit PNG (0 = no room, rooms 1..N)"),
      path_row("out-color", "FILE", TextKind::kOutput, &Outputs::color, "write a colour overlay of the rooms over the map (PNG, JPEG, ...)"),
      path_row("out-json", "FILE", TextKind::kOutput, &Outputs::json, "write rooms (with their kind) and passages as JSON (metres)"),
      path_row("out-svg", "FILE", TextKind::kOutput, &Outputs::svg, "write rooms and passages as SVG (metres)"),
      path_row("out-geojson", "FILE", TextKind::kOutput, &Outputs::geojson,
               "write rooms (Polygons with holes) and passages (LineStrings) as a GeoJSON FeatureCollection (map frame, metres)"),
      path_row("out-clean", "FILE", TextKind::kOutput, &Outputs::clean,
               "write the map as the segmenter saw it (PNG): free, occupied, unknown, and what the cleaning removed in colour")};
  return rows;
}

// How the overlay is drawn.
const std::vector<OptionRow<Outputs>>& output_switch_rows() {
  static const std::vector<OptionRow<Outputs>> rows = {switch_row(
      "color-by-kind", &Outputs::color_by_kind, "with --out-color: tint corridors orange and other rooms blue instead of a colour per room")};
  return rows;
}

QueryPoint query_point(const std::string& text);

// The map segment reads and the points it is asked about.
const std::vector<TextRow<Request>>& request_rows() {
  static const std::vector<TextRow<Request>> rows = {
      path_row("map", "MAP", TextKind::kInput, &Request::map_path, "map: ROS map_server YAML, or an image (PNG, PGM, ...)", true),
      text_row<Request>("at", "X,Y", [](Request& r, const std::string& text) { r.at.push_back(query_point(text)); },
                        "print the room at this point of the map frame (metres), or none; repeatable", true)};
  return rows;
}

// "X,Y" in metres (map frame); a UsageError otherwise.
QueryPoint query_point(const std::string& text) {
  QueryPoint q{text, {}};
  check_usage([&] { q.point = parse_option_point(text, "--at"); });
  return q;
}

// Every output is checked before the work starts, so a typo costs no time and leaves nothing behind.
// (An empty file name was refused by its row.)
void check_output_files(const Request& request) {
  const Outputs& out = request.out;
  std::vector<std::string> paths;
  for (const std::string* path : {&out.labels, &out.color, &out.json, &out.svg, &out.clean, &out.geojson})
    if (!path->empty()) paths.push_back(*path);
  check_outputs(paths, map_files(request.map_path));
  if (!out.labels.empty() && lower_extension(out.labels) != ".png")
    throw Error("the label image '" + out.labels + "' must be a .png file (16-bit PNG)");
  if (!out.color.empty() && !can_encode_image(out.color))
    throw Error("cannot write the overlay '" + out.color + "': unknown image format (use .png or .jpg)");
  if (!out.clean.empty() && lower_extension(out.clean) != ".png")
    throw Error("the cleaned map '" + out.clean + "' must be a .png file");
}

// The command line parsed and checked; nullopt after --help.
std::optional<Request> parse_request(const std::vector<std::string>& args) {
  Request request;
  po::options_description described("Map and outputs");
  add_text_rows(described, request_rows());
  add_segment_options(described, request.settings);
  add_map_load_options(described, request.load);
  add_text_rows(described, output_rows());
  add_option_rows(described, output_switch_rows(), request.out);
  po::positional_options_description positional;
  positional.add("map", 1);
  const auto vm = parse_options("topocut segment MAP [options]", kDescription, described, positional, args);
  if (!vm) return std::nullopt;
  request.settings = read_segment_settings(*vm, request.settings);
  check_usage([&] { request.options = to_segment_options(request.settings); });  // the library's ranges, before any work
  request.load = read_map_load_options(*vm, request.load);
  request.resolution_given = !vm->at("resolution").defaulted();
  read_text_rows(*vm, request_rows(), request);
  read_text_rows(*vm, output_rows(), request.out);
  read_option_rows(*vm, output_switch_rows(), request.out);
  check_output_files(request);
  if (request.out.color_by_kind && request.out.color.empty()) throw UsageError("--color-by-kind needs --out-color FILE");
  return request;
}

void write_outputs(const Outputs& out, const OccupancyGrid& grid, const GridSegmentation& result,
                   const SegmentationInput& input) {
  const Segmentation& segmentation = result.segmentation;
  if (!out.clean.empty()) write_image_atomically(out.clean, render_cleaned_map(grid.cells, input.cleaned));
  if (!out.labels.empty()) write_label_image(out.labels, segmentation.labels);
  if (!out.color.empty()) {
    OverlayOptions overlay;
    overlay.colour_by_kind = out.color_by_kind;
    write_overlay(out.color, grid, segmentation, overlay);
  }
  if (!out.json.empty()) write_rooms_json(out.json, segmentation, result.placements);
  if (!out.svg.empty()) write_rooms_svg(out.svg, grid, segmentation);
  if (!out.geojson.empty()) write_rooms_geojson(out.geojson, segmentation, result.placements);
}

bool any_output(const Outputs& out) {
  return !(out.labels.empty() && out.color.empty() && out.json.empty() && out.svg.empty() && out.geojson.empty() &&
           out.clean.empty());
}

// The method as the summary names it, e.g. "cleaning + doors + DuDe + merging, concavity 2.5 m": the
// stages that run, then the other rules switched off ("without wall-lines, open-rooms").
std::string method_summary(const Request& request) {
  if (request.settings.switches.trivial) return "trivial: one room per component";
  const SegmentOptions& o = request.options;
  std::ostringstream text;
  if (request.settings.switches.parity) {
    text << "DuDe pieces, parity";
  } else {
    std::string stages = std::string(o.clean ? "cleaning + " : "") + (o.doors.passages ? "doors + " : "") + "DuDe";
    if (o.merge.enabled) stages += o.merge.learned ? " + merging" : " + merging by hand rules";
    std::string others;
    for (const std::string& rule : rules_off(o)) {
      if (rule == "clean" || rule == "doors" || rule == "merge" || rule == "learned-merge") continue;
      // Without merging, its steps (fragments, bays) are not run either: no news.
      if (!o.merge.enabled && find_segmentation_rule(rule)->stage == RuleStage::kMerge) continue;
      others += (others.empty() ? "" : ", ") + rule;
    }
    text << stages << (others.empty() ? "" : ", without " + others);
  }
  text << ", concavity " << o.concavity << " m";
  return text.str();
}

struct Timing {
  double loading_ms = 0.0, segmenting_ms = 0.0;
};

std::string summary(const Request& request, const OccupancyGrid& grid, const Segmentation& segmentation,
                    const std::string& palette, const Timing& timing) {
  const Outputs& out = request.out;
  const std::size_t rooms = segmentation.rooms.size(), passages = segmentation.passages.size();
  std::ostringstream text;
  // File names are anyone's text: escaped, so that none moves the cursor or rewrites the terminal.
  const auto name = [](const std::string& path) { return terminal_text(path); };
  text << name(request.map_path) << ": " << grid.width() << " x " << grid.height() << " cells at " << grid.resolution << " m; "
       << rooms << (rooms == 1 ? " room, " : " rooms, ") << passages << (passages == 1 ? " passage" : " passages") << " ("
       << method_summary(request) << ") in " << std::fixed << std::setprecision(1) << timing.segmenting_ms << " ms (loading "
       << timing.loading_ms << " ms)\n" << std::defaultfloat;
  text << "map cells: " << palette << "\n";
  if (is_yaml_path(request.map_path) && request.resolution_given)
    text << "note: --resolution is ignored, the YAML gives " << grid.resolution << " m\n";
  if (!is_yaml_path(request.map_path) && !request.resolution_given)
    text << "note: an image holds no scale: its cells were taken as " << grid.resolution
         << " m (the default); give --resolution M, or segment the map_server YAML beside it\n";
  if (!any_output(out) && request.at.empty())
    text << "note: nothing written; ask for outputs: --out-json FILE (rooms, passages), --out-labels FILE.png, "
            "--out-color FILE.png, --out-geojson FILE, --out-svg FILE, or --at X,Y (topocut segment --help)\n";
  if (!out.labels.empty()) text << "wrote labels:  " << name(out.labels) << " (16-bit PNG, 0 = no room, rooms 1.." << rooms << ")\n";
  if (!out.color.empty()) text << "wrote overlay: " << name(out.color) << "\n";
  if (!out.json.empty()) text << "wrote JSON:    " << name(out.json) << "\n";
  if (!out.svg.empty()) text << "wrote SVG:     " << name(out.svg) << "\n";
  if (!out.geojson.empty()) text << "wrote GeoJSON: " << name(out.geojson) << "\n";
  if (!out.clean.empty()) text << "wrote cleaned map: " << name(out.clean) << "\n";
  return text.str();
}

// One line per --at point: the room holding it, or none.
std::string rooms_at(const std::vector<QueryPoint>& points, const GridSegmentation& result) {
  std::string text;
  for (const QueryPoint& q : points) {
    const int id = room_at(result, q.point);
    text += "at " + terminal_text(q.text) + ": " + (id > 0 ? "room " + std::to_string(id) : std::string("none")) + "\n";
  }
  return text;
}

int run(const std::vector<std::string>& args) {
  const std::optional<Request> request = parse_request(args);
  if (!request) return 0;
  const auto start = std::chrono::steady_clock::now();
  std::string palette;
  const OccupancyGrid grid = load_map(request->map_path, request->load, &palette);
  const auto loaded = std::chrono::steady_clock::now();
  SegmentationInput input;
  // The array API's call, in the file's frame (an image's rows are top-down; load_map ignores yaw).
  const GridSegmentation result =
      segment_grid(grid, GridFrame{}, request->options, request->out.clean.empty() ? nullptr : &input);
  const auto done = std::chrono::steady_clock::now();
  write_outputs(request->out, grid, result, input);
  const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  std::cout << summary(*request, grid, result.segmentation, palette, {ms(start, loaded), ms(loaded, done)})
            << rooms_at(request->at, result) << std::flush;
  return 0;
}

const bool registered = register_command({"segment", "segment a map into rooms (labels, overlay, JSON, SVG)", &run});

}  // namespace
}  // namespace topocut::cli
