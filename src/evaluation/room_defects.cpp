#include "topocut/evaluation/room_defects.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/io/image_input.h"
#include "topocut/map/room_outline.h"

namespace topocut {

const std::vector<OptionRow<MapFolderOptions>>& map_folder_option_rows() {
  static const std::vector<OptionRow<MapFolderOptions>> rows = {
      field_row("floor-repetitions", "N", OptionRange::kWholeNumber, &MapFolderOptions::floor_repetitions,
                "repetitions of the contour floor (decode, threshold, findContours) per map, median taken; 0: not measured"),
  };
  return rows;
}

namespace fs = std::filesystem;

namespace {

// Cells of the room that survive an opening with the disc, computed in a window around the room.
long long opened_cells(const cv::Mat& labels, int id, const cv::Rect& box, const cv::Mat& disc) {
  const int pad = disc.cols;
  const cv::Rect window = cv::Rect(box.x - pad, box.y - pad, box.width + 2 * pad, box.height + 2 * pad) &
                          cv::Rect(0, 0, labels.cols, labels.rows);
  cv::Mat room = labels(window) == id, opened;
  cv::morphologyEx(room, opened, cv::MORPH_OPEN, disc, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  return cv::countNonZero(opened);
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool is_image_name(const std::string& name) {
  static const std::set<std::string> extensions{".png", ".pgm", ".ppm", ".jpg", ".jpeg", ".bmp", ".tif", ".tiff"};
  return extensions.count(lower(fs::path(name).extension().string())) > 0;
}

MapDefectResult run_one(const MapFile& map, const MapFolderOptions& options) {
  MapDefectResult result;
  result.map = map.name;
  try {
    const double start = options.clock();
    const OccupancyGrid grid = load_map(map.path, options.load);
    result.load_ms = options.clock() - start;
    result.stages.clock = options.clock;
    const Segmentation segmentation = segment(grid, options.segment, nullptr, &result.stages);
    result.time_ms = options.clock() - start;
    result.width = grid.width();
    result.height = grid.height();
    // The free space the rooms were made of, outside the timing.
    result.defects = count_room_defects(segmentation.labels, grid, options.defects, segmentation_input(grid, options.segment).floor);
    if (options.floor_repetitions > 0)
      result.floor_ms = contour_floor_ms(map.path, options.load.free_min, options.floor_repetitions, options.clock);
    result.ok = true;
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  return result;
}

}  // namespace

RoomDefects count_room_defects(const cv::Mat& labels, const OccupancyGrid& grid, const DefectOptions& options,
                               const cv::Mat& floor) {
  if (labels.empty() || labels.channels() != 1) throw Error("the label image must be a non-empty single-channel image");
  const double resolution = grid.resolution;
  if (!std::isfinite(resolution) || resolution <= 0.0) throw Error("the resolution must be a positive number of metres");
  if (grid.cells.type() != CV_8UC1 || grid.cells.size() != labels.size())
    throw Error("the label image and the grid differ in size");
  cv::Mat ids;
  labels.convertTo(ids, CV_32S);
  const double cell_area = resolution * resolution;
  // A disc wider than the map fits in no room: clamped there, the same answer without its square.
  const int radius = static_cast<int>(std::min(std::round(options.thin_disc / 2.0 / resolution), double(std::max(labels.cols, labels.rows))));
  const cv::Mat disc = cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * radius + 1, 2 * radius + 1});
  RoomDefects defects;
  // Without a single occupied cell (walls drawn in the unknown grey) walls and never-seen space
  // cannot be told apart, so no room is called open.
  defects.open_judged = cv::countNonZero(grid.cells == kOccupied) > 0;
  // The tolerance keeps 0.15 m at 0.05 m per cell three cells, as it reads, despite rounding.
  const cv::Mat walls =
      defects.open_judged ? wall_cells(grid.cells, options.open.wall_reach / resolution + 1e-9) : cv::Mat();
  // With the floor given, a room's outline is that of its floor, as the open-rooms rule sees it (the
  // rays the cleaning removed and gave to a room reach past its own walls).
  cv::Mat on_floor = ids;
  if (!floor.empty()) {
    if (floor.size() != ids.size()) throw Error("the floor and the label image differ in size");
    on_floor = cv::Mat(ids.size(), CV_32SC1, cv::Scalar(0));  // a new image: assigning zeros() would clear ids
    ids.copyTo(on_floor, floor);
  }
  const int band = static_cast<int>(std::lround(options.open.wall_band / resolution));
  const LabelRuns outlines = defects.open_judged ? label_runs(on_floor) : LabelRuns();
  // Each room's floor cells: with the floor given, an island of floor that is mostly rays is open too.
  const std::map<int, RoomExtent> floors = !floor.empty() && defects.open_judged ? room_extents(outlines) : std::map<int, RoomExtent>();
  const auto mostly_rays = [&](int id, long long cells) {
    const auto it = floors.find(id);
    return options.open.floor_share > 0.0 && it != floors.end() &&
           static_cast<double>(it->second.cells) < options.open.floor_share * static_cast<double>(cells);
  };
  for (const auto& [id, room] : room_extents(label_runs(ids))) {
    ++defects.rooms;
    const double area = static_cast<double>(room.cells) * cell_area;
    const bool speck = area >= options.speck_min_area && area < options.speck_max_area;
    const bool thin = area >= options.thin_min_area && static_cast<double>(opened_cells(ids, id, room.box, disc)) <
                                                           options.thin_share * static_cast<double>(room.cells);
    bool open = false;
    if (defects.open_judged && area >= options.open.min_area) {
      const RoomOutline outline = room_outline(outlines, id, room.box, grid.cells, walls, band);
      open = outline.open(options.open.share, options.open.ragged_share) || (outline.neighbours.empty() && mostly_rays(id, room.cells));
      defects.unseen += outline.open(options.open.share, 0.0);
    }
    defects.specks += speck;
    defects.thin += thin;
    defects.open += open;
    defects.flagged += speck || thin || open;
  }
  return defects;
}

std::vector<MapFile> discover_map_files(const std::string& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw Error("map folder '" + folder + "' does not exist or is not a folder");
  std::vector<MapFile> maps;
  std::set<std::string> named_by_yaml, images;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    if (!entry.is_regular_file(ec)) continue;
    const std::string name = entry.path().filename().string();
    if (is_yaml_path(name)) {
      maps.push_back({name, entry.path().string()});
      try {
        named_by_yaml.insert(fs::path(ros_map_image_path(entry.path().string())).filename().string());
      } catch (const Error&) {
        // A broken YAML fails as a map of its own.
      }
    } else if (is_image_name(name) && name.find("_gt_segmentation.") == std::string::npos) {
      images.insert(name);
    }
  }
  for (const std::string& name : images) {
    if (!named_by_yaml.count(name)) maps.push_back({name, (fs::path(folder) / name).string()});
  }
  std::sort(maps.begin(), maps.end(), [](const MapFile& a, const MapFile& b) { return a.name < b.name; });
  if (maps.empty()) throw Error("map folder '" + folder + "' holds no map (no YAML and no image)");
  return maps;
}

std::vector<MapDefectResult> run_map_files(const std::vector<MapFile>& maps, const MapFolderOptions& options) {
  std::vector<MapDefectResult> results;
  for (std::size_t i = 0; i < maps.size(); ++i) {
    results.push_back(run_one(maps[i], options));
    const MapDefectResult& r = results.back();
    if (options.progress) {
      // Appended, not "literal" + a temporary string: GCC 12 warns falsely (-Wrestrict) on that.
      std::string line = "[";
      line += std::to_string(i + 1) + "/" + std::to_string(maps.size()) + "] " + r.map + ": ";
      line += r.ok ? std::to_string(r.defects.rooms) + " rooms, " + std::to_string(r.defects.thin) + " thin, " +
                         std::to_string(r.defects.specks) + " specks, " + std::to_string(r.defects.open) + " open, " +
                         fixed(r.time_ms, 0) + " ms"
                   : "FAILED: " + r.error;
      options.progress(line);
    }
  }
  return results;
}

namespace {

// One 8-bit channel for the floor's threshold and contours (the timed work is the same whatever
// the map's channels).
cv::Mat grey_8bit(const cv::Mat& image) {
  cv::Mat grey = image;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  if (image.channels() == 4) cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  if (grey.depth() != CV_8U) grey.convertTo(grey, CV_8U, 1.0 / 257.0);
  return grey;
}

}  // namespace

double contour_floor_ms(const std::string& path, int free_min, int repetitions, ClockMs clock) {
  const std::string image_path = is_yaml_path(path) ? ros_map_image_path(path) : path;
  std::vector<double> times;
  for (int i = 0; i < std::max(1, repetitions); ++i) {
    const double start = clock();
    const cv::Mat image = grey_8bit(read_image(image_path, "map image", ImageLimits{}));
    cv::Mat free;
    cv::threshold(image, free, free_min, 255, cv::THRESH_BINARY);
    std::vector<std::vector<cv::Point>> contours;
    std::vector<cv::Vec4i> hierarchy;
    cv::findContours(free, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
    times.push_back(clock() - start);
  }
  return time_statistics(times).median;
}

namespace {

std::string open_text(const RoomDefects& defects) {
  return defects.open_judged ? std::to_string(defects.open) : "-";
}

}  // namespace

RoomDefects total_defects(const std::vector<MapDefectResult>& results) {
  RoomDefects total;
  for (const MapDefectResult& r : results) {
    if (!r.ok) continue;
    total.rooms += r.defects.rooms;
    total.thin += r.defects.thin;
    total.specks += r.defects.specks;
    total.open += r.defects.open;
    total.unseen += r.defects.unseen;
    total.flagged += r.defects.flagged;
    total.open_judged = total.open_judged && r.defects.open_judged;
  }
  return total;
}

double flagged_share(const RoomDefects& defects) {
  return defects.rooms > 0 ? static_cast<double>(defects.flagged) / defects.rooms : 0.0;
}

std::string format_defects_table(const std::vector<MapDefectResult>& results) {
  std::vector<std::vector<std::string>> rows{
      {"map", "cells", "rooms", "thin", "specks", "open", "mostly unseen", "ms", "floor ms", "ms / floor"}};
  std::vector<double> ratios;
  int failed = 0;
  for (const MapDefectResult& r : results) {
    if (!r.ok) {
      ++failed;
      rows.push_back({r.map, "-", "-", "-", "-", "-", "-", "FAILED: " + r.error, "-", "-"});
      continue;
    }
    const bool floor = r.floor_ms > 0.0;
    if (floor) ratios.push_back(r.time_ms / r.floor_ms);
    rows.push_back({r.map, std::to_string(r.width) + " x " + std::to_string(r.height), std::to_string(r.defects.rooms),
                    std::to_string(r.defects.thin), std::to_string(r.defects.specks), open_text(r.defects),
                    r.defects.open_judged ? std::to_string(r.defects.unseen) : "-", fixed(r.time_ms, 1), floor ? fixed(r.floor_ms, 2) : "-",
                    floor ? fixed(r.time_ms / r.floor_ms, 1) : "-"});
  }
  const RoomDefects total = total_defects(results);
  std::string text = markdown_table(rows) + "\n" + std::to_string(results.size() - failed) + " maps, " +
                     std::to_string(total.rooms) + " rooms: " + std::to_string(total.thin) + " thin, " +
                     std::to_string(total.specks) + " specks, " + std::to_string(total.open) + " open (" +
                     std::to_string(total.flagged) + " rooms with a defect, " + fixed(100.0 * flagged_share(total), 1) +
                     " % of the rooms); " + std::to_string(total.unseen) + " bounded mostly by never-seen cells";
  int unjudged = 0;
  for (const MapDefectResult& r : results) unjudged += r.ok && !r.defects.open_judged;
  if (unjudged > 0) text += "; open rooms not judged on " + std::to_string(unjudged) + " map(s) without occupied cells";
  if (!ratios.empty()) {
    const TimeStatistics ratio = time_statistics(ratios);
    text += "; ms / floor median " + fixed(ratio.median, 1) + ", max " + fixed(ratio.max, 1);
  }
  if (failed > 0) {
    text += "; ";
    text += std::to_string(failed) + " failed";
  }
  return text + "\n";
}

std::string defects_csv(const std::vector<MapDefectResult>& results) {
  std::string csv = "map,width,height,rooms,thin,specks,open,time_ms,floor_ms\n";
  for (const MapDefectResult& r : results) {
    csv += csv_cell(r.map);
    if (r.ok) {
      csv += ',';
      csv += std::to_string(r.width) + "," + std::to_string(r.height) + "," + std::to_string(r.defects.rooms) + "," +
             std::to_string(r.defects.thin) + "," + std::to_string(r.defects.specks) + "," +
             (r.defects.open_judged ? std::to_string(r.defects.open) : "") + "," + fixed(r.time_ms, 3) + "," +
             (r.floor_ms > 0.0 ? fixed(r.floor_ms, 3) : "");
    } else {
      csv += ",,,,,,,,";
    }
    csv += "\n";
  }
  return csv;
}

}  // namespace topocut
