#include "topocut/evaluation/merge_training.h"

#include <map>

#include "topocut/core/error.h"
#include "topocut/map/rasterize.h"
#include "topocut/segmentation/merge_trace.h"

namespace topocut {

namespace {

using Histogram = std::map<int, int>;  // ground-truth room -> cells

// The ground-truth rooms under each piece's cells.
std::vector<Histogram> piece_rooms(const std::vector<PolygonWithHoles>& pieces, const cv::Mat& room_labels) {
  std::vector<Histogram> rooms(pieces.size());
  for (const CellSpan& span : polygon_spans(pieces, room_labels.size())) {
    const int* row = room_labels.ptr<int>(span.row);
    Histogram& h = rooms[static_cast<std::size_t>(span.index)];
    for (int c = span.first; c < span.end; ++c)
      if (row[c] > 0) ++h[row[c]];
  }
  return rooms;
}

// The most common room of a side and its share of the side's cells in rooms; room 0 if none.
std::pair<int, double> main_room(const std::vector<int>& side, const std::vector<Histogram>& rooms) {
  Histogram total;
  for (const int piece : side)
    for (const auto& [room, cells] : rooms[static_cast<std::size_t>(piece)]) total[room] += cells;
  int best = 0, best_cells = 0, all = 0;
  for (const auto& [room, cells] : total) {
    all += cells;
    if (cells > best_cells) std::tie(best, best_cells) = std::pair{room, cells};
  }
  return {best, all > 0 ? static_cast<double>(best_cells) / all : 0.0};
}

}  // namespace

std::vector<MergeTrainingRow> merge_training_rows(const OccupancyGrid& grid, const cv::Mat& room_labels,
                                                  const SegmentOptions& options) {
  if (room_labels.size() != grid.cells.size() || room_labels.type() != CV_32SC1)
    throw Error("the ground-truth rooms must be CV_32SC1 labels of the map's size");
  const MergeTrace trace = trace_merges(grid, options);
  const std::vector<Histogram> rooms = piece_rooms(trace.pieces, room_labels);
  std::vector<MergeTrainingRow> rows;
  for (const MergeStep& step : trace.steps) {
    const auto [room_a, share_a] = main_room(step.side_a, rooms);
    const auto [room_b, share_b] = main_room(step.side_b, rooms);
    if (room_a == 0 || room_b == 0) continue;
    rows.push_back({step.features, room_a == room_b, share_a * share_b, step.probability});
  }
  return rows;
}

}  // namespace topocut
