// Which rooms an update decomposes again and how: the touched rooms, their neighbours across
// passages, large rooms only near the change (partial_area), isolated specks to the nearest room.
#include "segmentation/incremental/incremental_state.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/map/binarize.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/map/rasterize.h"
#include "topocut/segmentation/open_rooms.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut {

using namespace incremental;

namespace {

// 4-connected parts of mask (nonzero) that hold a cell of ring.
int parts_reaching(const cv::Mat& mask, const cv::Mat& ring) {
  cv::Mat components;
  const int n = cv::connectedComponents(mask, components, 4, CV_32S);
  std::vector<char> reaches(static_cast<std::size_t>(n), 0);
  for (int r = 0; r < mask.rows; ++r) {
    const int* p = components.ptr<int>(r);
    const unsigned char* g = ring.ptr<unsigned char>(r);
    for (int c = 0; c < mask.cols; ++c)
      if (g[c]) reaches[static_cast<std::size_t>(p[c])] = 1;
  }
  return static_cast<int>(std::count(reaches.begin() + 1, reaches.end(), 1));
}

// One pass over the region: every piece's overlap with every old room of the region, its cell
// count, first cell, coordinate sums and bounding box. A free cell of the region without a piece
// is a broken decomposition: thrown, never labelled 0.
PieceTally tally_pieces(const cv::Mat& labels, const RegionPieces& found, const Region& region) {
  const cv::Rect& window = region.window;
  const std::vector<int>& region_ids = region.ids;
  PieceTally t;
  const int n_old = static_cast<int>(region_ids.size());
  t.n_old = n_old;
  std::vector<int> old_index(region.member.size(), -1);
  for (int j = 0; j < n_old; ++j) old_index[static_cast<std::size_t>(region_ids[static_cast<std::size_t>(j)])] = j;
  const std::size_t slots = static_cast<std::size_t>(found.pieces) + 1;
  t.overlap.assign(slots * static_cast<std::size_t>(n_old + 1), 0);  // column n_old: pending
  t.cells.assign(slots, 0);
  t.first_cell.assign(slots, LLONG_MAX);
  t.sum_c.assign(slots, 0);
  t.sum_r.assign(slots, 0);
  t.min_c.assign(slots, INT_MAX);
  t.max_c.assign(slots, -1);
  t.min_r.assign(slots, INT_MAX);
  t.max_r.assign(slots, -1);
  for_each_region_run(window, labels, found, [&](int gr, int gc, int end, int old, int piece) {
    if (piece <= 0) throw Error("internal: a free cell of the re-decomposed region got no room");
    const long long n = end - gc;
    const int last = end - 1;
    const std::size_t p = static_cast<std::size_t>(piece);
    if (t.cells[p] == 0) t.first_cell[p] = static_cast<long long>(gr - window.y) * window.width + (gc - window.x);
    t.cells[p] += n;
    const int j = old > 0 ? old_index[static_cast<std::size_t>(old)] : n_old;
    t.overlap[p * static_cast<std::size_t>(n_old + 1) + static_cast<std::size_t>(j)] += n;
    t.sum_c[p] += n * (gc + last) / 2;  // n * (gc + last) is even
    t.sum_r[p] += n * gr;
    t.min_c[p] = std::min(t.min_c[p], gc);
    t.max_c[p] = std::max(t.max_c[p], last);
    t.min_r[p] = std::min(t.min_r[p], gr);
    t.max_r[p] = std::max(t.max_r[p], gr);
  });
  return t;
}

}  // namespace

// Decomposes again the free cells of the rooms in region plus the pending cells in its window, with
// the batch stages, and gives the pieces ids (match_ids). Updates labels, room states,
// result.rooms and passages. Returns false, changing no room, when the region's rooms keep no free
// space to decompose: the whole map must be segmented again.
bool IncrementalSegmenter::State::redecompose(Region region, std::vector<int>& touched_rooms) {
  add_neighbour_rooms(region);
  frame_region(region);
  RegionPieces found;
  while (!decompose_partially(region, found)) decompose_whole(region);
  if (found.pieces == 0) {
    if (!region.ids.empty()) return false;
    // Newly labelled cells of a blob that holds no room (thinner than the opening, smaller than a
    // room): they take the nearest room's label, as in segment().
    std::vector<int> pending;
    cv::Mat& labels = result.labels;
    for (int r = region.window.y; r < region.window.y + region.window.height; ++r) {
      int* l = labels.ptr<int>(r);
      for (int c = region.window.x; c < region.window.x + region.window.width; ++c)
        if (l[c] == kPending) {
          l[c] = 0;
          pending.push_back(r * labels.cols + c);
        }
    }
    label_from_nearest_rooms(pending, touched_rooms);
    return true;
  }
  report_region(region, found.region_cells);
  const cv::Rect& window = region.window;

  std::vector<cv::Rect> outline_boxes;  // taken before refresh_room replaces the polygons
  for (const RegionPieces::Remainder& rest : found.remainders) outline_boxes.push_back(outline_box(rest.id));
  const std::vector<int> removed = retire_old_rooms(region, found);
  const WindowFrame frame = window_frame(window);
  for (const int id : removed) refresh_room(id, nullptr);
  adopt_pieces(found);
  adopt_held_rooms(found, frame);
  trace_partial_rooms(found, window, outline_boxes);
  // Rooms absorbed into this decomposition are refreshed here; the caller must not revive them.
  touched_rooms.erase(std::remove_if(touched_rooms.begin(), touched_rooms.end(),
                                     [&](int id) { return region.member[static_cast<std::size_t>(id)] != 0; }),
                      touched_rooms.end());

  // Passages: cuts on the region's border keep their outside room and find their inside one again;
  // cuts inside the region are replaced by the new decomposition's cuts.
  PassageList list;
  list.passages.reserve(result.passages.size() + found.rooms.passages.size());
  keep_border_passages(region, found, frame, list);
  add_new_passages(found, list);
  store_sorted(list);
  return true;
}

// The rooms next to the region go with it (one ring, through the passages): batch decides on
// the cuts between them again when it finds doors and merges pieces into rooms, and can only do
// so with both sides in view. A door found while one side was only partly seen (or cut short by
// the region's border) is not final, hence doors too unless options say otherwise.
void IncrementalSegmenter::State::add_neighbour_rooms(Region& region) const {
  std::vector<int>& region_ids = region.ids;
  std::vector<char>& in_region = region.member;
  in_region.assign(rooms.size(), 0);
  for (const int id : region_ids) in_region[static_cast<std::size_t>(id)] = 1;
  const std::size_t core = region_ids.size();
  for (std::size_t k = 0; k < result.passages.size(); ++k) {
    if (!(is_door_rule(result.passages[k].rule) ? options.neighbours_across_doors : options.neighbours_across_cuts)) continue;
    const Passage& p = result.passages[k];
    const bool a_in = in_region[static_cast<std::size_t>(p.room_a)] != 0;
    const bool b_in = in_region[static_cast<std::size_t>(p.room_b)] != 0;
    if (a_in == b_in) continue;
    const int other = a_in ? p.room_b : p.room_a;
    if (std::find(region_ids.begin() + static_cast<std::ptrdiff_t>(core), region_ids.end(), other) == region_ids.end())
      region_ids.push_back(other);
  }
  for (std::size_t k = core; k < region_ids.size(); ++k) in_region[static_cast<std::size_t>(region_ids[k])] = kWhole;
  // A room holding back a merge and its partner are decomposed together, so that each of their
  // decompositions votes on the merge.
  for (std::size_t id = 1; id < rooms.size(); ++id) {
    const int partner = rooms[id].merge_partner;
    if (!rooms[id].alive || partner == 0 || !rooms[static_cast<std::size_t>(partner)].alive ||
        in_region[id] == in_region[static_cast<std::size_t>(partner)])
      continue;
    const int missing = in_region[id] ? partner : static_cast<int>(id);
    in_region[static_cast<std::size_t>(missing)] = kWhole;
    region_ids.push_back(missing);
  }
}

// The region's window: the change and every room of the region, except that a room larger than
// partial_area whose box lies mostly beyond partial_margin of the change takes part only with its
// cells near the change (Region::near_change), so that a long corridor costs what the change costs.
// Pieces touching a partial room's rest join it, so that a partial decomposition never cuts it: a room
// that has grown by partial_area since it was last decomposed whole, or that holds back a split (every
// decomposition votes on it), is decomposed whole, as segment() would cut it.
void IncrementalSegmenter::State::frame_region(Region& region) const {
  const cv::Rect change = region.window;
  if (options.partial_area > 0.0 && !change.empty()) {
    const int margin = static_cast<int>(std::ceil(options.partial_margin / resolution));
    region.near_change = grown(change, margin, cells.size());
    const double cell_area = resolution * resolution;
    for (const int id : region.ids) {
      const RoomState& room = rooms[static_cast<std::size_t>(id)];
      // Worth it only when the window leaves out most of the room's box.
      if (static_cast<double>(room.cells) * cell_area > options.partial_area &&
          2 * (room.box & region.near_change).area() < room.box.area() && room.split_votes == 0 &&
          static_cast<double>(room.cells - room.whole_cells) * cell_area <= options.partial_area)
        region.member[static_cast<std::size_t>(id)] = kPartial;
    }
  }
  for (const int id : region.ids) {
    const cv::Rect& box = rooms[static_cast<std::size_t>(id)].box;
    region.window = unite(region.window, region.member[static_cast<std::size_t>(id)] == kPartial ? box & region.near_change : box);
  }
  // A frame of cells around the region as they are: the open-room rule reads the outline's far side,
  // and a window's edge would read as never-seen space.
  region.window = grown(region.window, 1, cells.size());
}

// Decomposes the region and gives its pieces ids (match_ids). Returns false, changing no room,
// when a partial room could not keep its id on its rest: it must then be decomposed whole.
bool IncrementalSegmenter::State::decompose_partially(Region& region, RegionPieces& found) {
  found = decompose_region(region);
  if (found.pieces == 0) return true;  // nothing to decompose: redecompose() decides
  if (!find_kept_pieces(region, found)) return false;
  found.tally = tally_pieces(result.labels, found, region);
  if (!kept_pieces_are_mostly_theirs(region, found)) return false;
  const bool partial = std::find(region.member.begin(), region.member.end(), kPartial) != region.member.end();
  if (!partial) {
    match_ids(region, found);
    return true;
  }
  // match_ids votes on held splits and merges and hands out ids: undone if the trial fails.
  const std::vector<RoomState> saved_rooms = rooms;
  const IdLedger saved_ledger = ledger;  // only its next id changes here
  const IncrementalUpdateReport saved_report = report;
  match_ids(region, found);
  if (partial_rooms_hold_together(region, found)) return true;
  rooms = saved_rooms;
  ledger = saved_ledger;
  report = saved_report;
  return false;
}

// Every partial room of the region takes part with all its cells from now on.
void IncrementalSegmenter::State::decompose_whole(Region& region) const {
  for (const int id : region.ids) {
    char& member = region.member[static_cast<std::size_t>(id)];
    if (member != kPartial) continue;
    member = kWhole;
    region.window = unite(region.window, rooms[static_cast<std::size_t>(id)].box);
  }
}

// The region's cells to label (raw) and the decomposition of its floor into pieces, in window grid
// coordinates, with the open-room rule applied to the pieces as segment() applies it to all of them.
// The floor is that of the region's rooms and pending cells, with the obstacle specks that count as
// floor (no room's cells).
RegionPieces IncrementalSegmenter::State::decompose_region(const Region& region) const {
  const cv::Mat& labels = result.labels;
  const std::vector<char>& in_region = region.member;
  const cv::Rect& window = region.window;
  RegionPieces found;
  cv::Mat& raw = found.raw;
  raw.create(window.size(), CV_8UC1);
  cv::Mat region_floor(window.size(), CV_8UC1);
  // member[id + 1]: 255 if cells labelled id are in the region (kPending = -1 always is), 128 if
  // only those near the change are (a partial room).
  std::vector<unsigned char> member(rooms.size() + 1, 0);
  member[0] = 255;
  for (std::size_t id = 1; id < rooms.size(); ++id)
    member[id + 1] = in_region[id] == kWhole ? 255 : in_region[id] == kPartial ? 128 : 0;
  const unsigned char* lut = member.data() + 1;
  const cv::Rect& near = region.near_change;
  for (int r = 0; r < window.height; ++r) {
    const int* l = labels.ptr<int>(window.y + r) + window.x;
    const unsigned char* f = floor.ptr<unsigned char>(window.y + r) + window.x;
    unsigned char* out_raw = raw.ptr<unsigned char>(r);
    unsigned char* out_floor = region_floor.ptr<unsigned char>(r);
    const bool near_row = window.y + r >= near.y && window.y + r < near.y + near.height;
    // Cells [begin, end) of one label, in the region or not: the floor there is the region's when
    // they are in it or in no room (obstacle specks), else none of it.
    auto fill = [&](int begin, int end, unsigned char in, int label) {
      std::memset(out_raw + begin, in, static_cast<std::size_t>(end - begin));
      if (label == 0 || in != 0) std::memcpy(out_floor + begin, f + begin, static_cast<std::size_t>(end - begin));
      else std::memset(out_floor + begin, 0, static_cast<std::size_t>(end - begin));
      if (in != 0) found.region_cells += end - begin;
    };
    for (int c = 0; c < window.width;) {  // run by run of equal labels (>= kPending)
      const int label = l[c];
      int end = c + 1;
      while (end < window.width && l[end] == label) ++end;
      if (lut[label] == 128) {  // a partial room: its cells within near only
        const int n0 = near_row ? std::clamp(near.x - window.x, c, end) : end;
        const int n1 = near_row ? std::clamp(near.x + near.width - window.x, n0, end) : end;
        fill(c, n0, 0, label);
        fill(n0, n1, 255, label);
        fill(n1, end, 0, label);
      } else {
        fill(c, end, lut[label], label);
      }
      c = end;
    }
  }
  if (cv::countNonZero(region_floor) == 0) {
    found.local = cv::Mat::zeros(window.size(), CV_32SC1);
    return found;
  }
  // segment()'s stages over the window (segment_input), labelling the region's cells only.
  SegmentationInput input;
  input.floor = region_floor;
  input.labelled = OccupancyGrid{labelled(window), resolution, {}};
  const WindowFrame frame = window_frame(window);
  input.labelled.origin = frame.to_world(Point2{-0.5, -0.5});
  found.rooms = segment_input(input, options.segment, raw);
  found.local = found.rooms.labels;
  found.pieces = static_cast<int>(found.rooms.rooms.size());
  return found;
}

// A partial room keeps its id on every piece touching its cells outside near_change across the
// window's edge (found.kept_by). Returns false when a piece touches two partial rooms or a partial
// room touches none.
bool IncrementalSegmenter::State::find_kept_pieces(const Region& region, RegionPieces& found) const {
  found.kept_by.assign(static_cast<std::size_t>(found.pieces) + 1, 0);
  const cv::Rect& near = region.near_change;
  const cv::Rect& window = region.window;
  const cv::Mat& labels = result.labels;
  bool ok = true;
  // A cell of a partial room outside near next to one of its cells inside: that one's piece joins it.
  auto touch = [&](int out_r, int out_c, int in_r, int in_c) {
    if (out_r < 0 || out_c < 0 || out_r >= labels.rows || out_c >= labels.cols) return;
    const int id = labels.at<int>(out_r, out_c);
    if (id <= 0 || region.member[static_cast<std::size_t>(id)] != kPartial || labels.at<int>(in_r, in_c) != id) return;
    const int piece = found.local.at<int>(in_r - window.y, in_c - window.x);
    int& kept = found.kept_by[static_cast<std::size_t>(std::max(piece, 0))];
    ok = ok && piece > 0 && (kept == 0 || kept == id);
    kept = id;
  };
  for (int c = near.x; c < near.x + near.width; ++c) {
    touch(near.y - 1, c, near.y, c);
    touch(near.y + near.height, c, near.y + near.height - 1, c);
  }
  for (int r = near.y; r < near.y + near.height; ++r) {
    touch(r, near.x - 1, r, near.x);
    touch(r, near.x + near.width, r, near.x + near.width - 1);
  }
  for (std::size_t id = 1; id < rooms.size() && ok; ++id)
    ok = region.member[id] != kPartial ||
         std::find(found.kept_by.begin(), found.kept_by.end(), static_cast<int>(id)) != found.kept_by.end();
  return ok;
}

// A piece kept by a partial room holds no more cells of another old room than of it: else that
// room would be merged into it only because the window's edge left no cut between them.
bool IncrementalSegmenter::State::kept_pieces_are_mostly_theirs(const Region& region, const RegionPieces& found) const {
  const PieceTally& t = found.tally;
  const std::size_t columns = static_cast<std::size_t>(t.n_old) + 1;
  std::vector<int> column(rooms.size(), -1);
  for (int j = 0; j < t.n_old; ++j) column[static_cast<std::size_t>(region.ids[static_cast<std::size_t>(j)])] = j;
  for (int p = 1; p <= found.pieces; ++p) {
    const int kept = found.kept_by[static_cast<std::size_t>(p)];
    if (kept == 0) continue;
    const long long* overlap = &t.overlap[static_cast<std::size_t>(p) * columns];
    const long long own = overlap[column[static_cast<std::size_t>(kept)]];
    for (int j = 0; j < t.n_old; ++j)
      if (overlap[j] > own) return false;
  }
  return true;
}

// After match_ids: each partial room must hold together where the window cut it. Looked at in
// near_change and the ring of cells around it, its parts that reach its cells on the ring must be
// no more after than before (a corridor crossing the window and cut in it would fall apart; parts
// may still join outside, so this errs towards decomposing the whole room). Tallies the room's
// cells outside near_change in found.remainders.
bool IncrementalSegmenter::State::partial_rooms_hold_together(const Region& region, RegionPieces& found) const {
  found.remainders.clear();
  const cv::Rect& near = region.near_change;
  const cv::Rect& window = region.window;
  const cv::Mat& labels = result.labels;
  const cv::Rect area = grown(near, 1, labels.size());
  for (const int id : region.ids) {
    if (region.member[static_cast<std::size_t>(id)] != kPartial) continue;
    const RoomState& room = rooms[static_cast<std::size_t>(id)];
    RegionPieces::Remainder rest{id, room.cells, room.sum_c, room.sum_r};
    cv::Mat before = cv::Mat::zeros(area.size(), CV_8UC1), after = before.clone(), ring = before.clone();
    for (int r = 0; r < area.height; ++r) {
      const int gr = area.y + r;
      const int* l = labels.ptr<int>(gr) + area.x;
      const bool near_row = gr >= near.y && gr < near.y + near.height;
      const bool window_row = gr >= window.y && gr < window.y + window.height;
      const int* k = window_row ? found.local.ptr<int>(gr - window.y) : nullptr;
      const unsigned char* in = window_row ? found.raw.ptr<unsigned char>(gr - window.y) : nullptr;
      unsigned char* b = before.ptr<unsigned char>(r);
      unsigned char* a = after.ptr<unsigned char>(r);
      unsigned char* g = ring.ptr<unsigned char>(r);
      for (int c = 0; c < area.width; ++c) {
        const int gc = area.x + c;
        const bool inside = near_row && gc >= near.x && gc < near.x + near.width;
        b[c] = l[c] == id ? 255 : 0;
        if (!inside) {
          a[c] = g[c] = b[c];
          continue;
        }
        if (b[c]) {  // in the region: leaves the rest
          --rest.cells;
          rest.sum_c -= gc;
          rest.sum_r -= gr;
        }
        const int wc = gc - window.x;  // the room's cells in near are all in the window
        a[c] = window_row && wc >= 0 && wc < window.width && in[wc] && k[wc] > 0 &&
                       found.id_of_piece[static_cast<std::size_t>(k[wc])] == id ? 255 : 0;
      }
    }
    found.remainders.push_back(rest);
    if (parts_reaching(after, ring) > parts_reaching(before, ring)) return false;
  }
  return true;
}

// The report names the region as finally decomposed, and calls it batch when it took every room.
void IncrementalSegmenter::State::report_region(const Region& region, int region_cells) {
  report.region = region.window;
  report.region_cells = region_cells;
  report.redecomposed_rooms = static_cast<int>(region.ids.size());
  report.partial_rooms = static_cast<int>(std::count(region.member.begin(), region.member.end(), kPartial));
  bool every_room = !region.ids.empty();
  for (std::size_t id = 1; id < rooms.size() && every_room; ++id) every_room = !rooms[id].alive || region.member[id] == kWhole;
  if (every_room) {
    report.kind = IncrementalUpdateReport::Kind::kBatch;
    report.reason = "the change touched every room";
  }
}

}  // namespace topocut
