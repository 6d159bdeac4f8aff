#include "topocut/segmentation/open_rooms.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include "topocut/core/error.h"
#include "topocut/map/label_runs.h"
#include "topocut/map/room_outline.h"
#include "topocut/segmentation/room_merging.h"

namespace topocut {

void validate(const OpenRoomOptions& options) { check_option_rows(open_room_option_rows(), options); }

namespace {

// Whether any cell is occupied; stops at the first one.
bool has_occupied_cell(const cv::Mat& cells) {
  for (int r = 0; r < cells.rows; ++r) {
    const unsigned char* row = cells.ptr<unsigned char>(r);
    if (std::memchr(row, kOccupied, static_cast<std::size_t>(cells.cols)) != nullptr) return true;
  }
  return false;
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

}  // namespace

PieceSet join_open_rooms(const PieceSet& rooms, const OccupancyGrid& grid, const OpenRoomOptions& options) {
  validate(options);
  if (!options.enabled || rooms.pieces.empty() || !has_occupied_cell(grid.cells)) return rooms;
  const LabelRuns ids = polygon_label_runs(rooms.pieces, grid.cells.size());
  const cv::Mat walls = wall_cells(grid.cells, options.wall_reach / grid.resolution + 1e-9);
  const double cell_area = grid.resolution * grid.resolution;
  std::vector<int> parent(rooms.pieces.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<bool> dropped(rooms.pieces.size(), false);
  bool changed = false;
  const auto extents = room_extents(ids);
  long long largest = 0;
  for (const auto& [id, extent] : extents) largest = std::max(largest, static_cast<long long>(extent.cells));
  for (const auto& [id, extent] : extents) {
    if (static_cast<double>(extent.cells) * cell_area < options.min_area) continue;
    const RoomOutline outline = room_outline(ids, id, extent.box, grid.cells, walls, static_cast<int>(std::lround(options.wall_band / grid.resolution)));
    if (!outline.open(options.share, options.ragged_share)) continue;
    int into = 0;
    long long longest = 0;
    for (const auto& [other, edges] : outline.neighbours) {
      if (edges > longest) std::tie(into, longest) = std::pair{other, edges};
    }
    if (into == 0) {
      // Nothing beside it: free space seen through a gap, outside the building, unless it is the
      // building itself (the map's largest room, or as large as half of it: a map explored so far).
      if (2 * static_cast<long long>(extent.cells) < largest) dropped[static_cast<std::size_t>(id - 1)] = changed = true;
      continue;
    }
    const int a = root(parent, id - 1), b = root(parent, into - 1);
    parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    changed = true;
  }
  return changed ? joined(rooms, parent, dropped) : rooms;
}

}  // namespace topocut
