#include "topocut/segmentation/open_rooms.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "segmentation/merging/window_outline.h"
#include "topocut/core/error.h"
#include "topocut/map/building_inside.h"
#include "topocut/map/label_runs.h"
#include "topocut/map/rasterize.h"
#include "topocut/map/room_outline.h"
#include "topocut/segmentation/room_merging.h"

namespace topocut {

void validate(const OpenRoomOptions& options) { check_option_rows(open_room_option_rows(), options); }

bool holds_rays(const Room& room, const OpenRoomOptions& options) {
  return room.labelled_area - room.area >= options.fan_ray_share * room.labelled_area;
}

namespace {

// The cells the labelling (rooms_from_pieces(): free cells of no room take the nearest room along free
// space) gives room id, estimated in the window of its extent grown on each side by its longer side:
// its own cells and the free cells of no room (rays the cleaning removed) nearest to it along the free
// space of the window. The pass costs the window, not the grid (the labelling's pass over the whole
// grid cost lab_b 1.3 times the segmentation's instructions); rays farther out are not counted. share:
// with fewer free cells of no room in the window than would make it mostly rays, none is completed.
long long labelled_cells(const LabelRuns& ids, int id, const RoomExtent& extent, const cv::Mat& cells, double share) {
  const int margin = std::max(extent.box.width, extent.box.height);
  const cv::Rect window = cv::Rect(extent.box.x - margin, extent.box.y - margin, extent.box.width + 2 * margin,
                                   extent.box.height + 2 * margin) & cv::Rect(0, 0, cells.cols, cells.rows);
  cv::Mat labels(window.size(), CV_32SC1, cv::Scalar(0));
  std::vector<int> unlabelled;
  for (int wr = 0; wr < window.height; ++wr) {
    int* label = labels.ptr<int>(wr);
    for (const LabelRun& run : ids.row(window.y + wr)) {
      const int begin = std::max(run.begin, window.x), end = std::min(run.end, window.x + window.width);
      if (begin < end) std::fill(label + begin - window.x, label + end - window.x, run.label);
    }
    const unsigned char* cell = cells.ptr<unsigned char>(window.y + wr) + window.x;
    for (int wc = 0; wc < window.width; ++wc)
      if (cell[wc] == kFree && label[wc] == 0) unlabelled.push_back(wr * window.width + wc);
  }
  // Given every one of them, the room would still not be mostly rays: no completion needed.
  if (static_cast<double>(extent.cells) >= share * static_cast<double>(extent.cells + static_cast<long long>(unlabelled.size())))
    return extent.cells;
  long long given = 0;
  if (!unlabelled.empty()) {
    std::vector<LabelChange> changes;
    complete_unlabelled_cells(labels, cells(window) == kFree, unlabelled, &changes);
    for (const LabelChange& change : changes) given += change.after == id;
  }
  return extent.cells + given;
}

int root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
  return i;
}

// The rooms after the joins: each group of pieces as their union (or as the pieces, if they do not
// form one polygon).
PieceSet joined(const PieceSet& rooms, std::vector<int>& parent, const std::vector<bool>& dropped) {
  std::vector<std::vector<int>> groups(rooms.pieces.size());
  for (std::size_t i = 0; i < rooms.pieces.size(); ++i)
    if (!dropped[i]) groups[static_cast<std::size_t>(root(parent, static_cast<int>(i)))].push_back(static_cast<int>(i));
  PieceSet out;
  out.cuts = rooms.cuts;
  out.rules = rooms.rules;
  for (const std::vector<int>& group : groups) {
    if (group.empty()) continue;
    std::vector<PolygonWithHoles> parts;
    for (const int i : group) parts.push_back(rooms.pieces[static_cast<std::size_t>(i)]);
    if (parts.size() > 1) {
      try {
        out.pieces.push_back(union_of_pieces(parts));
        continue;
      } catch (const Error&) {
      }
    }
    out.pieces.insert(out.pieces.end(), parts.begin(), parts.end());
  }
  return out;
}

// join_open_rooms() with the rooms' spans if given (else rasterized here, only when needed).
PieceSet join_open_rooms(const PieceSet& rooms, const OccupancyGrid& grid, const OpenRoomOptions& options,
                         const std::vector<CellSpan>* spans) {
  validate(options);
  if (!options.enabled || rooms.pieces.empty() || !has_occupied_cell(grid.cells)) return rooms;
  const LabelRuns ids = spans ? polygon_label_runs(*spans, grid.cells.size()) : polygon_label_runs(rooms.pieces, grid.cells.size());
  const cv::Mat walls = wall_cells(grid.cells, options.wall_reach / grid.resolution + 1e-9);
  const double cell_area = grid.resolution * grid.resolution;
  std::vector<int> parent(rooms.pieces.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<bool> dropped(rooms.pieces.size(), false);
  bool changed = false;
  const auto extents = room_extents(ids);
  long long largest = 0;
  for (const auto& [id, extent] : extents) largest = std::max(largest, static_cast<long long>(extent.cells));
  // Mostly rays: less than floor_share of the cells the labelling gives the room are its own.
  const auto mostly_rays = [&](int id, const RoomExtent& extent) {
    return options.floor_share > 0.0 &&
           static_cast<double>(extent.cells) < options.floor_share * static_cast<double>(labelled_cells(ids, id, extent, grid.cells, options.floor_share));
  };
  for (const auto& [id, extent] : extents) {
    if (static_cast<double>(extent.cells) * cell_area < options.min_area) continue;
    const RoomOutline outline = room_outline(ids, id, extent.box, grid.cells, walls, static_cast<int>(std::lround(options.wall_band / grid.resolution)));
    const bool open = outline.open(options.share, options.ragged_share);
    if (outline.neighbours.empty()) {
      // Nothing beside it: free space seen through a gap, or the dense core of a fan of rays through
      // one (beyond a wall, outside the building), unless it is the building itself (the map's largest
      // room, or as large as half of it: a map explored so far).
      if (2 * extent.cells < largest && (open || mostly_rays(id, extent))) dropped[static_cast<std::size_t>(id - 1)] = changed = true;
      continue;
    }
    if (!open) continue;
    int into = 0;
    long long longest = 0;
    for (const auto& [other, edges] : outline.neighbours) {
      if (edges > longest) std::tie(into, longest) = std::pair{other, edges};
    }
    const int a = root(parent, id - 1), b = root(parent, into - 1);
    parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    changed = true;
  }
  return changed ? joined(rooms, parent, dropped) : rooms;
}

// The bounding box of the cells of each room whose flag is set (index: the room's id), in one pass;
// throws Error on a label outside [0, flagged.size()). (A room's floor may lie far beyond its polygon:
// the floor of a piece the open-rooms row left out goes to the nearest room.)
std::vector<cv::Rect> flagged_boxes(const cv::Mat& labels, const std::vector<char>& flagged) {
  std::vector<cv::Rect> boxes(flagged.size());
  for (int r = 0; r < labels.rows; ++r) {
    const int* label = labels.ptr<int>(r);
    for (int c = 0; c < labels.cols;) {
      const std::size_t id = static_cast<std::size_t>(label[c]);  // a negative label wraps round to a large one
      if (id >= flagged.size()) throw Error("leave_out_fans: a label is no room of the segmentation");
      const int end = run_end(label, c, labels.cols, label[c]);
      if (flagged[id]) boxes[id] |= cv::Rect(c, r, end - c, 1);
      c = end;
    }
  }
  return boxes;
}

// Whether each of segmentation's rooms (index: its id) is a fan (leave_out_fans()), and in boxes the
// bounding box of each room judged. The rays are read off the rooms' areas, so that a map whose rooms
// hold none costs no pass over the grid; the outlines only when some room holds rays enough, each read
// in a window around its room.
std::vector<char> fan_rooms(const Segmentation& segmentation, const OccupancyGrid& grid, const cv::Mat& floor,
                            const OpenRoomOptions& options, std::vector<cv::Rect>& boxes) {
  const cv::Mat& labels = segmentation.labels;
  std::vector<char> candidate(segmentation.rooms.size() + 1, 0), fan(segmentation.rooms.size() + 1, 0);
  double largest = 0.0;
  for (const Room& room : segmentation.rooms) {
    largest = std::max(largest, room.labelled_area);
    candidate[static_cast<std::size_t>(room.id)] =
        room.labelled_area >= options.min_area && holds_rays(room, options);
  }
  if (std::find(candidate.begin(), candidate.end(), 1) == candidate.end()) return fan;
  boxes = flagged_boxes(labels, candidate);
  for (const Room& room : segmentation.rooms) {
    if (!candidate[static_cast<std::size_t>(room.id)]) continue;
    const cv::Rect window = outline_window(boxes[static_cast<std::size_t>(room.id)], labels.size(), grid.resolution, options);
    cv::Mat on_floor(window.size(), CV_32SC1, cv::Scalar(0));
    labels(window).copyTo(on_floor, floor(window));
    const std::optional<RoomOutline> outline = window_outline(on_floor, room.id, grid.cells(window), grid.resolution, options);
    if (!outline) continue;  // no floor: no outline to judge
    fan[static_cast<std::size_t>(room.id)] =
        outline->open(options.share, options.ragged_share) && (!outline->neighbours.empty() || 2.0 * room.labelled_area < largest);
  }
  return fan;
}

// Clears the flag of every fan (index: its id; box: its cells' bounding box) with more than share of
// its floor cells inside the building (building_inside(), walls closed across closing metres): a walled
// room (a hall, a small room by the front door) that holds a fan seen through its door is still a room.
void keep_walled_in(std::vector<char>& fan, const std::vector<cv::Rect>& box, const cv::Mat& labels, const OccupancyGrid& grid,
                    const cv::Mat& floor, double share, double closing, BuildingInside& building) {
  if (share >= 1.0) return;
  const cv::Mat& inside = building.at(closing / grid.resolution);
  for (std::size_t id = 1; id < fan.size(); ++id) {
    if (!fan[id]) continue;
    const cv::Mat room = (labels(box[id]) == static_cast<int>(id)) & floor(box[id]);
    const long long all = cv::countNonZero(room);
    fan[id] = static_cast<double>(cv::countNonZero(room & inside(box[id]))) <= share * static_cast<double>(all);
  }
}

}  // namespace

void leave_out_fans(Segmentation& segmentation, const OccupancyGrid& grid, const cv::Mat& floor, const OpenRoomOptions& options,
                    BuildingInside* inside) {
  validate(options);
  if (!options.enabled || options.fan_ray_share <= 0.0 || segmentation.rooms.empty() || !has_occupied_cell(grid.cells)) return;
  check_labelled(segmentation, grid, floor, "leave_out_fans");
  std::vector<cv::Rect> boxes;
  std::vector<char> fan = fan_rooms(segmentation, grid, floor, options, boxes);
  if (std::find(fan.begin(), fan.end(), 1) == fan.end()) return;
  BuildingInside own(grid.cells);
  keep_walled_in(fan, boxes, segmentation.labels, grid, floor, options.fan_inside_share, options.fan_closing, inside ? *inside : own);
  if (std::find(fan.begin(), fan.end(), 1) == fan.end()) return;
  std::vector<int> new_id(fan.size(), 0);
  std::vector<Room> rooms;
  for (Room& room : segmentation.rooms) {
    if (fan[static_cast<std::size_t>(room.id)]) continue;
    const int id = static_cast<int>(rooms.size()) + 1;
    new_id[static_cast<std::size_t>(room.id)] = id;
    room.id = id;
    rooms.push_back(std::move(room));
  }
  segmentation.rooms = std::move(rooms);
  for (int r = 0; r < segmentation.labels.rows; ++r) {  // every label checked by fan_rooms()
    int* label = segmentation.labels.ptr<int>(r);
    for (int c = 0; c < segmentation.labels.cols;) {
      const int end = run_end(label, c, segmentation.labels.cols, label[c]);
      std::fill(label + c, label + end, new_id[static_cast<std::size_t>(label[c])]);
      c = end;
    }
  }
  std::erase_if(segmentation.passages, [&](Passage& p) {
    p.room_a = new_id[static_cast<std::size_t>(p.room_a)];
    p.room_b = new_id[static_cast<std::size_t>(p.room_b)];
    return p.room_a == 0 || p.room_b == 0;
  });
}

cv::Rect outline_window(const cv::Rect& box, const cv::Size& size, double resolution, const OpenRoomOptions& options) {
  const int band = static_cast<int>(std::lround(options.wall_band / resolution));
  const int margin = band + static_cast<int>(std::ceil(options.wall_reach / resolution)) + 3;
  return cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) & cv::Rect(cv::Point(0, 0), size);
}

std::optional<RoomOutline> window_outline(const cv::Mat& labels, int id, const cv::Mat& cells, double resolution,
                                          const OpenRoomOptions& options) {
  const LabelRuns runs = label_runs(labels);
  const std::map<int, RoomExtent> extents = room_extents(runs);
  const auto extent = extents.find(id);
  if (extent == extents.end()) return std::nullopt;
  const int band = static_cast<int>(std::lround(options.wall_band / resolution));
  return room_outline(runs, id, extent->second.box, cells, wall_cells(cells, options.wall_reach / resolution + 1e-9), band);
}

void check_labelled(const Segmentation& segmentation, const OccupancyGrid& grid, const cv::Mat& floor, const char* caller) {
  const cv::Mat& labels = segmentation.labels;
  const std::string name = caller;
  if (labels.type() != CV_32SC1 || floor.type() != CV_8UC1) throw Error(name + ": the labels must be CV_32SC1, the floor CV_8UC1");
  if (floor.size() != labels.size() || grid.cells.size() != labels.size())
    throw Error(name + ": the labels, the floor and the grid differ in size");
  for (std::size_t k = 0; k < segmentation.rooms.size(); ++k)
    if (segmentation.rooms[k].id != static_cast<int>(k) + 1) throw Error(name + ": the rooms are not numbered 1..N in order");
}

PieceSet join_open_rooms(const PieceSet& rooms, const OccupancyGrid& grid, const OpenRoomOptions& options) {
  return join_open_rooms(rooms, grid, options, nullptr);
}

PieceSet join_open_rooms(const PieceSet& rooms, const OccupancyGrid& grid, const OpenRoomOptions& options,
                         const std::vector<CellSpan>& spans) {
  return join_open_rooms(rooms, grid, options, &spans);
}

}  // namespace topocut
