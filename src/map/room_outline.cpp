#include "topocut/map/room_outline.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "map/row_runs.h"
#include "topocut/core/occupancy_grid.h"

namespace topocut {

std::map<int, RoomExtent> room_extents(const LabelRuns& labels) {
  std::map<int, RoomExtent> rooms;
  const std::span<const LabelRun> all = labels.all();
  for (const int id : labels.labels()) {
    RoomExtent& room = rooms[id];
    for (const std::size_t i : labels.runs_of(id)) {
      const cv::Rect run(all[i].begin, labels.row_of(i), all[i].end - all[i].begin, 1);
      room.box = room.cells == 0 ? run : (room.box | run);
      room.cells += run.width;
    }
  }
  return rooms;
}

namespace {

// The largest squared distance (a whole number of cells²) that OpenCV's exact Euclidean distance
// transform (float, cv::DIST_MASK_PRECISE) compares as at most reach.
long long squared_reach(double reach) {
  const float limit = static_cast<float>(reach);
  if (!(limit >= 0.0f)) return -1;
  long long k = static_cast<long long>(std::floor(static_cast<double>(limit) * limit)) + 2;
  while (k >= 0 && !(std::sqrt(static_cast<float>(k)) <= limit)) --k;
  return k;
}

}  // namespace

cv::Mat wall_cells(const cv::Mat& cells, double reach) {
  // The cells within reach of an occupied cell are the occupied cells dilated by the disc of squared
  // radius squared_reach(reach): what thresholding the exact distance transform gives, on runs.
  cv::Mat walls(cells.size(), CV_8UC1);
  const long long k2 = squared_reach(reach);
  if (k2 < 0) {
    walls.setTo(0);
    return walls;
  }
  const int r = static_cast<int>(std::min<double>(std::floor(std::sqrt(static_cast<double>(k2))), std::max(cells.rows, cells.cols)));
  std::vector<int> half_widths(static_cast<std::size_t>(r) + 1);
  for (int dy = 0; dy <= r; ++dy) {
    long long dx = static_cast<long long>(std::sqrt(static_cast<double>(k2 - static_cast<long long>(dy) * dy)));
    while (dx * dx + static_cast<long long>(dy) * dy > k2) --dx;
    while ((dx + 1) * (dx + 1) + static_cast<long long>(dy) * dy <= k2) ++dx;
    half_widths[static_cast<std::size_t>(dy)] = static_cast<int>(std::min<long long>(dx, cells.cols));
  }
  write_mask(dilate(runs_of_value(cells, kOccupied), half_widths), walls, 255, 0);
  return walls;
}

namespace {

// The cells of a room's window (its box grown by a cell) as runs: the room's own cells and the rest,
// with which runs of the rest the window's frame reaches (4-connected through the rest, as a flood
// fill from the frame would): the cells outside the room, its enclosed cells (holes) filled.
class RoomWindow {
 public:
  RoomWindow(const LabelRuns& labels, int id, const cv::Rect& window) : room_(window.width) {
    const std::span<const LabelRun> all = labels.all();
    const std::span<const std::size_t> mine = labels.runs_of(id);
    std::size_t k = 0;
    for (int wr = 0; wr < window.height; ++wr) {
      while (k < mine.size() && labels.row_of(mine[k]) < window.y + wr) ++k;
      for (; k < mine.size() && labels.row_of(mine[k]) == window.y + wr; ++k) {
        const LabelRun& run = all[mine[k]];
        const int begin = std::max(run.begin, window.x + 1) - window.x, end = std::min(run.end, window.x + window.width - 1) - window.x;
        if (begin < end) room_.push({begin, end});
      }
      room_.end_row();
    }
    rest_ = complement(room_);
    int count = 0;
    const std::vector<int> component = run_components(rest_, /*eight_connected=*/false, count);
    // The frame's top row is one run of the rest (the box lies inside the frame).
    outside_.resize(component.size());
    for (std::size_t i = 0; i < component.size(); ++i) outside_[i] = component[i] == component.front();
  }

  const RowRuns& room() const { return room_; }
  const RowRuns& rest() const { return rest_; }
  // Whether run i of rest().all() lies outside the filled room.
  bool outside_run(std::size_t i) const { return outside_[i]; }
  // Whether the window cell (wr, wc) lies outside the filled room.
  bool outside(int wr, int wc) const {
    const std::span<const CellRun> row = rest_.row(wr);
    const auto run = std::upper_bound(row.begin(), row.end(), wc, [](int c, const CellRun& r) { return c < r.end; });
    return run != row.end() && run->begin <= wc && outside_[rest_.index_of_row(wr) + static_cast<std::size_t>(run - row.begin())];
  }

 private:
  RowRuns room_, rest_;
  std::vector<bool> outside_;
};

}  // namespace

RoomOutline room_outline(const LabelRuns& labels, int id, const cv::Rect& box, const cv::Mat& cells, const cv::Mat& walls,
                         int band, const cv::Mat& floor) {
  const cv::Rect window = cv::Rect(box.x - 1, box.y - 1, box.width + 2, box.height + 2);
  const RoomWindow filled(labels, id, window);
  RoomOutline outline;
  // Edges to other rooms come in long stretches along one neighbour: counted here, then in the map.
  int neighbour = 0;
  long long neighbour_edges = 0;
  const auto flush = [&] {
    if (neighbour_edges > 0) outline.neighbours[neighbour] += neighbour_edges;
    neighbour_edges = 0;
  };
  const cv::Size size = labels.size();
  const auto inside_grid = [&](int r, int c) { return r >= 0 && c >= 0 && r < size.height && c < size.width; };
  // Straight on behind the unknown cell (r, c), within band cells, the first cell that is not unknown is
  // a wall or another room's: the unknown cells are a wall drawn in grey. Free cells of no room (rays the
  // cleaning removed) or of this room do not count.
  const auto drawn_wall = [&](int r, int c, int dr, int dc) {
    for (int k = 1; k <= band && inside_grid(r + k * dr, c + k * dc); ++k) {
      const int rr = r + k * dr, cc = c + k * dc;
      if (walls.at<unsigned char>(rr, cc)) return true;
      if (cells.at<unsigned char>(rr, cc) == kUnknown) continue;
      const int owner = labels.at(rr, cc);
      return owner > 0 && owner != id && (floor.empty() || floor.at<unsigned char>(rr, cc) != 0);
    }
    return false;
  };
  // The room cell (wr, wc) facing out along (dr, dc): the outline turns there unless both cells beside it
  // (across the direction) are room cells facing out the same way.
  const auto ragged = [&](int wr, int wc, int dr, int dc) {
    for (const int side : {-1, 1}) {
      const int sr = wr + side * dc, sc = wc + side * dr;
      if (filled.outside(sr, sc) || !filled.outside(sr + dr, sc + dc)) return true;
    }
    return false;
  };
  // The edge from a room cell to the cell (wr, wc) outside the filled room, which lies along (dr, dc).
  const auto edge = [&](int wr, int wc, int dr, int dc) {
    const int r = window.y + wr, c = window.x + wc;
    if (!inside_grid(r, c)) {
      ++outline.unknown;
      return;
    }
    const int other = labels.at(r, c);
    if (other > 0) {
      if (other != neighbour) {
        flush();
        neighbour = other;
      }
      ++neighbour_edges;
    } else if (cells.at<unsigned char>(r, c) != kFree) {
      const bool wall = walls.at<unsigned char>(r, c) || (cells.at<unsigned char>(r, c) == kUnknown && drawn_wall(r, c, dr, dc));
      ++(wall ? outline.wall : outline.unknown);
      if (!wall && ragged(wr - dr, wc - dc, dr, dc)) ++outline.ragged;
    }
  };
  // Every edge from a room cell to a cell outside the filled room (only the room's own cells can face
  // it: an enclosed cell beside an outside one would be outside too): along each run's ends, and where
  // the runs of the rows above and below that lie outside overlap it.
  const RowRuns& rest = filled.rest();
  // The room's runs of row wr against the outside runs of row wr + dr, both in column order.
  const auto across = [&](int wr, int dr) {
    const std::span<const CellRun> mine = filled.room().row(wr), other = rest.row(wr + dr);
    const std::size_t first = rest.index_of_row(wr + dr);
    for (std::size_t i = 0, k = 0; i < mine.size() && k < other.size();) {
      const int from = std::max(mine[i].begin, other[k].begin), to = std::min(mine[i].end, other[k].end);
      if (from < to && filled.outside_run(first + k))
        for (int wc = from; wc < to; ++wc) edge(wr + dr, wc, dr, 0);
      if (mine[i].end < other[k].end) ++i;
      else ++k;
    }
  };
  for (int wr = 1; wr + 1 < window.height; ++wr) {
    across(wr, -1);
    across(wr, 1);
    for (const CellRun& run : filled.room().row(wr)) {
      if (filled.outside(wr, run.begin - 1)) edge(wr, run.begin - 1, 0, -1);
      if (filled.outside(wr, run.end)) edge(wr, run.end, 0, 1);
    }
  }
  flush();
  return outline;
}

}  // namespace topocut
