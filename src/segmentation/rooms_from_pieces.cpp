#include "topocut/segmentation/rooms_from_pieces.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "topocut/core/error.h"
#include "topocut/map/rasterize.h"

namespace topocut {

namespace {

// Even-odd crossing test of one ring (half-open in y, as in the rasterizer).
bool crosses_odd(const Ring& ring, const Point2& p) {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = ring[i];
    const Point2& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

bool contains(const PolygonWithHoles& polygon, const Point2& p) {
  bool inside = crosses_odd(polygon.outer, p);
  for (const Ring& hole : polygon.holes) inside ^= crosses_odd(hole, p);
  return inside;
}

}  // namespace

void PieceSet::append(const PieceSet& other) {
  pieces.insert(pieces.end(), other.pieces.begin(), other.pieces.end());
  cuts.insert(cuts.end(), other.cuts.begin(), other.cuts.end());
}

int piece_containing(const std::vector<PolygonWithHoles>& pieces, const Point2& p) {
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Ring& outer = pieces[i].outer;
    if (outer.size() < 3) continue;
    double x0 = outer[0].x, x1 = x0, y0 = outer[0].y, y1 = y0;
    for (const Point2& v : outer) {
      x0 = std::min(x0, v.x);
      x1 = std::max(x1, v.x);
      y0 = std::min(y0, v.y);
      y1 = std::max(y1, v.y);
    }
    if (p.x < x0 || p.x > x1 || p.y < y0 || p.y > y1) continue;
    if (contains(pieces[i], p)) return static_cast<int>(i);
  }
  return -1;
}

Segmentation rooms_from_pieces(const OccupancyGrid& grid, const PieceSet& set) {
  validate(grid);
  const int h = grid.height(), w = grid.width();
  cv::Mat labels = rasterize_polygons(set.pieces, grid.cells.size());
  fill_free_space_labels(labels, grid.cells == kFree);

  // Rooms numbered by first cell in raster order: the ids do not depend on the order of pieces.
  std::vector<int> room_of_piece(set.pieces.size() + 1, 0);
  std::vector<long> cells;
  std::vector<double> sum_c, sum_r;
  int rooms = 0;
  for (int r = 0; r < h; ++r) {
    int* row = labels.ptr<int>(r);
    for (int c = 0; c < w; ++c) {
      if (row[c] == 0) continue;
      int& room = room_of_piece[static_cast<std::size_t>(row[c])];
      if (room == 0) {
        room = ++rooms;
        cells.push_back(0);
        sum_c.push_back(0.0);
        sum_r.push_back(0.0);
      }
      row[c] = room;
      ++cells[static_cast<std::size_t>(room - 1)];
      sum_c[static_cast<std::size_t>(room - 1)] += c;
      sum_r[static_cast<std::size_t>(room - 1)] += r;
    }
  }

  Segmentation s;
  s.labels = labels;
  s.resolution = grid.resolution;
  s.origin = grid.origin;
  s.rooms.resize(static_cast<std::size_t>(rooms));
  const double cell_area = grid.resolution * grid.resolution;
  for (std::size_t piece = 0; piece < set.pieces.size(); ++piece) {
    const int id = room_of_piece[piece + 1];
    if (id == 0) continue;
    Room& room = s.rooms[static_cast<std::size_t>(id - 1)];
    room.id = id;
    PolygonWithHoles world;
    for (const Point2& v : set.pieces[piece].outer) world.outer.push_back(grid_to_world(grid, v));
    for (const Ring& hole : set.pieces[piece].holes) {
      Ring ring;
      for (const Point2& v : hole) ring.push_back(grid_to_world(grid, v));
      world.holes.push_back(std::move(ring));
    }
    room.polygon = normalized_orientation(world);
    const std::size_t k = static_cast<std::size_t>(id - 1);
    room.area = static_cast<double>(cells[k]) * cell_area;
    const double mean_c = sum_c[k] / static_cast<double>(cells[k]);
    const double mean_r = sum_r[k] / static_cast<double>(cells[k]);
    room.centroid = {grid.origin.x + (mean_c + 0.5) * grid.resolution, grid.origin.y + (h - mean_r - 0.5) * grid.resolution};
  }

  // A cut separates the pieces just left and right of its midpoint.
  for (const Segment2& cut : set.cuts) {
    const double dx = cut.b.x - cut.a.x, dy = cut.b.y - cut.a.y;
    const double length = std::hypot(dx, dy);
    if (!(length > 0.0) || !std::isfinite(length)) continue;
    const double eps = 1e-3;  // cells; far below any feature of a pixel polygon
    const Point2 mid{(cut.a.x + cut.b.x) / 2.0, (cut.a.y + cut.b.y) / 2.0};
    const Point2 left{mid.x - dy / length * eps, mid.y + dx / length * eps};
    const Point2 right{mid.x + dy / length * eps, mid.y - dx / length * eps};
    const int piece_a = piece_containing(set.pieces, left);
    const int piece_b = piece_containing(set.pieces, right);
    if (piece_a < 0 || piece_b < 0) continue;
    const int a = room_of_piece[static_cast<std::size_t>(piece_a) + 1];
    const int b = room_of_piece[static_cast<std::size_t>(piece_b) + 1];
    if (a == 0 || b == 0 || a == b) continue;
    Passage p;
    p.room_a = std::min(a, b);
    p.room_b = std::max(a, b);
    p.cut = {grid_to_world(grid, cut.a), grid_to_world(grid, cut.b)};
    p.width = length * grid.resolution;
    s.passages.push_back(p);
  }
  std::sort(s.passages.begin(), s.passages.end(), [](const Passage& x, const Passage& y) {
    return std::tie(x.room_a, x.room_b, x.cut.a.x, x.cut.a.y, x.cut.b.x, x.cut.b.y) <
           std::tie(y.room_a, y.room_b, y.cut.a.x, y.cut.a.y, y.cut.b.x, y.cut.b.y);
  });
  return s;
}

}  // namespace topocut
