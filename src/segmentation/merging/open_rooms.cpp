#include "topocut/segmentation/open_rooms.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <optional>
#include <span>

#include "topocut/core/error.h"
#include "topocut/map/label_runs.h"
#include "topocut/map/rasterize.h"
#include "topocut/map/room_outline.h"
#include "topocut/segmentation/room_merging.h"

namespace topocut {

void validate(const OpenRoomOptions& options) {
  auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!non_negative(options.min_area) || !non_negative(options.wall_reach) || !non_negative(options.wall_band) || !non_negative(options.share) || options.share > 1.0 ||
      !non_negative(options.ragged_share) || options.ragged_share > 1.0 || !non_negative(options.floor_share) || options.floor_share > 1.0)
    throw Error("the open rooms' area, wall reach and wall band must be non-negative numbers and their shares lie in [0, 1]");
}

namespace {

// Whether any cell is occupied; stops at the first one.
bool has_occupied_cell(const cv::Mat& cells) {
  for (int r = 0; r < cells.rows; ++r) {
    const unsigned char* row = cells.ptr<unsigned char>(r);
    if (std::memchr(row, kOccupied, static_cast<std::size_t>(cells.cols)) != nullptr) return true;
  }
  return false;
}

// Each room's cells once the labelling has completed the labels (rasterize.h, as rooms_from_pieces()
// does): its own cells and the free cells of no room nearest to it along free space (rays the cleaning
// removed). Indexed by room id; empty when every free cell is a room's (nothing to add).
std::vector<long long> labelled_cells(const LabelRuns& ids, const cv::Mat& cells, std::size_t rooms) {
  cv::Mat labels(cells.size(), CV_32SC1, cv::Scalar(0));
  std::vector<long long> counts(rooms + 1, 0);
  const std::span<const LabelRun> all = ids.all();
  for (std::size_t i = 0; i < all.size(); ++i) {
    int* row = labels.ptr<int>(ids.row_of(i));
    std::fill(row + all[i].begin, row + all[i].end, all[i].label);
    counts[static_cast<std::size_t>(all[i].label)] += all[i].end - all[i].begin;
  }
  std::vector<int> unlabelled;
  for (int r = 0; r < cells.rows; ++r) {
    const unsigned char* cell = cells.ptr<unsigned char>(r);
    const int* label = labels.ptr<int>(r);
    for (int c = 0; c < cells.cols; ++c)
      if (cell[c] == kFree && label[c] == 0) unlabelled.push_back(r * cells.cols + c);
  }
  if (unlabelled.empty()) return {};
  std::vector<LabelChange> changes;
  complete_unlabelled_cells(labels, cells == kFree, unlabelled, &changes);
  for (const LabelChange& change : changes)
    if (change.after > 0) ++counts[static_cast<std::size_t>(change.after)];
  return counts;
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
  // Counted on the first island that might be a fan's core: the completion is a pass over the grid.
  std::optional<std::vector<long long>> labelled;
  const auto mostly_rays = [&](int id, long long cells) {
    if (options.floor_share <= 0.0) return false;
    if (!labelled) labelled = labelled_cells(ids, grid.cells, rooms.pieces.size());
    return !labelled->empty() && static_cast<double>(cells) < options.floor_share * static_cast<double>((*labelled)[static_cast<std::size_t>(id)]);
  };
  for (const auto& [id, extent] : extents) {
    if (static_cast<double>(extent.cells) * cell_area < options.min_area) continue;
    const RoomOutline outline = room_outline(ids, id, extent.box, grid.cells, walls, static_cast<int>(std::lround(options.wall_band / grid.resolution)));
    const bool open = outline.open(options.share, options.ragged_share);
    if (outline.neighbours.empty()) {
      // Nothing beside it: free space seen through a gap, or the dense core of a fan of rays through
      // one (beyond a wall, outside the building), unless it is the building itself (the map's largest
      // room, or as large as half of it: a map explored so far).
      if (2 * extent.cells < largest && (open || mostly_rays(id, extent.cells))) dropped[static_cast<std::size_t>(id - 1)] = changed = true;
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

}  // namespace topocut
