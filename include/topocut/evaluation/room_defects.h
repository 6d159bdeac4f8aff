#pragma once
// Judging a segmentation without ground truth: rooms no person would draw. A 'thin' room (at least
// thin_min_area, yet less than thin_share of it survives a morphological opening with a disc of
// thin_disc diameter) is a laser-ray fan, a sliver along a wall or a strip; a 'speck' room
// (speck_min_area to speck_max_area) is a scrap of free space; an 'open' room (at least open_min_area)
// has an outline that runs mostly into never-seen cells rather than walls: a ray fan through a window
// or door, a scrap outside the building. DESIGN.md, "Beyond Bormann".
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

struct DefectOptions {
  double thin_min_area = 1.0;   // m²
  double thin_disc = 0.6;       // m, diameter of the opening's disc
  double thin_share = 0.5;      // a room is thin when less than this share survives the opening
  double speck_min_area = 0.1;  // m²
  double speck_max_area = 1.0;  // m² (exclusive)
  // Open rooms, by the same rule that joins them in segmentation (open_rooms.h); its enabled flag is not
  // read here.
  OpenRoomOptions open;
};

struct RoomDefects {
  int rooms = 0;   // distinct labels > 0
  int thin = 0;
  int specks = 0;
  int open = 0;
  // Rooms bounded mostly by never-seen cells: more than open.share of the outline against walls and
  // never-seen space runs into never-seen space, ragged or not (a room seen only through an opening);
  // counted beside the defects, not among them.
  int unseen = 0;
  int flagged = 0;           // rooms with at least one defect (a ray fan is often thin and open)
  bool open_judged = true;   // false when the grid has no occupied cell: open rooms are not counted
};

// Counts the rooms and their defects in a label image (single-channel integers, 0 = no room, the
// grid's size) of grid; open rooms by their outline (room_outline()), floor as there, and, with the
// floor given, rooms whose floor touches no other room's and is less than open.floor_share of their
// cells (the rest rays: a fan seen through an opening), as open_rooms.h joins them. The disc is
// 2 * round(thin_disc / 2 / resolution) + 1 cells across. Throws Error on a bad image, size or resolution.
RoomDefects count_room_defects(const cv::Mat& labels, const OccupancyGrid& grid, const DefectOptions& options = {},
                               const cv::Mat& floor = cv::Mat());

// A map of a folder without ground truth.
struct MapFile {
  std::string name;  // file name without its folder
  std::string path;
};

// The maps of a folder: every ROS map_server YAML, and every image (png, pgm, ppm, jpg, jpeg, bmp,
// tif, tiff) that no YAML of the folder names and that is no ground truth (*_gt_segmentation.*),
// sorted by name. Throws Error if the folder does not exist or holds no map.
std::vector<MapFile> discover_map_files(const std::string& folder);

struct MapDefectResult {
  std::string map;
  bool ok = false;
  std::string error;
  int width = 0, height = 0;
  RoomDefects defects;
  double time_ms = 0.0;   // load + segment, the whole job
  double floor_ms = 0.0;  // the contour floor of the same image (0 when not measured)
  double load_ms = 0.0;   // of time_ms, loading the map
  SegmentTimes stages;    // of time_ms, segment()'s stages
};

struct MapFolderOptions {
  SegmentOptions segment;
  MapLoadOptions load;    // plain images use load.resolution
  DefectOptions defects;
  int floor_repetitions = 0;  // 0: do not measure the contour floor
  ClockMs clock = wall_clock_ms;  // what the times are read from (the floor's too)
  std::function<void(const std::string&)> progress;  // one line per map; may be empty
};

// floor_repetitions as an option (option_table.h); a front end may start from another default.
const std::vector<OptionRow<MapFolderOptions>>& map_folder_option_rows();

// Segments every map (load + segment timed together, and each stage), counts its defects and, if asked,
// measures its contour floor. A map that fails becomes a failed result; never throws for a single map.
std::vector<MapDefectResult> run_map_files(const std::vector<MapFile>& maps, const MapFolderOptions& options);

// The least work any contour-based segmenter must do on an image file, in milliseconds (median of
// repetitions, read from clock): decode it as grey, threshold at free_min, cv::findContours. A YAML's
// image is used for a YAML. Throws Error if the image cannot be read.
double contour_floor_ms(const std::string& path, int free_min, int repetitions, ClockMs clock = wall_clock_ms);

// The defects of every map that succeeded, added up (open_judged: on every one of them).
RoomDefects total_defects(const std::vector<MapDefectResult>& results);

// The share of rooms with at least one defect (0 without rooms).
double flagged_share(const RoomDefects& defects);

// The per-map table (Markdown) and the totals line: map, size, rooms, thin, specks, open, ms, floor,
// ratio; the totals give the share of rooms with at least one defect. Open shows "-" on a map where
// it was not judged.
std::string format_defects_table(const std::vector<MapDefectResult>& results);

// CSV: map,width,height,rooms,thin,specks,open,time_ms,floor_ms (a failed map leaves the numbers empty,
// a map where open rooms were not judged leaves open empty).
std::string defects_csv(const std::vector<MapDefectResult>& results);

}  // namespace topocut
