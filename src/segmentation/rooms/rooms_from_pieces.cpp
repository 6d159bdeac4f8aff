#include "topocut/segmentation/rooms_from_pieces.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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

constexpr long kNever = std::numeric_limits<long>::max();

// Per room id (index 0 unused): its cells and the sums of their column and row indices.
struct RoomCells {
  std::vector<long> cells;
  std::vector<double> sum_c, sum_r;
};

// Which room each piece is, and back; a piece that labels no cell is room 0.
struct RoomNumbering {
  std::vector<int> room_of_piece;  // by piece index + 1
  std::vector<int> piece_of_room;  // by room id; index 0: -1
  int rooms = 0;
};

// The label image as the spans write it, with what the completion must still fix.
struct SpanLabels {
  cv::Mat labels;
  RoomCells tally;
  std::vector<LabelChange> changes;  // covered cells cleared, free cells filled: to fix the span counts
  std::vector<int> unlabelled;       // free cells no span covers
  bool overlap = false;              // pieces overlap: the cells written first stay
};

// Rooms are numbered by their first cell in raster order. The spans tell each piece's first cell
// before anything is written, so the label image is written once, with room ids; the few cells
// that the completion changes are checked later, and only if one of them moves a room's first
// cell are the rooms numbered again from the image.
RoomNumbering number_by_spans(const OccupancyGrid& grid, const std::vector<CellSpan>& spans, std::size_t n,
                              bool cover_absorbed_obstacles) {
  const int w = grid.width();
  std::vector<long> first(n, kNever);
  // A piece's first cell that keeps its label: the first free one of its spans (any, if covered
  // obstacles are labelled). Pieces' spans run from their bottom row up, so walk them backwards.
  for (std::size_t k = spans.size(); k-- > 0;) {
    const CellSpan& span = spans[k];
    long& f = first[static_cast<std::size_t>(span.index)];
    if (f != kNever && f < static_cast<long>(span.row) * w) continue;  // an earlier row already has one
    const unsigned char* g = grid.cells.ptr<unsigned char>(span.row);
    for (int c = span.first; c < span.end; ++c) {
      if (cover_absorbed_obstacles || g[c] == kFree) {
        f = std::min(f, static_cast<long>(span.row) * w + c);
        break;
      }
    }
  }
  std::vector<int> order;
  for (std::size_t i = 0; i < n; ++i)
    if (first[i] != kNever) order.push_back(static_cast<int>(i));
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::tie(first[static_cast<std::size_t>(a)], a) < std::tie(first[static_cast<std::size_t>(b)], b);
  });
  RoomNumbering numbering;
  numbering.room_of_piece.assign(n + 1, 0);
  for (std::size_t k = 0; k < order.size(); ++k)
    numbering.room_of_piece[static_cast<std::size_t>(order[k]) + 1] = static_cast<int>(k) + 1;
  numbering.rooms = static_cast<int>(order.size());
  numbering.piece_of_room.assign(static_cast<std::size_t>(numbering.rooms) + 1, -1);
  for (std::size_t k = 0; k < order.size(); ++k) numbering.piece_of_room[k + 1] = order[k];
  return numbering;
}

// One pass writes the label image row by row from the spans (sorted by row, then column): room
// ids on covered cells (0 where a covered cell is not free, unless obstacles are covered), 0
// between spans, and lists the free cells no span covers; every cell is written exactly once.
SpanLabels write_span_labels(const OccupancyGrid& grid, const std::vector<CellSpan>& spans,
                             const RoomNumbering& numbering, bool keep) {
  const int h = grid.height(), w = grid.width();
  std::vector<std::size_t> row_begin(static_cast<std::size_t>(h) + 1, 0);
  for (const CellSpan& span : spans) ++row_begin[static_cast<std::size_t>(span.row) + 1];
  for (int r = 0; r < h; ++r) row_begin[static_cast<std::size_t>(r) + 1] += row_begin[static_cast<std::size_t>(r)];
  std::vector<int> by_row(spans.size());
  {
    std::vector<std::size_t> next(row_begin.begin(), row_begin.end() - 1);
    for (std::size_t i = 0; i < spans.size(); ++i) by_row[next[static_cast<std::size_t>(spans[i].row)]++] = static_cast<int>(i);
  }
  SpanLabels out;
  out.labels = cv::Mat(grid.cells.size(), CV_32SC1);
  const std::size_t slots = static_cast<std::size_t>(numbering.rooms) + 1;
  out.tally.cells.assign(slots, 0);
  out.tally.sum_c.assign(slots, 0.0);
  out.tally.sum_r.assign(slots, 0.0);
  std::vector<int> row_spans;
  for (int r = 0; r < h; ++r) {
    int* labels = out.labels.ptr<int>(r);
    const unsigned char* g = grid.cells.ptr<unsigned char>(r);
    row_spans.assign(by_row.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(r)]),
                     by_row.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(r) + 1]));
    std::sort(row_spans.begin(), row_spans.end(), [&](int a, int b) {
      return std::tie(spans[static_cast<std::size_t>(a)].first, a) < std::tie(spans[static_cast<std::size_t>(b)].first, b);
    });
    int c = 0;
    auto gap = [&](int until) {
      std::fill(labels + c, labels + until, 0);
      // Free cells are rare between spans (walls, unknown space): memchr skips to the next one.
      for (const void* f; c < until && (f = std::memchr(g + c, kFree, static_cast<std::size_t>(until - c))) != nullptr;) {
        c = static_cast<int>(static_cast<const unsigned char*>(f) - g);
        out.unlabelled.push_back(r * w + c++);
      }
      c = until;
    };
    for (const int i : row_spans) {
      const CellSpan& span = spans[static_cast<std::size_t>(i)];
      int first_cell = span.first;
      if (first_cell < c) {
        out.overlap = true;  // pieces overlap: the cells written first stay; rooms are counted again below
        if (span.end <= c) continue;
        first_cell = c;
      }
      gap(first_cell);
      const int id = numbering.room_of_piece[static_cast<std::size_t>(span.index) + 1];
      std::fill(labels + first_cell, labels + span.end, id);
      const long count = span.end - first_cell;
      out.tally.cells[static_cast<std::size_t>(id)] += count;
      out.tally.sum_c[static_cast<std::size_t>(id)] += 0.5 * static_cast<double>(count) * (first_cell + span.end - 1);
      out.tally.sum_r[static_cast<std::size_t>(id)] += static_cast<double>(count) * r;
      if (!keep) {
        for (int x = first_cell; x < span.end; ++x) {
          if (g[x] == kFree) continue;
          labels[x] = 0;
          out.changes.push_back({r * w + x, id, 0});
        }
      }
      c = span.end;
    }
    gap(w);
  }
  return out;
}

// Labels the free cells no span covered and brings the rooms' counts and sums in line with every
// change made after the spans. Returns each room's earliest filled cell (kNever if none).
std::vector<long> complete_labels(const OccupancyGrid& grid, SpanLabels& written, int rooms) {
  const int w = grid.width();
  if (!written.unlabelled.empty())
    complete_unlabelled_cells(written.labels, grid.cells == kFree, written.unlabelled, &written.changes);
  std::vector<long> filled_first(static_cast<std::size_t>(rooms) + 1, kNever);  // earliest filled cell per room
  RoomCells& t = written.tally;
  for (const LabelChange& change : written.changes) {
    const int r = change.index / w, c = change.index % w;
    if (change.before > 0) {
      const std::size_t k = static_cast<std::size_t>(change.before);
      --t.cells[k];
      t.sum_c[k] -= c;
      t.sum_r[k] -= r;
    }
    if (change.after > 0) {
      const std::size_t k = static_cast<std::size_t>(change.after);
      ++t.cells[k];
      t.sum_c[k] += c;
      t.sum_r[k] += r;
      filled_first[k] = std::min(filled_first[k], static_cast<long>(change.index));
    }
  }
  return filled_first;
}

// Pieces that overlap (not a tiling): the rooms are numbered from the image itself, as the
// definition says, and counted again from it.
void renumber_from_image(SpanLabels& written, RoomNumbering& numbering) {
  RoomCells& t = written.tally;
  std::vector<int> renamed(static_cast<std::size_t>(numbering.rooms) + 1, 0);
  std::vector<int> new_piece(1, -1);
  int next = 0;
  std::fill(t.cells.begin(), t.cells.end(), 0);
  std::fill(t.sum_c.begin(), t.sum_c.end(), 0.0);
  std::fill(t.sum_r.begin(), t.sum_r.end(), 0.0);
  for (int r = 0; r < written.labels.rows; ++r) {
    int* row = written.labels.ptr<int>(r);
    for (int c = 0; c < written.labels.cols; ++c) {
      if (row[c] == 0) continue;
      int& id = renamed[static_cast<std::size_t>(row[c])];
      if (id == 0) {
        id = ++next;
        new_piece.push_back(numbering.piece_of_room[static_cast<std::size_t>(row[c])]);
      }
      row[c] = id;
      ++t.cells[static_cast<std::size_t>(id)];
      t.sum_c[static_cast<std::size_t>(id)] += c;
      t.sum_r[static_cast<std::size_t>(id)] += r;
    }
  }
  std::fill(numbering.room_of_piece.begin(), numbering.room_of_piece.end(), 0);
  for (int id = 1; id <= next; ++id)
    numbering.room_of_piece[static_cast<std::size_t>(new_piece[static_cast<std::size_t>(id)]) + 1] = id;
  numbering.piece_of_room = new_piece;
  numbering.rooms = next;
}

// Each room's true first cell after the completion: its first span cell that kept its label, or
// an earlier filled cell.
std::vector<long> true_first_cells(const cv::Mat& labels, const std::vector<CellSpan>& spans, std::size_t n,
                                   const RoomNumbering& numbering, const std::vector<long>& filled_first) {
  const int rooms = numbering.rooms, w = labels.cols;
  std::vector<std::size_t> span_begin(n + 1, 0);
  for (const CellSpan& span : spans) ++span_begin[static_cast<std::size_t>(span.index) + 1];
  for (std::size_t i = 0; i < n; ++i) span_begin[i + 1] += span_begin[i];
  std::vector<long> true_first(static_cast<std::size_t>(rooms) + 1, kNever);
  for (int k = 1; k <= rooms; ++k) {
    const std::size_t piece = static_cast<std::size_t>(numbering.piece_of_room[static_cast<std::size_t>(k)]);
    long found = kNever;
    // The piece's spans run from its bottom row up; walk its rows from the top.
    std::size_t end = span_begin[piece + 1];
    while (end > span_begin[piece] && found == kNever) {
      std::size_t begin = end - 1;
      while (begin > span_begin[piece] && spans[begin - 1].row == spans[end - 1].row) --begin;
      for (std::size_t i = begin; i < end && found == kNever; ++i) {
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
  return true_first;
}

// The completion cleared some cells (obstacles a piece covered) and labelled others: only if that
// changes the rooms' order by first cell (or empties a room) are the labels renamed, by table.
void renumber_by_first_cells(SpanLabels& written, RoomNumbering& numbering, const std::vector<long>& true_first) {
  const int rooms = numbering.rooms;
  RoomCells& t = written.tally;
  std::vector<int> by_first;
  for (int k = 1; k <= rooms; ++k)
    if (t.cells[static_cast<std::size_t>(k)] > 0) by_first.push_back(k);
  std::sort(by_first.begin(), by_first.end(), [&](int a, int b) {
    return true_first[static_cast<std::size_t>(a)] < true_first[static_cast<std::size_t>(b)];
  });
  bool identity = static_cast<int>(by_first.size()) == rooms;
  for (std::size_t i = 0; i < by_first.size() && identity; ++i) identity = by_first[i] == static_cast<int>(i) + 1;
  if (identity) return;
  std::vector<int> renamed(static_cast<std::size_t>(rooms) + 1, 0);
  std::vector<int> new_piece(1, -1);
  RoomCells renamed_cells{{0}, {0.0}, {0.0}};
  for (std::size_t i = 0; i < by_first.size(); ++i) {
    const std::size_t k = static_cast<std::size_t>(by_first[i]);
    renamed[k] = static_cast<int>(i) + 1;
    new_piece.push_back(numbering.piece_of_room[k]);
    renamed_cells.cells.push_back(t.cells[k]);
    renamed_cells.sum_c.push_back(t.sum_c[k]);
    renamed_cells.sum_r.push_back(t.sum_r[k]);
  }
  for (int r = 0; r < written.labels.rows; ++r) {
    int* row = written.labels.ptr<int>(r);
    for (int c = 0; c < written.labels.cols; ++c) row[c] = renamed[static_cast<std::size_t>(row[c])];
  }
  std::fill(numbering.room_of_piece.begin(), numbering.room_of_piece.end(), 0);
  for (std::size_t id = 1; id < new_piece.size(); ++id)
    numbering.room_of_piece[static_cast<std::size_t>(new_piece[id]) + 1] = static_cast<int>(id);
  numbering.piece_of_room = new_piece;
  t = renamed_cells;
  numbering.rooms = static_cast<int>(by_first.size());
}

// Room k is piece piece_of_room[k] in world metres, with its area, and the area and centroid of its cells.
std::vector<Room> room_list(const OccupancyGrid& grid, const PieceSet& set, const RoomNumbering& numbering,
                            const RoomCells& t) {
  const int h = grid.height();
  std::vector<Room> rooms(static_cast<std::size_t>(numbering.rooms));
  const double cell_area = grid.resolution * grid.resolution;
  for (int id = 1; id <= numbering.rooms; ++id) {
    const std::size_t k = static_cast<std::size_t>(id);
    const PolygonWithHoles& piece = set.pieces[static_cast<std::size_t>(numbering.piece_of_room[k])];
    Room& room = rooms[k - 1];
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
    room.area = area(room.polygon);
    room.labelled_area = static_cast<double>(t.cells[k]) * cell_area;
    const double mean_c = t.sum_c[k] / static_cast<double>(t.cells[k]);
    const double mean_r = t.sum_r[k] / static_cast<double>(t.cells[k]);
    room.centroid = {grid.origin.x + (mean_c + 0.5) * grid.resolution, grid.origin.y + (h - mean_r - 0.5) * grid.resolution};
  }
  return rooms;
}

// Which piece contains a point, as piece_containing() answers it (the first piece in order whose
// outer ring's box holds the point and which contains it), with the pieces' boxes in buckets of a
// grid over them: one passage per cut then costs the pieces near the cut, not all of them.
class PieceLocator {
 public:
  explicit PieceLocator(const std::vector<PolygonWithHoles>& pieces) : pieces_(pieces), boxes_(pieces.size()) {
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (pieces[i].outer.size() < 3) continue;
      boxes_[i] = bounding_box(pieces[i].outer);
      all_.x0 = std::min(all_.x0, boxes_[i].x0);
      all_.y0 = std::min(all_.y0, boxes_[i].y0);
      all_.x1 = std::max(all_.x1, boxes_[i].x1);
      all_.y1 = std::max(all_.y1, boxes_[i].y1);
    }
    if (!(all_.x0 <= all_.x1)) return;
    // About one bucket per piece.
    side_ = static_cast<int>(std::clamp(std::sqrt(static_cast<double>(pieces.size())), 1.0, 1024.0));
    bucket_w_ = std::max((all_.x1 - all_.x0) / side_, 1e-9);
    bucket_h_ = std::max((all_.y1 - all_.y0) / side_, 1e-9);
    buckets_.resize(static_cast<std::size_t>(side_) * side_);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (pieces[i].outer.size() < 3) continue;
      const int cx0 = column(boxes_[i].x0), cx1 = column(boxes_[i].x1), cy0 = row(boxes_[i].y0), cy1 = row(boxes_[i].y1);
      for (int cy = cy0; cy <= cy1; ++cy)
        for (int cx = cx0; cx <= cx1; ++cx) buckets_[static_cast<std::size_t>(cy) * side_ + cx].push_back(static_cast<int>(i));
    }
  }

  int piece_at(const Point2& p) const {
    if (!(p.x >= all_.x0 && p.x <= all_.x1 && p.y >= all_.y0 && p.y <= all_.y1)) return -1;
    for (const int i : buckets_[static_cast<std::size_t>(row(p.y)) * side_ + column(p.x)]) {
      const Box& box = boxes_[static_cast<std::size_t>(i)];
      if (p.x < box.x0 || p.x > box.x1 || p.y < box.y0 || p.y > box.y1) continue;
      if (contains(pieces_[static_cast<std::size_t>(i)], p)) return i;
    }
    return -1;
  }

 private:
  // Monotone in the coordinate, so a box's buckets hold every point the box holds.
  int column(double x) const { return std::clamp(static_cast<int>((x - all_.x0) / bucket_w_), 0, side_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>((y - all_.y0) / bucket_h_), 0, side_ - 1); }

  const std::vector<PolygonWithHoles>& pieces_;
  std::vector<Box> boxes_;
  Box all_;
  int side_ = 0;
  double bucket_w_ = 1.0, bucket_h_ = 1.0;
  std::vector<std::vector<int>> buckets_;  // piece indices in ascending order
};

// A cut between two different rooms is a passage between them; a cut separates the pieces just
// left and right of its midpoint. Sorted by rooms, then cut, so the list is deterministic.
std::vector<Passage> passages_between(const OccupancyGrid& grid, const PieceSet& set,
                                      const std::vector<int>& room_of_piece) {
  std::vector<Passage> passages;
  const PieceLocator locator(set.pieces);
  for (std::size_t k = 0; k < set.cuts.size(); ++k) {
    const Segment2& cut = set.cuts[k];
    Point2 left, right;
    if (!cut_sides(cut.a, cut.b, left, right)) continue;
    const int piece_a = locator.piece_at(left);
    const int piece_b = locator.piece_at(right);
    if (piece_a < 0 || piece_b < 0) continue;
    const int a = room_of_piece[static_cast<std::size_t>(piece_a) + 1];
    const int b = room_of_piece[static_cast<std::size_t>(piece_b) + 1];
    if (a == 0 || b == 0 || a == b) continue;
    Passage p;
    p.room_a = std::min(a, b);
    p.room_b = std::max(a, b);
    p.cut = {grid_to_world(grid, cut.a), grid_to_world(grid, cut.b)};
    p.width = std::hypot(cut.b.x - cut.a.x, cut.b.y - cut.a.y) * grid.resolution;
    p.rule = k < set.rules.size() ? set.rules[k] : CutRule::kDecomposition;
    passages.push_back(p);
  }
  std::sort(passages.begin(), passages.end(), [](const Passage& x, const Passage& y) {
    return std::tie(x.room_a, x.room_b, x.cut.a.x, x.cut.a.y, x.cut.b.x, x.cut.b.y) <
           std::tie(y.room_a, y.room_b, y.cut.a.x, y.cut.a.y, y.cut.b.x, y.cut.b.y);
  });
  return passages;
}

}  // namespace

void PieceSet::add_cut(const Segment2& cut, CutRule rule) {
  cuts.push_back(cut);
  rules.push_back(rule);
}

void PieceSet::append(const PieceSet& other) {
  pieces.insert(pieces.end(), other.pieces.begin(), other.pieces.end());
  cuts.insert(cuts.end(), other.cuts.begin(), other.cuts.end());
  rules.insert(rules.end(), other.rules.begin(), other.rules.end());
}

CutRule PieceSet::rule_of(const Segment2& cut) const {
  const auto it = std::find(cuts.begin(), cuts.end(), cut);
  const std::size_t k = static_cast<std::size_t>(it - cuts.begin());
  return k < rules.size() ? rules[k] : CutRule::kDecomposition;
}

bool cut_sides(const Point2& a, const Point2& b, Point2& left, Point2& right) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length = std::hypot(dx, dy);
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  const double eps = 1e-3;
  const Point2 mid{(a.x + b.x) / 2.0, (a.y + b.y) / 2.0};
  left = {mid.x - dy / length * eps, mid.y + dx / length * eps};
  right = {mid.x + dy / length * eps, mid.y - dx / length * eps};
  return true;
}

int piece_containing(const std::vector<PolygonWithHoles>& pieces, const Point2& p) {
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Ring& outer = pieces[i].outer;
    if (outer.size() < 3) continue;
    const Box box = bounding_box(outer);
    if (p.x < box.x0 || p.x > box.x1 || p.y < box.y0 || p.y > box.y1) continue;
    if (contains(pieces[i], p)) return static_cast<int>(i);
  }
  return -1;
}

Segmentation rooms_from_pieces(const OccupancyGrid& grid, const PieceSet& set, const RoomLabelOptions& options) {
  validate(grid);
  return rooms_from_pieces(grid, set, polygon_spans(set.pieces, grid.cells.size()), options);
}

Segmentation rooms_from_pieces(const OccupancyGrid& grid, const PieceSet& set, const std::vector<CellSpan>& spans,
                               const RoomLabelOptions& options) {
  validate(grid);
  const bool cover = options.cover_absorbed_obstacles;
  RoomNumbering numbering = number_by_spans(grid, spans, set.pieces.size(), cover);
  SpanLabels written = write_span_labels(grid, spans, numbering, cover);
  const std::vector<long> filled_first = complete_labels(grid, written, numbering.rooms);
  if (written.overlap) {
    renumber_from_image(written, numbering);
  } else {
    const std::vector<long> true_first =
        true_first_cells(written.labels, spans, set.pieces.size(), numbering, filled_first);
    renumber_by_first_cells(written, numbering, true_first);
  }

  Segmentation s;
  s.labels = written.labels;
  s.resolution = grid.resolution;
  s.origin = grid.origin;
  s.rooms = room_list(grid, set, numbering, written.tally);
  s.passages = passages_between(grid, set, numbering.room_of_piece);
  return s;
}

}  // namespace topocut
