#include "topocut/segmentation/rooms_from_pieces.h"

#include <algorithm>
#include <cmath>
#include <limits>
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
  doors.insert(doors.end(), other.doors.begin(), other.doors.end());
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

Segmentation rooms_from_pieces(const OccupancyGrid& grid, const PieceSet& set, const RoomLabelOptions& options) {
  validate(grid);
  const int h = grid.height(), w = grid.width();
  const std::size_t n = set.pieces.size();

  // Rooms are numbered by their first cell in raster order. The spans tell each piece's first cell
  // before anything is written, so the label image is written once, with room ids; the few cells
  // that the completion below changes are checked, and only if one of them moves a room's first
  // cell are the rooms numbered again from the image.
  const std::vector<CellSpan> spans = polygon_spans(set.pieces, grid.cells.size());
  const long never = std::numeric_limits<long>::max();
  std::vector<long> first(n, never);
  // A piece's first cell that keeps its label: the first free one of its spans (any, if covered
  // obstacles are labelled). Pieces' spans run from their bottom row up, so walk them backwards.
  for (std::size_t k = spans.size(); k-- > 0;) {
    const CellSpan& span = spans[k];
    long& f = first[static_cast<std::size_t>(span.index)];
    if (f != never && f < static_cast<long>(span.row) * w) continue;  // an earlier row already has one
    const unsigned char* g = grid.cells.ptr<unsigned char>(span.row);
    for (int c = span.first; c < span.end; ++c) {
      if (options.cover_absorbed_obstacles || g[c] == kFree) {
        f = std::min(f, static_cast<long>(span.row) * w + c);
        break;
      }
    }
  }
  std::vector<int> order;
  for (std::size_t i = 0; i < n; ++i)
    if (first[i] != never) order.push_back(static_cast<int>(i));
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::tie(first[static_cast<std::size_t>(a)], a) < std::tie(first[static_cast<std::size_t>(b)], b);
  });
  std::vector<int> room_of_piece(n + 1, 0);
  for (std::size_t k = 0; k < order.size(); ++k) room_of_piece[static_cast<std::size_t>(order[k]) + 1] = static_cast<int>(k) + 1;
  const int rooms = static_cast<int>(order.size());

  // One pass writes the label image row by row from the spans (sorted by row, then column):
  // room ids on covered cells (0 where a covered cell is not free, unless obstacles are covered),
  // 0 between spans, and lists the free cells no span covers.
  std::vector<std::size_t> row_begin(static_cast<std::size_t>(h) + 1, 0);
  for (const CellSpan& span : spans) ++row_begin[static_cast<std::size_t>(span.row) + 1];
  for (int r = 0; r < h; ++r) row_begin[static_cast<std::size_t>(r) + 1] += row_begin[static_cast<std::size_t>(r)];
  std::vector<int> by_row(spans.size());
  {
    std::vector<std::size_t> next(row_begin.begin(), row_begin.end() - 1);
    for (std::size_t i = 0; i < spans.size(); ++i) by_row[next[static_cast<std::size_t>(spans[i].row)]++] = static_cast<int>(i);
  }
  cv::Mat labels(grid.cells.size(), CV_32SC1);
  std::vector<long> cells(static_cast<std::size_t>(rooms) + 1, 0);
  std::vector<double> sum_c(static_cast<std::size_t>(rooms) + 1, 0.0), sum_r(static_cast<std::size_t>(rooms) + 1, 0.0);
  std::vector<LabelChange> changes;  // covered cells cleared, free cells filled: to fix the span counts
  std::vector<int> unlabelled;
  bool overlap = false;
  const bool keep = options.cover_absorbed_obstacles;
  std::vector<int> row_spans;
  for (int r = 0; r < h; ++r) {
    int* out = labels.ptr<int>(r);
    const unsigned char* g = grid.cells.ptr<unsigned char>(r);
    row_spans.assign(by_row.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(r)]),
                     by_row.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(r) + 1]));
    std::sort(row_spans.begin(), row_spans.end(), [&](int a, int b) {
      return std::tie(spans[static_cast<std::size_t>(a)].first, a) < std::tie(spans[static_cast<std::size_t>(b)].first, b);
    });
    int c = 0;
    auto gap = [&](int until) {
      std::fill(out + c, out + until, 0);
      for (; c < until; ++c)
        if (g[c] == kFree) unlabelled.push_back(r * w + c);
    };
    for (const int i : row_spans) {
      const CellSpan& span = spans[static_cast<std::size_t>(i)];
      int first_cell = span.first;
      if (first_cell < c) {
        overlap = true;  // pieces overlap: the cells written first stay; rooms are counted again below
        if (span.end <= c) continue;
        first_cell = c;
      }
      gap(first_cell);
      const int id = room_of_piece[static_cast<std::size_t>(span.index) + 1];
      std::fill(out + first_cell, out + span.end, id);
      const long count = span.end - first_cell;
      cells[static_cast<std::size_t>(id)] += count;
      sum_c[static_cast<std::size_t>(id)] += 0.5 * static_cast<double>(count) * (first_cell + span.end - 1);
      sum_r[static_cast<std::size_t>(id)] += static_cast<double>(count) * r;
      if (!keep) {
        for (int x = first_cell; x < span.end; ++x) {
          if (g[x] == kFree) continue;
          out[x] = 0;
          changes.push_back({r * w + x, id, 0});
        }
      }
      c = span.end;
    }
    gap(w);
  }
  if (!unlabelled.empty()) complete_unlabelled_cells(labels, grid.cells == kFree, unlabelled, &changes);
  std::vector<long> filled_first(static_cast<std::size_t>(rooms) + 1, never);  // earliest filled cell per room
  for (const LabelChange& change : changes) {
    const int r = change.index / w, c = change.index % w;
    if (change.before > 0) {
      const std::size_t k = static_cast<std::size_t>(change.before);
      --cells[k];
      sum_c[k] -= c;
      sum_r[k] -= r;
    }
    if (change.after > 0) {
      const std::size_t k = static_cast<std::size_t>(change.after);
      ++cells[k];
      sum_c[k] += c;
      sum_r[k] += r;
      filled_first[k] = std::min(filled_first[k], static_cast<long>(change.index));
    }
  }

  std::vector<int> piece_of_room(static_cast<std::size_t>(rooms) + 1, -1);
  for (std::size_t k = 0; k < order.size(); ++k) piece_of_room[k + 1] = order[k];
  int room_count = rooms;
  if (overlap) {
    // Pieces that overlap (not a tiling): number the rooms from the image itself, as the
    // definition says.
    std::vector<int> renamed(static_cast<std::size_t>(rooms) + 1, 0);
    std::vector<int> new_piece(1, -1);
    int next = 0;
    std::fill(cells.begin(), cells.end(), 0);
    std::fill(sum_c.begin(), sum_c.end(), 0.0);
    std::fill(sum_r.begin(), sum_r.end(), 0.0);
    for (int r = 0; r < h; ++r) {
      int* row = labels.ptr<int>(r);
      for (int c = 0; c < w; ++c) {
        if (row[c] == 0) continue;
        int& id = renamed[static_cast<std::size_t>(row[c])];
        if (id == 0) {
          id = ++next;
          new_piece.push_back(piece_of_room[static_cast<std::size_t>(row[c])]);
        }
        row[c] = id;
        ++cells[static_cast<std::size_t>(id)];
        sum_c[static_cast<std::size_t>(id)] += c;
        sum_r[static_cast<std::size_t>(id)] += r;
      }
    }
    std::fill(room_of_piece.begin(), room_of_piece.end(), 0);
    for (int id = 1; id <= next; ++id) room_of_piece[static_cast<std::size_t>(new_piece[static_cast<std::size_t>(id)]) + 1] = id;
    piece_of_room = new_piece;
    room_count = next;
  } else {
    // The completion cleared some cells (obstacles a piece covered) and labelled others: each
    // room's first cell is its first span cell that kept its label, or an earlier filled cell.
    // Only if that changes the order (or empties a room) are the labels renamed, by table.
    std::vector<std::size_t> span_begin(n + 1, 0);
    for (const CellSpan& span : spans) ++span_begin[static_cast<std::size_t>(span.index) + 1];
    for (std::size_t i = 0; i < n; ++i) span_begin[i + 1] += span_begin[i];
    std::vector<long> true_first(static_cast<std::size_t>(rooms) + 1, never);
    for (int k = 1; k <= rooms; ++k) {
      const std::size_t piece = static_cast<std::size_t>(piece_of_room[static_cast<std::size_t>(k)]);
      long found = never;
      // The piece's spans run from its bottom row up; walk its rows from the top.
      std::size_t end = span_begin[piece + 1];
      while (end > span_begin[piece] && found == never) {
        std::size_t begin = end - 1;
        while (begin > span_begin[piece] && spans[begin - 1].row == spans[end - 1].row) --begin;
        for (std::size_t i = begin; i < end && found == never; ++i) {
          const int* row = labels.ptr<int>(spans[i].row);
          for (int c = spans[i].first; c < spans[i].end; ++c) {
            if (row[c] == k) {
              found = static_cast<long>(spans[i].row) * w + c;
              break;
            }
          }
        }
        end = begin;
      }
      true_first[static_cast<std::size_t>(k)] = std::min(found, filled_first[static_cast<std::size_t>(k)]);
    }
    std::vector<int> by_first;
    for (int k = 1; k <= rooms; ++k)
      if (cells[static_cast<std::size_t>(k)] > 0) by_first.push_back(k);
    std::sort(by_first.begin(), by_first.end(), [&](int a, int b) {
      return true_first[static_cast<std::size_t>(a)] < true_first[static_cast<std::size_t>(b)];
    });
    bool identity = static_cast<int>(by_first.size()) == rooms;
    for (std::size_t i = 0; i < by_first.size() && identity; ++i) identity = by_first[i] == static_cast<int>(i) + 1;
    if (!identity) {
      std::vector<int> renamed(static_cast<std::size_t>(rooms) + 1, 0);
      std::vector<int> new_piece(1, -1);
      std::vector<long> new_cells(1, 0);
      std::vector<double> new_c(1, 0.0), new_r(1, 0.0);
      for (std::size_t i = 0; i < by_first.size(); ++i) {
        const std::size_t k = static_cast<std::size_t>(by_first[i]);
        renamed[k] = static_cast<int>(i) + 1;
        new_piece.push_back(piece_of_room[k]);
        new_cells.push_back(cells[k]);
        new_c.push_back(sum_c[k]);
        new_r.push_back(sum_r[k]);
      }
      for (int r = 0; r < h; ++r) {
        int* row = labels.ptr<int>(r);
        for (int c = 0; c < w; ++c) row[c] = renamed[static_cast<std::size_t>(row[c])];
      }
      std::fill(room_of_piece.begin(), room_of_piece.end(), 0);
      for (std::size_t id = 1; id < new_piece.size(); ++id) room_of_piece[static_cast<std::size_t>(new_piece[id]) + 1] = static_cast<int>(id);
      piece_of_room = new_piece;
      cells = new_cells;
      sum_c = new_c;
      sum_r = new_r;
      room_count = static_cast<int>(by_first.size());
    }
  }

  Segmentation s;
  s.labels = labels;
  s.resolution = grid.resolution;
  s.origin = grid.origin;
  s.rooms.resize(static_cast<std::size_t>(room_count));
  const double cell_area = grid.resolution * grid.resolution;
  for (int id = 1; id <= room_count; ++id) {
    const std::size_t k = static_cast<std::size_t>(id);
    const PolygonWithHoles& piece = set.pieces[static_cast<std::size_t>(piece_of_room[k])];
    Room& room = s.rooms[k - 1];
    room.id = id;
    PolygonWithHoles world;
    world.outer.reserve(piece.outer.size());
    for (const Point2& v : piece.outer) world.outer.push_back(grid_to_world(grid, v));
    for (const Ring& hole : piece.holes) {
      Ring ring;
      ring.reserve(hole.size());
      for (const Point2& v : hole) ring.push_back(grid_to_world(grid, v));
      world.holes.push_back(std::move(ring));
    }
    room.polygon = normalized_orientation(world);
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
