// Which room each piece of a decomposed region becomes: old ids by overlap, splits and merges held
// back, the rooms' polygons and states, and the passages kept at the region's border or found new.
#include "segmentation/incremental/incremental_state.h"
#include "segmentation/passage_kind.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <tuple>
#include <vector>

#include "topocut/map/free_space_polygons.h"
#include "topocut/segmentation/carried_ids.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut {

using namespace incremental;

namespace {

// The room of the region (region_room[id] set) on the other side of an old cut a-b (window
// coordinates) from `outside`, or 0. The region's pieces follow pixel edges while an old cut may
// run diagonally, so the cut's own side test can miss them: look at the labelled cells across the
// cut instead, nearest first.
int region_room_beside(const cv::Mat& labels, const cv::Rect& window, const std::vector<char>& region_room,
                       const Point2& a, const Point2& b, int outside) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length = std::hypot(dx, dy);
  if (!(length > 0.0) || !std::isfinite(length)) return 0;
  const Point2 normal{-dy / length, dx / length};
  for (const double t : {0.5, 0.25, 0.75})
    for (const double k : {0.5, 1.0, 1.5, 2.0, 3.0})
      for (const double side : {1.0, -1.0}) {
        const double x = a.x + t * dx + side * k * normal.x, y = a.y + t * dy + side * k * normal.y;
        const int column = static_cast<int>(std::floor(x + 0.5));
        const int row = window.height - 1 - static_cast<int>(std::floor(y + 0.5));
        if (column < 0 || row < 0 || column >= window.width || row >= window.height) continue;
        const int id = labels.at<int>(window.y + row, window.x + column);
        if (id > 0 && id != outside && region_room[static_cast<std::size_t>(id)]) return id;
      }
  return 0;
}

// A polygon in window grid coordinates, in world metres.
PolygonWithHoles to_world_polygon(const PolygonWithHoles& window_polygon, const WindowFrame& frame) {
  PolygonWithHoles world;
  for (const Point2& v : window_polygon.outer) world.outer.push_back(frame.to_world(v));
  for (const Ring& hole : window_polygon.holes) {
    Ring ring;
    ring.reserve(hole.size());
    for (const Point2& v : hole) ring.push_back(frame.to_world(v));
    world.holes.push_back(std::move(ring));
  }
  return normalized_orientation(world);
}

}  // namespace

// Old ids go to pieces by overlap, largest first (ties by piece, then room), each id to one piece
// and each piece one id: a room cut in two keeps its id on the part sharing the most of its cells,
// which changes the fewest labels. The other pieces get new ids in raster order of their first
// cells, deterministic like batch numbering.
void IncrementalSegmenter::State::match_ids(const Region& region, RegionPieces& found) {
  const PieceTally& t = found.tally;
  const int pieces = found.pieces, n_old = t.n_old;
  struct Candidate {
    long long count;
    int piece;
    int old;
  };
  std::vector<Candidate> candidates;
  for (int p = 1; p <= pieces; ++p)
    for (int j = 0; j < n_old; ++j) {
      const long long count = t.overlap[static_cast<std::size_t>(p) * static_cast<std::size_t>(n_old + 1) + static_cast<std::size_t>(j)];
      if (count > 0) candidates.push_back({count, p, region.ids[static_cast<std::size_t>(j)]});
    }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return std::tie(b.count, a.piece, a.old) < std::tie(a.count, b.piece, b.old);
  });
  std::vector<int>& id_of_piece = found.id_of_piece;
  std::vector<char>& reused = found.reused;
  id_of_piece.assign(static_cast<std::size_t>(pieces) + 1, 0);
  reused.assign(rooms.size(), 0);
  // Pieces touching a partial room's rest are that room, whatever they overlap.
  for (int p = 1; p <= pieces; ++p) {
    const int kept = found.kept_by[static_cast<std::size_t>(p)];
    if (kept == 0) continue;
    id_of_piece[static_cast<std::size_t>(p)] = kept;
    reused[static_cast<std::size_t>(kept)] = 1;
  }
  for (const Candidate& candidate : candidates) {
    if (id_of_piece[static_cast<std::size_t>(candidate.piece)] != 0 || reused[static_cast<std::size_t>(candidate.old)]) continue;
    id_of_piece[static_cast<std::size_t>(candidate.piece)] = candidate.old;
    reused[static_cast<std::size_t>(candidate.old)] = 1;
  }
  hold_back_splits(region, found);
  hold_back_merges(region, found);
  // The other pieces (numbered in raster order of their first cells, as batch numbers rooms) are named
  // by the ledger: back the id of a room that disappeared where the piece lies, else a new one; ids
  // of rooms still alive (those retiring now included) are not given twice.
  std::vector<int> named(id_of_piece.size(), -1);  // -1: has its id, left alone
  for (int p = 1; p <= pieces; ++p)
    if (id_of_piece[static_cast<std::size_t>(p)] == 0 && t.cells[static_cast<std::size_t>(p)] > 0) named[static_cast<std::size_t>(p)] = 0;
  report.new_rooms = ledger.name(region.window, found.local, found.raw, named, [&](int id) {
    return !rooms[static_cast<std::size_t>(id)].alive && !reused[static_cast<std::size_t>(id)];
  });
  for (int p = 1; p <= pieces; ++p)
    if (named[static_cast<std::size_t>(p)] > 0) id_of_piece[static_cast<std::size_t>(p)] = named[static_cast<std::size_t>(p)];
  rooms.resize(static_cast<std::size_t>(ledger.next_id()));
}

// Hysteresis on splits: a piece without an old id that is mostly cut from one old room whose id went
// to a piece across one of the new cuts stays in that room until split_after decompositions in a
// row have cut it off, so that a cut the decomposition finds one scan and drops the next does not
// hand out an id each time. Pieces mostly of newly seen cells, and parts no longer connected to
// the room (a door closed), are new rooms at once.
void IncrementalSegmenter::State::hold_back_splits(const Region& region, RegionPieces& found) {
  const PieceTally& t = found.tally;
  const std::size_t columns = static_cast<std::size_t>(t.n_old) + 1;
  std::vector<std::pair<int, int>> across;  // pieces on the two sides of a passage
  for (const Passage& p : found.rooms.passages) across.emplace_back(p.room_a, p.room_b);
  auto next_to_room = [&](int piece, int id) {
    return std::any_of(across.begin(), across.end(), [&](const std::pair<int, int>& a) {
      return (a.first == piece && a.second > 0 && found.id_of_piece[static_cast<std::size_t>(a.second)] == id) ||
             (a.second == piece && a.first > 0 && found.id_of_piece[static_cast<std::size_t>(a.first)] == id);
    });
  };
  std::vector<char> cut(rooms.size(), 0);
  // Until nothing changes: a piece cut off beyond a held one (a room cut in three) is next to the
  // room once that one holds its id.
  for (bool held = true; held;) {
    held = false;
    for (int p = 1; p <= found.pieces; ++p) {
      const std::size_t piece = static_cast<std::size_t>(p);
      if (found.id_of_piece[piece] != 0 || t.cells[piece] == 0) continue;
      for (int j = 0; j < t.n_old && found.id_of_piece[piece] == 0; ++j) {
        const int old = region.ids[static_cast<std::size_t>(j)];
        if (2 * t.overlap[piece * columns + static_cast<std::size_t>(j)] <= t.cells[piece] ||
            !found.reused[static_cast<std::size_t>(old)] || !next_to_room(p, old))
          continue;
        cut[static_cast<std::size_t>(old)] = 1;
        if (rooms[static_cast<std::size_t>(old)].split_votes + 1 < options.split_after) {
          found.id_of_piece[piece] = old;
          held = true;
        }
      }
    }
  }
  for (const int id : region.ids) {
    RoomState& room = rooms[static_cast<std::size_t>(id)];
    room.split_votes = cut[static_cast<std::size_t>(id)] && room.split_votes + 1 < options.split_after ? room.split_votes + 1 : 0;
  }
}

// Hysteresis on merges, the mirror of hold_back_splits: an old room whose id went to no piece while
// most of its cells went to a piece that keeps another old room's id (the merging stage joined
// them) keeps its id and those cells until merge_after decompositions in a row have merged it.
// The pair is then decomposed together (add_neighbour_rooms), so every decomposition votes.
void IncrementalSegmenter::State::hold_back_merges(const Region& region, RegionPieces& found) {
  const PieceTally& t = found.tally;
  const std::size_t columns = static_cast<std::size_t>(t.n_old) + 1;
  found.held_piece.assign(rooms.size(), 0);
  std::vector<int> partner(rooms.size(), 0);  // by old id: merged into this room in this decomposition
  for (int j = 0; j < t.n_old; ++j) {
    const int old = region.ids[static_cast<std::size_t>(j)];
    if (found.reused[static_cast<std::size_t>(old)]) continue;
    int best = 0;
    for (int p = 1; p <= found.pieces; ++p)
      if (t.overlap[static_cast<std::size_t>(p) * columns + static_cast<std::size_t>(j)] >
          (best == 0 ? 0 : t.overlap[static_cast<std::size_t>(best) * columns + static_cast<std::size_t>(j)]))
        best = p;
    if (best == 0 || found.id_of_piece[static_cast<std::size_t>(best)] == 0) continue;
    // Mostly carried over whole: a room carved up between pieces is no merge to hold back.
    if (2 * t.overlap[static_cast<std::size_t>(best) * columns + static_cast<std::size_t>(j)] <= rooms[static_cast<std::size_t>(old)].cells)
      continue;
    partner[static_cast<std::size_t>(old)] = found.id_of_piece[static_cast<std::size_t>(best)];
    if (rooms[static_cast<std::size_t>(old)].merge_votes + 1 < options.merge_after) {
      found.held_piece[static_cast<std::size_t>(old)] = best;
      found.reused[static_cast<std::size_t>(old)] = 1;
      found.held.push_back({old});
    }
  }
  for (const int id : region.ids) {
    RoomState& room = rooms[static_cast<std::size_t>(id)];
    const bool hold = found.held_piece[static_cast<std::size_t>(id)] != 0;
    room.merge_votes = hold ? room.merge_votes + 1 : 0;
    room.merge_partner = hold ? partner[static_cast<std::size_t>(id)] : 0;
  }
}

// Old rooms of the region die unless reused, and every cell of the region takes its piece's id
// (a room holding back a merge keeps its own, and found.held counts them). Returns the dead rooms.
std::vector<int> IncrementalSegmenter::State::retire_old_rooms(const Region& region, RegionPieces& found) {
  const cv::Rect& window = region.window;
  std::vector<int> removed;
  for (const int id : region.ids)
    if (!found.reused[static_cast<std::size_t>(id)]) {
      rooms[static_cast<std::size_t>(id)] = RoomState{};
      removed.push_back(id);
    }
  report.removed_rooms = static_cast<int>(removed.size());
  // A room holding back a merge keeps its cells in the piece it was merged into (held_piece is 0,
  // no piece, for every other room).
  std::vector<int> held_index(found.held_piece.size(), -1);
  for (std::size_t h = 0; h < found.held.size(); ++h) held_index[static_cast<std::size_t>(found.held[h].id)] = static_cast<int>(h);
  for_each_region_run(window, result.labels, found, [&](int gr, int gc, int end, int old, int piece) {
    if (old > 0 && !found.reused[static_cast<std::size_t>(old)]) ledger.retire(gr, gc, end, old);
    if (old > 0 && found.held_piece[static_cast<std::size_t>(old)] == piece) {
      RegionPieces::HeldCells& h = found.held[static_cast<std::size_t>(held_index[static_cast<std::size_t>(old)])];
      const long long n = end - gc;
      const int last = end - 1;
      h.cells += n;
      h.sum_c += n * (gc + last) / 2;  // n * (gc + last) is even
      h.sum_r += n * gr;
      h.min_c = std::min(h.min_c, gc);
      h.max_c = std::max(h.max_c, last);
      h.min_r = std::min(h.min_r, gr);
      h.max_r = std::max(h.max_r, gr);
    } else {
      int* l = result.labels.ptr<int>(gr);
      const int id = found.id_of_piece[static_cast<std::size_t>(piece)];
      if (id != old) {  // a room whose every run keeps its id keeps its cells
        if (old > 0) relabelled.push_back(old);
        if (id > 0) relabelled.push_back(id);
      }
      std::fill(l + gc, l + end, id);
    }
  });
  return removed;
}

// Every piece that labels a cell belongs to a live room, its state rebuilt from its pieces' cells
// alone (nothing absorbed since) and its polygon, in world metres, that of its largest piece (a
// room holding back a split has two).
void IncrementalSegmenter::State::adopt_pieces(const RegionPieces& found) {
  const PieceTally& t = found.tally;
  std::vector<int> largest(rooms.size(), 0);  // by id: its piece with the most cells
  for (int p = 1; p <= found.pieces; ++p) {
    const std::size_t piece = static_cast<std::size_t>(p);
    if (t.cells[piece] == 0) continue;
    const std::size_t id = static_cast<std::size_t>(found.id_of_piece[piece]);
    RoomState& room = rooms[id];
    const cv::Rect box(t.min_c[piece], t.min_r[piece], t.max_c[piece] - t.min_c[piece] + 1, t.max_r[piece] - t.min_r[piece] + 1);
    if (largest[id] == 0) {
      // A partial room starts from its cells outside the window and keeps its box.
      const RegionPieces::Remainder* rest = found.remainder(static_cast<int>(id));
      room.alive = true;
      room.cells = rest != nullptr ? rest->cells : 0;
      room.sum_c = rest != nullptr ? rest->sum_c : 0.0;
      room.sum_r = rest != nullptr ? rest->sum_r : 0.0;
      room.absorbed = 0;
      room.box = rest != nullptr ? room.box | box : box;
    }
    room.cells += t.cells[piece];
    room.sum_c += static_cast<double>(t.sum_c[piece]);
    room.sum_r += static_cast<double>(t.sum_r[piece]);
    room.box |= box;
    if (largest[id] == 0 || t.cells[piece] > t.cells[static_cast<std::size_t>(largest[id])]) largest[id] = p;
  }
  for (std::size_t id = 1; id < rooms.size(); ++id) {
    if (largest[id] == 0 || found.remainder(static_cast<int>(id)) != nullptr) continue;  // traced later
    rooms[id].whole_cells = rooms[id].cells;
    refresh_room(static_cast<int>(id), &found.rooms.rooms[static_cast<std::size_t>(largest[id]) - 1].polygon);
  }
}

// A room holding back a merge is what is left of it in its partner's piece: cells, sums and box
// move from the partner to it; it keeps its polygon and the partner's is traced from the partner's
// own cells of that piece (the piece's outline would cover both).
void IncrementalSegmenter::State::adopt_held_rooms(const RegionPieces& found, const WindowFrame& frame) {
  for (const RegionPieces::HeldCells& h : found.held) {
    RoomState& room = rooms[static_cast<std::size_t>(h.id)];
    const int piece = found.held_piece[static_cast<std::size_t>(h.id)];
    const int partner_id = found.id_of_piece[static_cast<std::size_t>(piece)];
    RoomState& partner = rooms[static_cast<std::size_t>(partner_id)];
    room.alive = true;
    room.cells = h.cells;
    room.sum_c = static_cast<double>(h.sum_c);
    room.sum_r = static_cast<double>(h.sum_r);
    room.box = cv::Rect(h.min_c, h.min_r, h.max_c - h.min_c + 1, h.max_r - h.min_r + 1);
    room.absorbed = 0;
    partner.cells -= h.cells;
    partner.sum_c -= static_cast<double>(h.sum_c);
    partner.sum_r -= static_cast<double>(h.sum_r);
    refresh_room(h.id, nullptr);
    // The partner's polygon is that of its largest piece (adopt_pieces): only if that is this piece
    // does it cover the held room's cells.
    int partner_piece = 0;
    for (int p = 1; p <= found.pieces; ++p)
      if (found.id_of_piece[static_cast<std::size_t>(p)] == partner_id &&
          (partner_piece == 0 || found.tally.cells[static_cast<std::size_t>(p)] > found.tally.cells[static_cast<std::size_t>(partner_piece)]))
        partner_piece = p;
    if (partner.cells <= 0 || partner_piece != piece || found.remainder(partner_id) != nullptr) continue;
    const cv::Rect& window = frame.window;
    cv::Mat own(window.size(), CV_8UC1);
    for (int r = 0; r < window.height; ++r) {
      const int* l = result.labels.ptr<int>(window.y + r) + window.x;
      const int* k = found.local.ptr<int>(r);
      unsigned char* out = own.ptr<unsigned char>(r);
      for (int c = 0; c < window.width; ++c) out[c] = k[c] == piece && l[c] == partner_id ? 255 : 0;
    }
    const std::vector<FreeSpaceComponent> parts = trace_components(remove_diagonal_pinches(own));
    const auto largest = std::max_element(parts.begin(), parts.end(), [](const FreeSpaceComponent& a, const FreeSpaceComponent& b) {
      return a.pixel_count < b.pixel_count;
    });
    if (largest == parts.end()) continue;
    PolygonWithHoles world = to_world_polygon(largest->polygon, frame);
    refresh_room(partner_id, &world);
  }
}

// A partial room's polygon is traced from its cells (the rest and the pieces it kept), the largest
// part, over its old polygon's box and the region's window (its box also reaches the free specks
// labelled from it far away, which are no part of its outline).
void IncrementalSegmenter::State::trace_partial_rooms(const RegionPieces& found, const cv::Rect& window,
                                                      const std::vector<cv::Rect>& outline_boxes) {
  for (std::size_t k = 0; k < found.remainders.size(); ++k) {
    const int id = found.remainders[k].id;
    const cv::Rect box = (outline_boxes[k] | window) & rooms[static_cast<std::size_t>(id)].box;
    const cv::Mat own = result.labels(box) == id;
    const std::vector<FreeSpaceComponent> parts = trace_components(remove_diagonal_pinches(own));
    const auto largest = std::max_element(parts.begin(), parts.end(), [](const FreeSpaceComponent& a, const FreeSpaceComponent& b) {
      return a.pixel_count < b.pixel_count;
    });
    if (largest == parts.end()) continue;
    const WindowFrame frame = window_frame(box);
    const PolygonWithHoles world = to_world_polygon(largest->polygon, frame);
    refresh_room(id, &world);
  }
}

// The cells under a room's polygon's box (before the update), for trace_partial_rooms.
cv::Rect IncrementalSegmenter::State::outline_box(int id) const {
  auto it = std::lower_bound(result.rooms.begin(), result.rooms.end(), id,
                             [](const Room& room, int value) { return room.id < value; });
  if (it == result.rooms.end() || it->id != id || it->polygon.outer.empty()) return rooms[static_cast<std::size_t>(id)].box;
  const Box b = bounding_box(it->polygon.outer);
  const int rows = result.labels.rows;
  const int c0 = static_cast<int>(std::floor((b.x0 - origin.x) / resolution)) - 1;
  const int c1 = static_cast<int>(std::ceil((b.x1 - origin.x) / resolution)) + 1;
  const int r0 = rows - static_cast<int>(std::ceil((b.y1 - origin.y) / resolution)) - 1;
  const int r1 = rows - static_cast<int>(std::floor((b.y0 - origin.y) / resolution)) + 1;
  return cv::Rect(c0, r0, c1 - c0, r1 - r0) & cv::Rect(0, 0, result.labels.cols, rows);
}

// Old passages outside the region stay as they were; one crossing its border keeps its outside
// room and finds its inside one again (dropped if none); those inside it are gone.
void IncrementalSegmenter::State::keep_border_passages(const Region& region, const RegionPieces& found,
                                                       const WindowFrame& frame, PassageList& out) const {
  std::vector<char> region_room(rooms.size(), 0);
  for (int p = 1; p <= found.pieces; ++p)
    if (found.tally.cells[static_cast<std::size_t>(p)] > 0)
      region_room[static_cast<std::size_t>(found.id_of_piece[static_cast<std::size_t>(p)])] = 1;
  // A partial room's cut is in the region when its middle lies near the change.
  const OccupancyGrid map_frame{cells, resolution, origin};  // the whole map, for world_to_cell
  auto in_region = [&](int id, const Segment2& cut) {
    const char member = region.member[static_cast<std::size_t>(id)];
    if (member != kPartial) return member != 0;
    const Point2 middle{0.5 * (cut.a.x + cut.b.x), 0.5 * (cut.a.y + cut.b.y)};
    return region.near_change.contains(world_to_cell(map_frame, middle));
  };
  for (std::size_t k = 0; k < result.passages.size(); ++k) {
    const Passage& passage = result.passages[k];
    const bool a_in = in_region(passage.room_a, passage.cut);
    const bool b_in = in_region(passage.room_b, passage.cut);
    if (!a_in && !b_in) {
      out.passages.push_back(passage);
      continue;
    }
    if (a_in && b_in) {
      // The cut between a room holding back a merge and its partner still parts their cells.
      const int a = passage.room_a, b = passage.room_b;
      if (rooms[static_cast<std::size_t>(a)].merge_partner == b || rooms[static_cast<std::size_t>(b)].merge_partner == a) {
        out.passages.push_back(passage);
        }
      continue;
    }
    const int outside = a_in ? passage.room_b : passage.room_a;
    const int inside = region_room_beside(result.labels, region.window, region_room, frame.to_window(passage.cut.a),
                                          frame.to_window(passage.cut.b), outside);
    if (inside == 0) continue;
    Passage kept = passage;
    kept.room_a = std::min(inside, outside);
    kept.room_b = std::max(inside, outside);
    out.passages.push_back(kept);
  }
}

// Every passage of the new decomposition between two different rooms (a held split's pieces share
// one) stays, with the rooms' ids.
void IncrementalSegmenter::State::add_new_passages(const RegionPieces& found, PassageList& out) const {
  for (Passage passage : found.rooms.passages) {
    const int a = found.id_of_piece[static_cast<std::size_t>(passage.room_a)];
    const int b = found.id_of_piece[static_cast<std::size_t>(passage.room_b)];
    if (a == 0 || b == 0 || a == b) continue;
    passage.room_a = std::min(a, b);
    passage.room_b = std::max(a, b);
    out.passages.push_back(passage);
  }
}

// Window grid coordinates of window against the map's world frame.
WindowFrame IncrementalSegmenter::State::window_frame(const cv::Rect& window) const {
  return WindowFrame{origin, resolution, window, static_cast<double>(result.labels.rows - window.height - window.y)};
}

// result.passages in one order whatever the update history: by rooms, then cut, then as found.
void IncrementalSegmenter::State::store_sorted(const PassageList& list) {
  const std::vector<Passage>& passages = list.passages;
  std::vector<std::size_t> order(passages.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    const Passage& x = passages[i];
    const Passage& y = passages[j];
    return std::tie(x.room_a, x.room_b, x.cut.a.x, x.cut.a.y, x.cut.b.x, x.cut.b.y, i) <
           std::tie(y.room_a, y.room_b, y.cut.a.x, y.cut.a.y, y.cut.b.x, y.cut.b.y, j);
  });
  result.passages.clear();
  for (const std::size_t k : order) result.passages.push_back(passages[k]);
}

}  // namespace topocut
