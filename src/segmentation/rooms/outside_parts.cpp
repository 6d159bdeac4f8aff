#include "topocut/segmentation/outside_parts.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "segmentation/merging/window_outline.h"
#include "topocut/core/error.h"
#include "topocut/map/building_inside.h"
#include "topocut/map/cell_components.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/map/label_runs.h"

namespace topocut {

namespace {

// What one pass over the labels counts per room.
struct RoomTally {
  long long floor = 0;         // floor cells
  long long floor_inside = 0;  // of those, inside the building
  long long outside = 0;       // cells outside
  cv::Rect box;                // of all its cells
  cv::Rect outside_box;        // of its cells outside
};

// Grows box by the cells [c0, c1) of row r; an empty box becomes them.
void add_run(cv::Rect& box, int c0, int c1, int r) {
  if (box.empty()) {
    box = cv::Rect(c0, r, c1 - c0, 1);
    return;
  }
  box |= cv::Rect(c0, r, c1 - c0, 1);
}

// Per room (index: its id; rooms: the number of rooms, every label checked against it), run by run.
std::vector<RoomTally> tally_rooms(const cv::Mat& labels, const cv::Mat& floor, const cv::Mat& inside, std::size_t rooms) {
  std::vector<RoomTally> tally(rooms + 1);
  for (int r = 0; r < labels.rows; ++r) {
    const int* label = labels.ptr<int>(r);
    const unsigned char* on_floor = floor.ptr<unsigned char>(r);
    const unsigned char* in = inside.ptr<unsigned char>(r);
    for (int c = 0; c < labels.cols;) {
      const int id = label[c];
      const int end = run_end(label, c, labels.cols, id);
      if (id < 0 || static_cast<std::size_t>(id) > rooms) throw Error("leave_out_outside_parts: a label is no room of the segmentation");
      if (id == 0) {
        c = end;
        continue;
      }
      RoomTally& t = tally[static_cast<std::size_t>(id)];
      add_run(t.box, c, end, r);
      int first_out = -1, last_out = -1;
      for (int k = c; k < end; ++k) {
        if (on_floor[k]) {
          ++t.floor;
          t.floor_inside += in[k] != 0;
        }
        if (in[k]) continue;
        ++t.outside;
        if (first_out < 0) first_out = k;
        last_out = k;
      }
      if (first_out >= 0) add_run(t.outside_box, first_out, last_out + 1, r);
      c = end;
    }
  }
  return tally;
}

// Whether the room's floor outside (outside true; box: its cells there) or inside is open as open rooms
// are (room_outline(): its outline mostly against never-seen cells, those edges ragged), the room's other
// floor and the other rooms' floor its neighbours.
bool part_open(int id, bool outside, const cv::Rect& box, const cv::Mat& labels, const cv::Mat& floor, const cv::Mat& inside,
               const OccupancyGrid& grid, const OpenRoomOptions& options) {
  const cv::Rect window = outline_window(box, labels.size(), grid.resolution, options);
  constexpr int kPart = 1, kOther = 2;
  cv::Mat parts(window.size(), CV_32SC1, cv::Scalar(0));
  for (int r = 0; r < window.height; ++r) {
    const int* label = labels.ptr<int>(window.y + r) + window.x;
    const unsigned char* on_floor = floor.ptr<unsigned char>(window.y + r) + window.x;
    const unsigned char* in = inside.ptr<unsigned char>(window.y + r) + window.x;
    int* part = parts.ptr<int>(r);
    for (int c = 0; c < window.width; ++c)
      if (on_floor[c] && label[c] != 0) part[c] = label[c] == id && (in[c] == 0) == outside ? kPart : kOther;
  }
  const std::optional<RoomOutline> outline = window_outline(parts, kPart, grid.cells(window), grid.resolution, options);
  return outline && outline->open(options.share, options.ragged_share);  // none of its floor there: not open
}

// Whether the room is cut back: it holds rays, has cells outside, more than fan_inside_share of its floor
// inside, its floor outside is open (a fan seen through a window ends in rays, while a floor outside
// because its walls have gaps wider than the closing is walled along the rest), and its floor inside is
// not (the walled room; where the closing encloses the far end of a fan against a wall far out and a
// gap wider than it lets the outside into the room, the part inside is that fan's end).
bool cut_back(const Room& room, const RoomTally& t, const cv::Mat& labels, const cv::Mat& floor, const cv::Mat& inside,
              const OccupancyGrid& grid, const OpenRoomOptions& options) {
  return holds_rays(room, options) && t.outside > 0 &&
         static_cast<double>(t.floor_inside) > options.fan_inside_share * static_cast<double>(t.floor) &&
         part_open(room.id, true, t.outside_box, labels, floor, inside, grid, options) &&
         !part_open(room.id, false, t.box, labels, floor, inside, grid, options);
}

// Whether some room without rays lies mostly outside: then the map's walls do not enclose its rooms
// (a plan whose outer walls are drawn as the never-seen grey around it: Bormann's lab_ipa, its octagon
// hall and the corridor to it), and outside tells no fan.
bool rooms_outside(const Segmentation& segmentation, const std::vector<RoomTally>& tally, const OpenRoomOptions& options) {
  return std::any_of(segmentation.rooms.begin(), segmentation.rooms.end(), [&](const Room& room) {
    const RoomTally& t = tally[static_cast<std::size_t>(room.id)];
    return room.labelled_area >= options.min_area && room.labelled_area <= room.area && 2 * t.floor_inside < t.floor;
  });
}

// A ring traced in a window of the grid (x = the window's column, y up from its bottom row), in world metres.
Ring window_ring_to_world(const Ring& ring, const OccupancyGrid& grid, const cv::Rect& window) {
  const double shift_y = static_cast<double>(grid.height() - window.y - window.height);
  Ring world;
  world.reserve(ring.size());
  for (const Point2& p : ring) world.push_back(grid_to_world(grid, {p.x + window.x, p.y + shift_y}));
  return world;
}

// The largest part of room id's floor cells in box, traced along the cells' edges (as the live path
// traces a room it redid in part): the polygon of a room cut back. fallback: when it has no floor left.
PolygonWithHoles traced_polygon(const cv::Mat& labels, const cv::Mat& floor, int id, const cv::Rect& box, const OccupancyGrid& grid,
                                const PolygonWithHoles& fallback) {
  const cv::Mat own = (labels(box) == id) & floor(box);
  if (cv::countNonZero(own) == 0) return fallback;
  ContourOptions contours;  // its holes as the free space's polygons have them (specks filled), every part
  contours.min_component_area = 0.0;
  const std::vector<FreeSpaceComponent> parts = free_space_polygons(own, grid.resolution, contours).components;
  const auto largest = std::max_element(parts.begin(), parts.end(), [](const FreeSpaceComponent& a, const FreeSpaceComponent& b) {
    return a.pixel_count < b.pixel_count;
  });
  if (largest == parts.end()) return fallback;
  PolygonWithHoles world{window_ring_to_world(largest->polygon.outer, grid, box), {}};
  for (const Ring& hole : largest->polygon.holes) world.holes.push_back(window_ring_to_world(hole, grid, box));
  return normalized_orientation(world);
}

// Clears the room's cells in box that lie outside, and then those of every part of it but the largest
// (8-connected) that touches a cell outside: the bits of a fan the closing enclosed against a wall far
// out. A free speck walled in inside the building, labelled with the room, stays.
void clear_outside(cv::Mat& labels, int id, cv::Rect box, const cv::Mat& inside) {
  cv::Mat room(box.size(), CV_8UC1, cv::Scalar(0));
  int top = box.height, bottom = -1, left = box.width, right = -1;  // of its cells inside, in room
  for (int r = 0; r < box.height; ++r) {
    int* label = labels.ptr<int>(box.y + r) + box.x;
    const unsigned char* in = inside.ptr<unsigned char>(box.y + r) + box.x;
    unsigned char* own = room.ptr<unsigned char>(r);
    for (int c = 0; c < box.width; ++c) {
      if (label[c] != id) continue;
      if (in[c]) {
        own[c] = 255;
        top = std::min(top, r);
        bottom = r;
        left = std::min(left, c);
        right = std::max(right, c);
      } else {
        label[c] = 0;
      }
    }
  }
  if (bottom < 0) return;
  const cv::Rect kept(left, top, right - left + 1, bottom - top + 1);
  // The parts of what is left, in its own box: the fan cut off often spans most of the room's box.
  std::vector<long long> sizes;
  const cv::Mat part = cell_components(room(kept), /*eight_connected=*/true, sizes);
  if (sizes.size() <= 1) return;
  box = cv::Rect(box.x + kept.x, box.y + kept.y, kept.width, kept.height);
  const int largest = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin()) + 1;  // the first of equals
  // The parts touching a cell outside: an outside cell's 8 neighbours, the box grown by one.
  const cv::Rect grown = cv::Rect(box.x - 1, box.y - 1, box.width + 2, box.height + 2) & cv::Rect(0, 0, labels.cols, labels.rows);
  std::vector<char> touches(sizes.size() + 1, 0);
  for (int r = 0; r < box.height; ++r)
    for (int c = 0; c < box.width; ++c) {
      const int k = part.at<int>(r, c);
      if (k == 0 || k == largest || touches[static_cast<std::size_t>(k)]) continue;
      for (int dr = -1; dr <= 1 && !touches[static_cast<std::size_t>(k)]; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const cv::Point q(box.x + c + dc, box.y + r + dr);
          if (grown.contains(q) && inside.at<unsigned char>(q) == 0) {
            touches[static_cast<std::size_t>(k)] = 1;
            break;
          }
        }
    }
  for (int r = 0; r < box.height; ++r) {
    int* label = labels.ptr<int>(box.y + r) + box.x;
    for (int c = 0; c < box.width; ++c)
      if (touches[static_cast<std::size_t>(part.at<int>(r, c))]) label[c] = 0;
  }
}

// The room's labelled area and centroid from its cells in box.
void recount(Room& room, const cv::Mat& labels, const cv::Rect& box, const OccupancyGrid& grid) {
  long long cells = 0;
  double sum_c = 0.0, sum_r = 0.0;
  for (int r = box.y; r < box.y + box.height; ++r) {
    const int* label = labels.ptr<int>(r);
    for (int c = box.x; c < box.x + box.width; ++c)
      if (label[c] == room.id) {
        ++cells;
        sum_c += c;
        sum_r += r;
      }
  }
  if (cells == 0) return;  // more than fan_inside_share of its floor is inside: never so
  room.labelled_area = static_cast<double>(cells) * grid.resolution * grid.resolution;
  room.centroid = cell_center_world(grid, 0, 0) + Point2{sum_c / static_cast<double>(cells) * grid.resolution,
                                                         -sum_r / static_cast<double>(cells) * grid.resolution};
}

// Whether the cut's middle lies in a cell outside the building (or off the grid).
bool middle_outside(const Passage& passage, const OccupancyGrid& grid, const cv::Mat& inside) {
  const cv::Point cell = world_to_cell(grid, 0.5 * (passage.cut.a + passage.cut.b));
  if (cell.x < 0 || cell.y < 0 || cell.x >= inside.cols || cell.y >= inside.rows) return true;
  return inside.at<unsigned char>(cell) == 0;
}

}  // namespace

void leave_out_outside_parts(Segmentation& segmentation, const OccupancyGrid& grid, const cv::Mat& floor, const OpenRoomOptions& options,
                             BuildingInside* building) {
  validate(options);
  if (!options.enabled || options.fan_ray_share <= 0.0 || !options.cut_outside_parts || segmentation.rooms.empty() ||
      !has_occupied_cell(grid.cells))
    return;
  check_labelled(segmentation, grid, floor, "leave_out_outside_parts");
  const auto rays = [&](const Room& room) { return holds_rays(room, options); };
  if (std::none_of(segmentation.rooms.begin(), segmentation.rooms.end(), rays)) return;  // a drawn plan: no pass over the grid
  BuildingInside own(grid.cells);
  const cv::Mat& inside = (building ? *building : own).at(options.fan_closing / grid.resolution);
  const std::vector<RoomTally> tally = tally_rooms(segmentation.labels, floor, inside, segmentation.rooms.size());
  if (rooms_outside(segmentation, tally, options)) return;
  std::vector<char> cut(segmentation.rooms.size() + 1, 0);  // every room judged on the labels as they came
  for (const Room& room : segmentation.rooms)
    cut[static_cast<std::size_t>(room.id)] = cut_back(room, tally[static_cast<std::size_t>(room.id)], segmentation.labels, floor, inside, grid, options);
  for (Room& room : segmentation.rooms) {
    if (!cut[static_cast<std::size_t>(room.id)]) continue;
    const RoomTally& t = tally[static_cast<std::size_t>(room.id)];
    clear_outside(segmentation.labels, room.id, t.box, inside);
    room.polygon = traced_polygon(segmentation.labels, floor, room.id, t.box, grid, room.polygon);
    room.area = area(room.polygon);
    recount(room, segmentation.labels, t.box, grid);
  }
  std::erase_if(segmentation.passages, [&](const Passage& p) {
    return (cut[static_cast<std::size_t>(p.room_a)] || cut[static_cast<std::size_t>(p.room_b)]) && middle_outside(p, grid, inside);
  });
}

}  // namespace topocut
