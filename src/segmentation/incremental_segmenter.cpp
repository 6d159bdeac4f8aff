#include "topocut/segmentation/incremental_segmenter.h"

#include "segmentation/passage_kind.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <tuple>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/map/binarize.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/map/rasterize.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut {

namespace {

// Label of a newly free cell that waits, within one update, for the room it will belong to.
constexpr int kPending = -1;

// Bits of the change mask: how a cell's free space changed.
constexpr unsigned char kGained = 1;    // not free before, free now
constexpr unsigned char kLost = 2;      // free before, not free now
constexpr unsigned char kReshaped = 4;  // free in both, but its binarized state changed

struct RoomState {
  bool alive = false;
  cv::Rect box;              // contains every cell of the room (may be larger after it lost cells)
  long long cells = 0;
  double sum_c = 0.0;        // sums of the column and row indices of its cells, for the centroid
  double sum_r = 0.0;
  long long absorbed = 0;    // cells joined without a decomposition since the last one
  int split_votes = 0;       // decompositions in a row that cut a piece off this room (held back)
  int merge_votes = 0;       // decompositions in a row that merged this room into merge_partner (held back)
  int merge_partner = 0;     // the room it is held apart from (0: none); decomposed together
};

bool trivial_binarization(const BinarizeOptions& b) {
  return b.robot_radius == 0.0 && b.opening_size == 0.0 && b.median_size == 0.0;
}

// How far (cells) a changed cell can change the binarized free space: inflation radius, opening
// and median windows, plus slack for rounding.
int binarization_reach(const BinarizeOptions& b, double resolution) {
  if (trivial_binarization(b)) return 0;
  int reach = 2;
  if (b.robot_radius > 0.0) reach += static_cast<int>(std::ceil(b.robot_radius / resolution)) + 1;
  if (b.opening_size > 0.0) reach += static_cast<int>(std::lround(b.opening_size / resolution)) + 1;
  if (b.median_size > 0.0) reach += static_cast<int>(std::lround(b.median_size / resolution)) / 2 + 2;
  return reach;
}

cv::Rect grown(const cv::Rect& r, int margin, const cv::Size& size) {
  if (r.empty()) return r;
  return cv::Rect(r.x - margin, r.y - margin, r.width + 2 * margin, r.height + 2 * margin) &
         cv::Rect(0, 0, size.width, size.height);
}

cv::Rect unite(const cv::Rect& a, const cv::Rect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return a | b;
}

// Bounding box of the cells that differ between a and b inside window: a row-wise memcmp first,
// so unchanged rows cost a fraction of a full comparison.
cv::Rect changed_box(const cv::Mat& a, const cv::Mat& b, const cv::Rect& window) {
  if (window.empty()) return {};
  int top = -1, bottom = -1, left = INT_MAX, right = -1;
  const std::size_t bytes = static_cast<std::size_t>(window.width);
  for (int r = window.y; r < window.y + window.height; ++r) {
    const unsigned char* pa = a.ptr<unsigned char>(r) + window.x;
    const unsigned char* pb = b.ptr<unsigned char>(r) + window.x;
    if (std::memcmp(pa, pb, bytes) == 0) continue;
    if (top < 0) top = r;
    bottom = r;
    int c0 = 0;
    while (pa[c0] == pb[c0]) ++c0;
    int c1 = window.width - 1;
    while (pa[c1] == pb[c1]) --c1;
    left = std::min(left, window.x + c0);
    right = std::max(right, window.x + c1);
  }
  if (top < 0) return {};
  return cv::Rect(left, top, right - left + 1, bottom - top + 1);
}

void add_unique(std::vector<int>& ids, int id) {
  if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
}

// A shift within a thousandth of a cell of a whole number of cells is that number: ROS maps carry
// their resolution as float32, so an origin moved by 80 cells of 0.05 m reads as 79.9999988 cells.
bool near_integer(double v) { return std::abs(v - std::round(v)) < 1e-3; }


std::size_t polygon_bytes(const PolygonWithHoles& p) {
  std::size_t n = p.outer.capacity();
  for (const Ring& h : p.holes) n += h.capacity();
  return n * sizeof(Point2) + p.holes.capacity() * sizeof(Ring);
}

// The binarized free space over window (255 free), computed with `reach` cells of context around
// it, so that it equals the whole map's binarization there.
cv::Mat binarized_window(const OccupancyGrid& grid, const cv::Rect& window, const BinarizeOptions& binarize,
                         int reach) {
  cv::Mat new_bin;
  if (window.empty()) return new_bin;
  if (trivial_binarization(binarize)) {
    new_bin = grid.cells(window) == kFree;
    return new_bin;
  }
  const cv::Rect context = grown(window, reach, grid.cells.size());
  OccupancyGrid sub;
  sub.cells = grid.cells(context);
  sub.resolution = grid.resolution;
  new_bin = free_space_mask(sub, binarize)(window - context.tl()).clone();
  return new_bin;
}

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

// The changed cells of one update, over the window where the binarized free space may differ.
struct ChangeMask {
  cv::Rect window;  // the changed box grown by the binarization's reach
  cv::Mat change;   // per window cell: kGained, kLost, kReshaped or 0
  int changed_cells = 0;
};

// A connected blob of changed cells and the rooms it touches (old labels of its cells and of the
// cells around its newly free cells).
struct Blob {
  int gained = 0;
  int lost = 0;
  bool structural = false;  // lost or reshaped cells: the touched rooms must be decomposed again
  std::vector<int> touched;
  cv::Rect box;
  bool absorb = false;
};

// Region::member values: how a room of the region takes part in its decomposition.
constexpr char kWhole = 1;    // every cell
constexpr char kPartial = 2;  // only its cells in Region::near_change (a room larger than partial_area)

// The old rooms and pending cells one update decomposes again.
struct Region {
  std::vector<int> ids;        // old rooms: those the change touched first, then their neighbours
  std::vector<char> member;    // by room id: kWhole or kPartial if in ids, else 0
  cv::Rect window;             // contains the pending cells and every cell of the region
  cv::Rect near_change;        // the changed box grown by partial_margin (empty when partial_area is 0)
  bool whole_map = false;
};

// What one pass over the re-decomposed region learns about each piece (index 1..pieces).
struct PieceTally {
  int n_old = 0;                   // old rooms of the region
  std::vector<long long> overlap;  // [piece * (n_old + 1) + j]: cells shared with old room j; j = n_old: pending
  std::vector<long long> cells, first_cell, sum_c, sum_r;
  std::vector<int> min_c, max_c, min_r, max_r;
};

// The region's new decomposition and the ids its pieces take.
struct RegionPieces {
  cv::Mat raw;               // 255 where a cell of the region is free (to be labelled)
  int region_cells = 0;
  PieceSet set;              // pieces and cuts in window grid coordinates
  int pieces = 0;
  cv::Mat local;             // piece index + 1 of each cell of the window (0 outside the region)
  PieceTally tally;
  std::vector<int> id_of_piece;  // by piece index + 1: its room id
  std::vector<char> reused;      // by old room id: its id went to a piece
  std::vector<int> held_piece;   // by old room id: the piece (index + 1) in which it keeps its cells, 0 none
  struct HeldCells {             // the cells a held room keeps, gathered as the labels are written
    int id = 0;
    long long cells = 0, sum_c = 0, sum_r = 0;
    int min_c = INT_MAX, max_c = -1, min_r = INT_MAX, max_r = -1;
  };
  std::vector<HeldCells> held;
  std::vector<int> kept_by;      // by piece index + 1: the partial room whose rest it touches, 0 none
  struct Remainder {             // a partial room's cells outside near_change, which keep its id
    int id = 0;
    long long cells = 0;
    double sum_c = 0.0, sum_r = 0.0;
  };
  std::vector<Remainder> remainders;

  const Remainder* remainder(int id) const {
    for (const Remainder& r : remainders)
      if (r.id == id) return &r;
    return nullptr;
  }
};

// Window grid coordinates (pixel centres at integers, y up) against world metres.
struct WindowFrame {
  Point2 origin;
  double resolution;
  cv::Rect window;
  double y_offset;  // rows of the map below the window

  Point2 to_world(const Point2& p) const {
    return Point2{origin.x + (p.x + window.x + 0.5) * resolution, origin.y + (p.y + y_offset + 0.5) * resolution};
  }
  Point2 to_window(const Point2& p) const {
    return Point2{(p.x - origin.x) / resolution - 0.5 - window.x, (p.y - origin.y) / resolution - 0.5 - y_offset};
  }
};

// Passages with their door flags, in the order they were found.
struct PassageList {
  std::vector<Passage> passages;
  std::vector<char> doors;
};

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
  for (int r = 0; r < window.height; ++r) {
    const int* l = labels.ptr<int>(window.y + r) + window.x;
    const int* k = found.local.ptr<int>(r);
    const unsigned char* in = found.raw.ptr<unsigned char>(r);
    const int gr = window.y + r;
    for (int c = 0; c < window.width; ++c) {
      if (!in[c]) continue;
      const int piece = k[c];
      if (piece <= 0) throw Error("internal: a free cell of the re-decomposed region got no room");
      const std::size_t p = static_cast<std::size_t>(piece);
      if (t.cells[p]++ == 0) t.first_cell[p] = static_cast<long long>(r) * window.width + c;
      const int j = l[c] > 0 ? old_index[static_cast<std::size_t>(l[c])] : n_old;
      ++t.overlap[p * static_cast<std::size_t>(n_old + 1) + static_cast<std::size_t>(j)];
      const int gc = window.x + c;
      t.sum_c[p] += gc;
      t.sum_r[p] += gr;
      t.min_c[p] = std::min(t.min_c[p], gc);
      t.max_c[p] = std::max(t.max_c[p], gc);
      t.min_r[p] = std::min(t.min_r[p], gr);
      t.max_r[p] = std::max(t.max_r[p], gr);
    }
  }
  return t;
}

}  // namespace

struct IncrementalSegmenter::State {
  IncrementalOptions options;
  bool initialised = false;
  double resolution = 0.0;
  Point2 origin;
  cv::Mat cells;  // copy of the previous grid (CV_8UC1)
  cv::Mat bin;    // its binarized free space (CV_8UC1, 255 free)
  Segmentation result;               // result.labels is the state's label image
  std::vector<RoomState> rooms{1};   // by id; index 0 unused
  std::vector<char> passage_door;    // per result.passages entry: its cut was found as a door
  int next_id = 1;
  long long free_cells = 0;
  IncrementalUpdateReport report;

  const Segmentation& update(const OccupancyGrid& grid, const cv::Rect* hint);

 private:
  void start_frame(const OccupancyGrid& grid);
  bool move_frame(const OccupancyGrid& grid, bool& restarted);
  void recount_rooms();
  void process(const OccupancyGrid& grid, const cv::Rect& changed, const std::string& batch_reason);
  ChangeMask take_changes(const OccupancyGrid& grid, const cv::Rect& changed);
  std::vector<Blob> find_blobs(const ChangeMask& mask, cv::Mat& blob_of) const;
  Region choose_region(std::vector<Blob>& blobs, bool whole_map);
  bool is_speck(const Blob& blob) const;
  std::vector<int> apply_changes(const ChangeMask& mask, const cv::Mat& blob_of, const std::vector<Blob>& blobs);
  void redecompose(Region region, std::vector<int>& touched_rooms);
  bool label_isolated_cells(const Region& region, std::vector<int>& touched_rooms);
  void add_neighbour_rooms(Region& region) const;
  void frame_region(Region& region) const;
  void decompose_whole(Region& region) const;
  RegionPieces decompose_region(Region& region);
  void label_pieces(const Region& region, RegionPieces& found) const;
  bool find_kept_pieces(const Region& region, RegionPieces& found) const;
  bool kept_pieces_are_mostly_theirs(const Region& region, const RegionPieces& found) const;
  bool partial_rooms_hold_together(const Region& region, RegionPieces& found) const;
  bool decompose_partially(Region& region, RegionPieces& found);
  void trace_partial_rooms(const RegionPieces& found, const cv::Rect& window, const std::vector<cv::Rect>& outline_boxes);
  cv::Rect outline_box(int id) const;
  void report_region(const Region& region, int region_cells);
  void match_ids(const Region& region, RegionPieces& found);
  void hold_back_splits(const Region& region, RegionPieces& found);
  void hold_back_merges(const Region& region, RegionPieces& found);
  void adopt_held_rooms(const RegionPieces& found, const WindowFrame& frame);
  std::vector<int> retire_old_rooms(const Region& region, RegionPieces& found);
  void adopt_pieces(const RegionPieces& found, const WindowFrame& frame);
  void keep_border_passages(const Region& region, const RegionPieces& found, const WindowFrame& frame,
                            PassageList& out) const;
  void add_new_passages(const RegionPieces& found, const WindowFrame& frame, PassageList& out) const;
  void store_sorted(const PassageList& list);
  void refresh_room(int id, const PolygonWithHoles* polygon);
  Point2 room_centroid(const RoomState& room, int height) const;
};

void IncrementalSegmenter::State::start_frame(const OccupancyGrid& grid) {
  resolution = grid.resolution;
  origin = grid.origin;
  cells = cv::Mat(grid.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
  bin = cv::Mat::zeros(grid.cells.size(), CV_8UC1);
  result.labels = cv::Mat::zeros(grid.cells.size(), CV_32SC1);
  result.resolution = grid.resolution;
  result.origin = grid.origin;
  result.rooms.clear();
  result.passages.clear();
  passage_door.clear();
  rooms.assign(static_cast<std::size_t>(next_id), RoomState{});
  free_cells = 0;
  initialised = true;
}

// Re-embeds the state into grid's frame (same resolution). Returns false when the new frame does
// not contain the old one (what falls outside is dropped) or is offset by a fraction of a cell
// (the state is restarted).
bool IncrementalSegmenter::State::move_frame(const OccupancyGrid& grid, bool& restarted) {
  const int old_w = cells.cols, old_h = cells.rows;
  const double shift_c = (origin.x - grid.origin.x) / resolution;
  const double shift_r = grid.height() - old_h - (origin.y - grid.origin.y) / resolution;
  if (!near_integer(shift_c) || !near_integer(shift_r)) {
    start_frame(grid);
    restarted = true;
    return false;
  }
  const int dc = static_cast<int>(std::lround(shift_c)), dr = static_cast<int>(std::lround(shift_r));
  const cv::Rect all(0, 0, grid.width(), grid.height());
  const cv::Rect old_in_new(dc, dr, old_w, old_h);
  const cv::Rect kept = old_in_new & all;
  cv::Mat new_cells(grid.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
  cv::Mat new_bin = cv::Mat::zeros(grid.cells.size(), CV_8UC1);
  cv::Mat new_labels = cv::Mat::zeros(grid.cells.size(), CV_32SC1);
  if (!kept.empty()) {
    const cv::Rect source = kept - cv::Point(dc, dr);
    cells(source).copyTo(new_cells(kept));
    bin(source).copyTo(new_bin(kept));
    result.labels(source).copyTo(new_labels(kept));
  }
  cells = new_cells;
  bin = new_bin;
  result.labels = new_labels;
  result.origin = grid.origin;
  origin = grid.origin;
  for (RoomState& room : rooms) {
    if (!room.alive) continue;
    room.box = (room.box + cv::Point(dc, dr)) & all;
    room.sum_c += static_cast<double>(room.cells) * dc;
    room.sum_r += static_cast<double>(room.cells) * dr;
  }
  if (kept == old_in_new) return true;
  recount_rooms();
  return false;
}

// Recomputes every room's cells, sums and box from the label image (after cropping).
void IncrementalSegmenter::State::recount_rooms() {
  for (RoomState& room : rooms) {
    if (!room.alive) continue;
    room.cells = 0;
    room.sum_c = room.sum_r = 0.0;
    room.box = {};
  }
  std::vector<int> min_c(rooms.size(), INT_MAX), max_c(rooms.size(), -1), min_r(rooms.size(), INT_MAX),
      max_r(rooms.size(), -1);
  free_cells = 0;
  for (int r = 0; r < result.labels.rows; ++r) {
    const int* l = result.labels.ptr<int>(r);
    for (int c = 0; c < result.labels.cols; ++c) {
      if (l[c] <= 0) continue;
      const std::size_t id = static_cast<std::size_t>(l[c]);
      RoomState& room = rooms[id];
      ++room.cells;
      room.sum_c += c;
      room.sum_r += r;
      min_c[id] = std::min(min_c[id], c);
      max_c[id] = std::max(max_c[id], c);
      min_r[id] = std::min(min_r[id], r);
      max_r[id] = std::max(max_r[id], r);
      ++free_cells;
    }
  }
  for (std::size_t id = 1; id < rooms.size(); ++id)
    if (rooms[id].alive && rooms[id].cells > 0)
      rooms[id].box = cv::Rect(min_c[id], min_r[id], max_c[id] - min_c[id] + 1, max_r[id] - min_r[id] + 1);
}

Point2 IncrementalSegmenter::State::room_centroid(const RoomState& room, int height) const {
  const double n = static_cast<double>(std::max<long long>(room.cells, 1));
  return {origin.x + (room.sum_c / n + 0.5) * resolution, origin.y + (height - room.sum_r / n - 0.5) * resolution};
}

// Brings result.rooms (sorted by id) up to date for one room: erased if dead, else area and
// centroid from its state and, when given, the new polygon.
void IncrementalSegmenter::State::refresh_room(int id, const PolygonWithHoles* polygon) {
  auto it = std::lower_bound(result.rooms.begin(), result.rooms.end(), id,
                             [](const Room& room, int value) { return room.id < value; });
  const bool present = it != result.rooms.end() && it->id == id;
  const RoomState& state = rooms[static_cast<std::size_t>(id)];
  if (!state.alive) {
    if (present) result.rooms.erase(it);
    return;
  }
  if (!present) {
    it = result.rooms.insert(it, Room{});
    it->id = id;
  }
  if (polygon != nullptr) it->polygon = *polygon;
  it->area = static_cast<double>(state.cells) * resolution * resolution;
  it->centroid = room_centroid(state, cells.rows);
}

const Segmentation& IncrementalSegmenter::State::update(const OccupancyGrid& grid, const cv::Rect* hint) {
  validate(grid);
  validate(options.segment);
  report = {};
  // Copy on write: a caller that still holds the previous labels keeps them unchanged.
  if (!result.labels.empty() && result.labels.u != nullptr && result.labels.u->refcount > 1)
    result.labels = result.labels.clone();

  std::string batch_reason;
  bool restarted = false;  // a hint is only trusted against a state in the same place
  if (!initialised) {
    start_frame(grid);
    batch_reason = "first update";
    restarted = true;
  } else if (std::abs(grid.resolution - resolution) > 1e-12 * resolution) {
    start_frame(grid);
    batch_reason = "the resolution changed";
    restarted = true;
  } else if (grid.cells.size() != cells.size() || !(grid.origin == origin)) {
    if (!move_frame(grid, restarted))
      batch_reason = restarted ? "the origin moved by a fraction of a cell" : "the new map does not contain the previous one";
  }
  const cv::Rect all(0, 0, grid.width(), grid.height());
  const cv::Rect search = (hint != nullptr && !restarted) ? (*hint & all) : all;
  const cv::Rect changed = changed_box(grid.cells, cells, search);
  report.changed = changed;
  if (changed.empty() && batch_reason.empty()) {
    report.kind = IncrementalUpdateReport::Kind::kUnchanged;
    return result;
  }
  try {
    process(grid, changed, batch_reason);
  } catch (...) {
    // Never keep a half-updated state: the next update starts from scratch.
    IncrementalOptions keep_options = options;
    const int keep_next = next_id;
    *this = State{};
    options = keep_options;
    next_id = keep_next;
    rooms.assign(static_cast<std::size_t>(next_id), RoomState{});
    throw;
  }
  return result;
}

void IncrementalSegmenter::State::process(const OccupancyGrid& grid, const cv::Rect& changed,
                                          const std::string& batch_reason) {
  const ChangeMask mask = take_changes(grid, changed);
  report.changed_cells = mask.changed_cells;
  if (mask.changed_cells == 0 && batch_reason.empty()) {
    report.kind = IncrementalUpdateReport::Kind::kUnchanged;
    return;
  }

  bool whole_map = !batch_reason.empty();
  report.reason = batch_reason;
  if (!whole_map &&
      static_cast<double>(mask.changed_cells) > options.batch_fraction * static_cast<double>(free_cells)) {
    whole_map = true;
    report.reason = free_cells == 0 ? "first free space" : "more than the batch fraction of the free space changed";
  }

  cv::Mat blob_of;
  std::vector<Blob> blobs;
  if (mask.changed_cells > 0) blobs = find_blobs(mask, blob_of);
  Region region = choose_region(blobs, whole_map);
  std::vector<int> touched_rooms = apply_changes(mask, blob_of, blobs);  // rooms whose area or cells changed

  report.kind = whole_map ? IncrementalUpdateReport::Kind::kBatch : IncrementalUpdateReport::Kind::kIncremental;
  if (!region.ids.empty() || !region.window.empty()) {
    redecompose(std::move(region), touched_rooms);
  }
  for (const int id : touched_rooms) refresh_room(id, nullptr);
}

// The state's cells and free space are the grid's from here on; the returned mask is all that
// remains of how they were.
ChangeMask IncrementalSegmenter::State::take_changes(const OccupancyGrid& grid, const cv::Rect& changed) {
  const BinarizeOptions& binarize = options.segment.binarize;
  const int reach = binarization_reach(binarize, resolution);

  // The binarized free space can change up to `reach` cells away from a changed cell; computing
  // it there needs the cells up to `reach` farther again.
  ChangeMask mask;
  mask.window = grown(changed, reach, grid.cells.size());
  const cv::Rect& window = mask.window;
  const cv::Mat new_bin = binarized_window(grid, window, binarize, reach);

  mask.change = cv::Mat::zeros(window.size(), CV_8UC1);
  for (int r = 0; r < window.height; ++r) {
    const unsigned char* old_cell = cells.ptr<unsigned char>(window.y + r) + window.x;
    const unsigned char* new_cell = grid.cells.ptr<unsigned char>(window.y + r) + window.x;
    const unsigned char* old_bin = bin.ptr<unsigned char>(window.y + r) + window.x;
    const unsigned char* nb = new_bin.ptr<unsigned char>(r);
    unsigned char* d = mask.change.ptr<unsigned char>(r);
    for (int c = 0; c < window.width; ++c) {
      const bool was = old_cell[c] == kFree, is = new_cell[c] == kFree;
      if (is && !was) d[c] = kGained;
      else if (was && !is) d[c] = kLost;
      else if (was && is && (old_bin[c] != 0) != (nb[c] != 0)) d[c] = kReshaped;
      mask.changed_cells += d[c] != 0;
    }
  }
  if (!changed.empty()) grid.cells(changed).copyTo(cells(changed));
  if (!window.empty()) new_bin.copyTo(bin(window));
  return mask;
}

// Blobs of changed cells (8-connected), each with the rooms it touches in raster order of first
// contact: the order in which choose_region adds them, so region ids never depend on history.
std::vector<Blob> IncrementalSegmenter::State::find_blobs(const ChangeMask& mask, cv::Mat& blob_of) const {
  const cv::Rect& window = mask.window;
  const cv::Mat& labels = result.labels;
  const int h = labels.rows, w = labels.cols;
  cv::Mat stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask.change != 0, blob_of, stats, centroids, 8, CV_32S);
  std::vector<Blob> blobs(static_cast<std::size_t>(n));
  for (int b = 1; b < n; ++b)
    blobs[static_cast<std::size_t>(b)].box =
        cv::Rect(stats.at<int>(b, cv::CC_STAT_LEFT) + window.x, stats.at<int>(b, cv::CC_STAT_TOP) + window.y,
                 stats.at<int>(b, cv::CC_STAT_WIDTH), stats.at<int>(b, cv::CC_STAT_HEIGHT));
  for (int r = 0; r < window.height; ++r) {
    const unsigned char* d = mask.change.ptr<unsigned char>(r);
    const int* b = blob_of.ptr<int>(r);
    for (int c = 0; c < window.width; ++c) {
      if (d[c] == 0) continue;
      Blob& blob = blobs[static_cast<std::size_t>(b[c])];
      const int gr = window.y + r, gc = window.x + c;
      if (d[c] & (kLost | kReshaped)) {
        blob.structural = true;
        blob.lost += (d[c] & kLost) != 0;
        const int id = labels.at<int>(gr, gc);
        if (id > 0) add_unique(blob.touched, id);
      }
      if (d[c] & kGained) {
        ++blob.gained;
        for (int nr = std::max(0, gr - 1); nr <= std::min(h - 1, gr + 1); ++nr) {
          const int* row = labels.ptr<int>(nr);
          for (int nc = std::max(0, gc - 1); nc <= std::min(w - 1, gc + 1); ++nc)
            if (row[nc] > 0) add_unique(blob.touched, row[nc]);
        }
      }
    }
  }
  return blobs;
}

// Decides per blob: join the one room it touches (small, only newly free cells) or be decomposed
// again together with every room it touches. A room's allowance is charged as its blobs are seen,
// so later blobs see what earlier ones took.
Region IncrementalSegmenter::State::choose_region(std::vector<Blob>& blobs, bool whole_map) {
  const long long absorb_cells =
      static_cast<long long>(std::floor(options.absorb_area / (resolution * resolution) + 1e-9));
  Region region;
  region.whole_map = whole_map;
  std::vector<char> in_region(rooms.size(), 0);
  auto add_region = [&](int id) {
    if (!in_region[static_cast<std::size_t>(id)]) {
      in_region[static_cast<std::size_t>(id)] = 1;
      region.ids.push_back(id);
    }
  };
  if (whole_map)
    for (std::size_t id = 1; id < rooms.size(); ++id)
      if (rooms[id].alive) add_region(static_cast<int>(id));
  // A room takes newly seen cells without a decomposition until they add up to its allowance.
  auto allowance = [&](const RoomState& room) {
    return std::max(absorb_cells, static_cast<long long>(options.absorb_fraction * static_cast<double>(room.cells)));
  };
  for (std::size_t b = 1; b < blobs.size(); ++b) {
    Blob& blob = blobs[b];
    // A blob touching several rooms joins them (a door seen open): always decomposed again.
    blob.absorb = !whole_map && blob.touched.size() == 1 && (!blob.structural || is_speck(blob));
    if (blob.absorb) {
      RoomState& room = rooms[static_cast<std::size_t>(blob.touched.front())];
      const long long taken = blob.gained + blob.lost;
      blob.absorb = room.absorbed + taken <= allowance(room);
      if (blob.absorb) room.absorbed += taken;  // counted now, so later blobs see it
    }
    if (blob.absorb) {
      ++report.absorbed_blobs;
    } else {
      for (const int id : blob.touched) add_region(id);
      region.window = unite(region.window, blob.box);
    }
  }
  return region;
}

// A speck: a small structural blob of one room (an obstacle seen inside it, a wall's edge moved by
// a few centimetres, free cells that only change the binarized free space). Newly free cells can
// only join parts of the room; lost ones could cut it, so the room's cells around them (in the
// box grown by one cell, with the newly free ones) must stay one 4-connected piece, or none when
// they were a detached island: any path of the room through the box can then go round.
bool IncrementalSegmenter::State::is_speck(const Blob& blob) const {
  if (blob.lost == 0) return true;  // only the binarization changed: absorbed like any new free blob
  const int limit = static_cast<int>(std::floor(options.speck_size / resolution + 1e-9));
  if (blob.box.width > limit || blob.box.height > limit) return false;
  const int id = blob.touched.front();
  if (rooms[static_cast<std::size_t>(id)].cells <= blob.lost) return false;  // nothing of the room would be left
  const cv::Rect around = grown(blob.box, 1, cells.size());
  cv::Mat room(around.size(), CV_8UC1);
  for (int r = 0; r < around.height; ++r) {
    const unsigned char* cell = cells.ptr<unsigned char>(around.y + r) + around.x;
    const int* label = result.labels.ptr<int>(around.y + r) + around.x;
    unsigned char* out = room.ptr<unsigned char>(r);
    for (int c = 0; c < around.width; ++c) out[c] = cell[c] == kFree && (label[c] == id || label[c] == 0) ? 255 : 0;
  }
  cv::Mat components;
  return cv::connectedComponents(room, components, 4, CV_32S) <= 2;  // background and at most one piece
}

// Applies the cell changes to the labels: lost cells leave their room, absorbed ones join theirs,
// the others wait (kPending) for the decomposition. Returns the rooms whose cells changed (those
// decomposed again are refreshed by the decomposition).
std::vector<int> IncrementalSegmenter::State::apply_changes(const ChangeMask& mask, const cv::Mat& blob_of,
                                                            const std::vector<Blob>& blobs) {
  const cv::Rect& window = mask.window;
  cv::Mat& labels = result.labels;
  std::vector<int> touched_rooms;
  for (int r = 0; r < window.height; ++r) {
    const unsigned char* d = mask.change.ptr<unsigned char>(r);
    const int* b = blob_of.empty() ? nullptr : blob_of.ptr<int>(r);
    int* l = labels.ptr<int>(window.y + r) + window.x;
    for (int c = 0; c < window.width; ++c) {
      if (d[c] == kLost && l[c] > 0) {
        RoomState& room = rooms[static_cast<std::size_t>(l[c])];
        --room.cells;
        room.sum_c -= window.x + c;
        room.sum_r -= window.y + r;
        add_unique(touched_rooms, l[c]);
        l[c] = 0;
        --free_cells;
      } else if (d[c] == kGained) {
        ++free_cells;
        const Blob& blob = blobs[static_cast<std::size_t>(b[c])];
        if (!blob.absorb) {
          l[c] = kPending;
          continue;
        }
        const int id = blob.touched.front();
        RoomState& room = rooms[static_cast<std::size_t>(id)];
        l[c] = id;
        ++room.cells;
        room.sum_c += window.x + c;
        room.sum_r += window.y + r;
        room.box = unite(room.box, cv::Rect(window.x + c, window.y + r, 1, 1));
        add_unique(touched_rooms, id);
      }
    }
  }
  return touched_rooms;
}

// Decomposes again the free cells of the rooms in region plus the pending cells in its window, with
// the batch stages, and gives the pieces ids (match_ids). Updates labels, room states,
// result.rooms and passages.
void IncrementalSegmenter::State::redecompose(Region region, std::vector<int>& touched_rooms) {
  if (options.isolated_to_nearest_room && region.ids.empty() && !region.whole_map &&
      label_isolated_cells(region, touched_rooms))
    return;
  add_neighbour_rooms(region);
  frame_region(region);
  RegionPieces found;
  while (!decompose_partially(region, found)) decompose_whole(region);
  report_region(region, found.region_cells);
  const cv::Rect& window = region.window;

  std::vector<cv::Rect> outline_boxes;  // taken before refresh_room replaces the polygons
  for (const RegionPieces::Remainder& rest : found.remainders) outline_boxes.push_back(outline_box(rest.id));
  const std::vector<int> removed = retire_old_rooms(region, found);
  const double y_offset = result.labels.rows - window.height - window.y;
  const WindowFrame frame{origin, resolution, window, y_offset};
  for (const int id : removed) refresh_room(id, nullptr);
  adopt_pieces(found, frame);
  adopt_held_rooms(found, frame);
  trace_partial_rooms(found, window, outline_boxes);
  // Rooms absorbed into this decomposition are refreshed here; the caller must not revive them.
  touched_rooms.erase(std::remove_if(touched_rooms.begin(), touched_rooms.end(),
                                     [&](int id) { return region.member[static_cast<std::size_t>(id)] != 0; }),
                      touched_rooms.end());

  // Passages: cuts on the region's border keep their outside room and find their inside one again;
  // cuts inside the region are replaced by the new decomposition's cuts.
  PassageList list;
  list.passages.reserve(result.passages.size() + found.set.cuts.size());
  keep_border_passages(region, found, frame, list);
  add_new_passages(found, frame, list);
  store_sorted(list);
}

// Newly free cells that touch no room and keep no binarized free space (a ray fan seen through a
// gap, thinner than the opening) can be no room of their own: as in batch, each takes the label of
// the nearest room (along free space, else in a straight line). Decomposing them would find no
// free space and take the whole map. Returns false, changing nothing, when they are not such cells.
bool IncrementalSegmenter::State::label_isolated_cells(const Region& region, std::vector<int>& touched_rooms) {
  const cv::Rect& window = region.window;
  cv::Mat& labels = result.labels;
  std::vector<int> pending;
  for (int r = window.y; r < window.y + window.height; ++r) {
    const int* l = labels.ptr<int>(r);
    const unsigned char* b = bin.ptr<unsigned char>(r);
    for (int c = window.x; c < window.x + window.width; ++c) {
      if (l[c] != kPending) continue;
      if (b[c] != 0) return false;  // binarized free space: it may be a room
      pending.push_back(r * labels.cols + c);
    }
  }
  if (pending.empty() || free_cells <= static_cast<long long>(pending.size())) return false;
  int* data = labels.ptr<int>(0);
  for (const int index : pending) data[index] = 0;
  complete_unlabelled_cells(labels, cells == kFree, pending);
  const bool all_labelled = std::all_of(pending.begin(), pending.end(), [&](int index) { return data[index] > 0; });
  for (const int index : pending) {
    if (!all_labelled) {
      data[index] = kPending;
      continue;
    }
    RoomState& room = rooms[static_cast<std::size_t>(data[index])];
    const int r = index / labels.cols, c = index % labels.cols;
    ++room.cells;
    room.sum_c += c;
    room.sum_r += r;
    room.box = unite(room.box, cv::Rect(c, r, 1, 1));
    add_unique(touched_rooms, data[index]);
  }
  return all_labelled;
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
    if (!(passage_door[k] ? options.neighbours_across_doors : options.neighbours_across_cuts)) continue;
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
void IncrementalSegmenter::State::frame_region(Region& region) const {
  const cv::Rect change = region.window;
  if (options.partial_area > 0.0 && !region.whole_map && !change.empty()) {
    const int margin = static_cast<int>(std::ceil(options.partial_margin / resolution));
    region.near_change = grown(change, margin, cells.size());
    const double cell_area = resolution * resolution;
    for (const int id : region.ids) {
      const RoomState& room = rooms[static_cast<std::size_t>(id)];
      // Worth it only when the window leaves out most of the room's box.
      if (static_cast<double>(room.cells) * cell_area > options.partial_area &&
          2 * (room.box & region.near_change).area() < room.box.area())
        region.member[static_cast<std::size_t>(id)] = kPartial;
    }
  }
  for (const int id : region.ids) {
    const cv::Rect& box = rooms[static_cast<std::size_t>(id)].box;
    region.window = unite(region.window, region.member[static_cast<std::size_t>(id)] == kPartial ? box & region.near_change : box);
  }
}

// Decomposes the region and gives its pieces ids (match_ids). Returns false, changing no room,
// when a partial room could not keep its id on its rest: it must then be decomposed whole.
bool IncrementalSegmenter::State::decompose_partially(Region& region, RegionPieces& found) {
  found = decompose_region(region);
  label_pieces(region, found);
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
  const int saved_next_id = next_id;
  const IncrementalUpdateReport saved_report = report;
  match_ids(region, found);
  if (partial_rooms_hold_together(region, found)) return true;
  rooms = saved_rooms;
  next_id = saved_next_id;
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

// The region's free cells (raw) and their decomposition into pieces, in window grid coordinates.
// Where binarization leaves nothing of a region that has free cells, the region grows to the whole
// map, as batch would take it; a map with no binarized free space at all throws.
RegionPieces IncrementalSegmenter::State::decompose_region(Region& region) {
  const cv::Mat& labels = result.labels;
  std::vector<char>& in_region = region.member;
  cv::Rect& window = region.window;
  RegionPieces found;
  cv::Mat& raw = found.raw;
  cv::Mat binarized;
  for (int attempt = 0; attempt < 2; ++attempt) {
    raw.create(window.size(), CV_8UC1);
    binarized.create(window.size(), CV_8UC1);
    found.region_cells = 0;
    int binarized_cells = 0;
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
      const unsigned char* b = bin.ptr<unsigned char>(window.y + r) + window.x;
      unsigned char* out_raw = raw.ptr<unsigned char>(r);
      unsigned char* out_bin = binarized.ptr<unsigned char>(r);
      const bool near_row = window.y + r >= near.y && window.y + r < near.y + near.height;
      for (int c = 0; c < window.width; ++c) {
        unsigned char in = lut[l[c]];  // labels are >= kPending
        if (in == 128) in = near_row && window.x + c >= near.x && window.x + c < near.x + near.width ? 255 : 0;
        out_raw[c] = in;
        out_bin[c] = in & b[c];
        found.region_cells += in & 1;
        binarized_cells += out_bin[c] & 1;
      }
    }
    found.set = PieceSet{};
    if (binarized_cells > 0) {
      const FreeSpacePolygons polygons = free_space_polygons(binarized, resolution, options.segment.contours);
      for (const FreeSpaceComponent& component : polygons.components)
        found.set.append(decompose_component(component, resolution, options.segment));
    }
    if (found.region_cells == 0 || !found.set.pieces.empty()) break;
    // Free cells but nothing left after binarization here: as batch would, take the whole map.
    if (region.whole_map || attempt == 1)
      throw Error("no free space is left after inflating obstacles by the robot radius and filtering");
    region.whole_map = true;
    decompose_whole(region);
    for (std::size_t id = 1; id < rooms.size(); ++id)
      if (rooms[id].alive && !in_region[id]) {
        in_region[id] = kWhole;
        region.ids.push_back(static_cast<int>(id));
        window = unite(window, rooms[id].box);
      }
    report.kind = IncrementalUpdateReport::Kind::kBatch;
    report.reason = "no binarized free space in the changed region";
  }
  return found;
}

// Every free cell of the region gets its piece (index + 1 in found.local).
void IncrementalSegmenter::State::label_pieces(const Region& region, RegionPieces& found) const {
  found.pieces = static_cast<int>(found.set.pieces.size());
  if (found.pieces > 0) {
    found.local = rasterize_polygons(found.set.pieces, region.window.size());
    fill_free_space_labels(found.local, found.raw);
  } else {
    found.local = cv::Mat::zeros(region.window.size(), CV_32SC1);
  }
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
  if (!region.whole_map && every_room) {
    report.kind = IncrementalUpdateReport::Kind::kBatch;
    report.reason = "the change touched every room";
  }
}

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
  std::vector<int> fresh;
  for (int p = 1; p <= pieces; ++p)
    if (id_of_piece[static_cast<std::size_t>(p)] == 0 && t.cells[static_cast<std::size_t>(p)] > 0) fresh.push_back(p);
  std::sort(fresh.begin(), fresh.end(), [&](int a, int b) {
    return t.first_cell[static_cast<std::size_t>(a)] < t.first_cell[static_cast<std::size_t>(b)];
  });
  for (const int p : fresh) id_of_piece[static_cast<std::size_t>(p)] = next_id++;
  report.new_rooms = static_cast<int>(fresh.size());
  rooms.resize(static_cast<std::size_t>(next_id));
}

// Hysteresis on splits: a piece without an old id that is mostly cut from one old room whose id went
// to a piece across one of the new cuts stays in that room until split_after decompositions in a
// row have cut it off, so that a cut the decomposition finds one scan and drops the next does not
// hand out an id each time. Pieces mostly of newly seen cells, and parts no longer connected to
// the room (a door closed), are new rooms at once.
void IncrementalSegmenter::State::hold_back_splits(const Region& region, RegionPieces& found) {
  const PieceTally& t = found.tally;
  const std::size_t columns = static_cast<std::size_t>(t.n_old) + 1;
  std::vector<std::pair<int, int>> across;  // pieces (index + 1) on the two sides of a cut
  for (const Segment2& c : found.set.cuts) {
    Point2 left, right;
    if (!cut_sides(c.a, c.b, left, right)) continue;
    across.emplace_back(piece_containing(found.set.pieces, left) + 1, piece_containing(found.set.pieces, right) + 1);
  }
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
  for (int r = 0; r < window.height; ++r) {
    int* l = result.labels.ptr<int>(window.y + r) + window.x;
    const int* k = found.local.ptr<int>(r);
    const unsigned char* in = found.raw.ptr<unsigned char>(r);
    for (int c = 0; c < window.width; ++c) {
      if (!in[c]) continue;
      const int old = l[c];
      if (old > 0 && found.held_piece[static_cast<std::size_t>(old)] == k[c]) {
        RegionPieces::HeldCells& h = found.held[static_cast<std::size_t>(held_index[static_cast<std::size_t>(old)])];
        const int gc = window.x + c, gr = window.y + r;
        ++h.cells;
        h.sum_c += gc;
        h.sum_r += gr;
        h.min_c = std::min(h.min_c, gc);
        h.max_c = std::max(h.max_c, gc);
        h.min_r = std::min(h.min_r, gr);
        h.max_r = std::max(h.max_r, gr);
        continue;
      }
      l[c] = found.id_of_piece[static_cast<std::size_t>(k[c])];
    }
  }
  return removed;
}

// Every piece that labels a cell belongs to a live room, its state rebuilt from its pieces' cells
// alone (nothing absorbed since) and its polygon, in world metres, that of its largest piece (a
// room holding back a split has two).
void IncrementalSegmenter::State::adopt_pieces(const RegionPieces& found, const WindowFrame& frame) {
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
    const PolygonWithHoles world = to_world_polygon(found.set.pieces[static_cast<std::size_t>(largest[id]) - 1], frame);
    refresh_room(static_cast<int>(id), &world);
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
    const WindowFrame frame{origin, resolution, box, static_cast<double>(result.labels.rows - box.height - box.y)};
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
      out.doors.push_back(passage_door[k]);
      continue;
    }
    if (a_in && b_in) {
      // The cut between a room holding back a merge and its partner still parts their cells.
      const int a = passage.room_a, b = passage.room_b;
      if (rooms[static_cast<std::size_t>(a)].merge_partner == b || rooms[static_cast<std::size_t>(b)].merge_partner == a) {
        out.passages.push_back(passage);
        out.doors.push_back(passage_door[k]);
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
    out.doors.push_back(passage_door[k]);
  }
}

// Every cut of the new decomposition between two different rooms is a passage, a door if the
// decomposition found it as one.
void IncrementalSegmenter::State::add_new_passages(const RegionPieces& found, const WindowFrame& frame,
                                                   PassageList& out) const {
  auto room_of = [&](const Point2& window_point) {
    const int piece = piece_containing(found.set.pieces, window_point);
    if (piece < 0) return 0;
    const std::size_t p = static_cast<std::size_t>(piece) + 1;
    return found.tally.cells[p] > 0 ? found.id_of_piece[p] : 0;
  };
  for (const Segment2& cut : found.set.cuts) {
    Point2 left, right;
    if (!cut_sides(cut.a, cut.b, left, right)) continue;
    const int a = room_of(left), b = room_of(right);
    if (a == 0 || b == 0 || a == b) continue;
    Passage passage;
    passage.room_a = std::min(a, b);
    passage.room_b = std::max(a, b);
    passage.cut = {frame.to_world(cut.a), frame.to_world(cut.b)};
    passage.width = std::hypot(cut.b.x - cut.a.x, cut.b.y - cut.a.y) * resolution;
    passage.door = is_door(passage, options.segment.doors);
    out.passages.push_back(passage);
    out.doors.push_back(std::find(found.set.doors.begin(), found.set.doors.end(), cut) != found.set.doors.end());
  }
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
  passage_door.clear();
  for (const std::size_t k : order) {
    result.passages.push_back(passages[k]);
    passage_door.push_back(list.doors[k]);
  }
}

IncrementalSegmenter::IncrementalSegmenter(const IncrementalOptions& options) : state_(std::make_unique<State>()) {
  if (!std::isfinite(options.absorb_area) || options.absorb_area < 0.0)
    throw Error("the absorb area must be a finite, non-negative number of square metres");
  if (!std::isfinite(options.absorb_fraction) || options.absorb_fraction < 0.0)
    throw Error("the absorb fraction must be a finite, non-negative number");
  if (options.split_after < 1) throw Error("split_after must be at least 1 decomposition");
  if (options.merge_after < 1) throw Error("merge_after must be at least 1 decomposition");
  if (!std::isfinite(options.partial_area) || options.partial_area < 0.0)
    throw Error("the partial area must be a finite, non-negative number of square metres");
  if (!std::isfinite(options.partial_margin) || options.partial_margin <= 0.0)
    throw Error("the partial margin must be a positive number of metres");
  if (!std::isfinite(options.speck_size) || options.speck_size < 0.0)
    throw Error("the speck size must be a finite, non-negative number of metres");
  if (!std::isfinite(options.batch_fraction) || options.batch_fraction <= 0.0)
    throw Error("the batch fraction must be a positive number");
  validate(options.segment);
  if (options.segment.labels.cover_absorbed_obstacles)
    throw Error("the incremental segmenter labels free cells only: cover_absorbed_obstacles is not supported");
  if (options.segment.clean)
    throw Error("the incremental segmenter does not clean the free space (ray fans, specks): set clean to false");
  state_->options = options;
}

IncrementalSegmenter::~IncrementalSegmenter() = default;
IncrementalSegmenter::IncrementalSegmenter(IncrementalSegmenter&&) noexcept = default;
IncrementalSegmenter& IncrementalSegmenter::operator=(IncrementalSegmenter&&) noexcept = default;

const Segmentation& IncrementalSegmenter::update(const OccupancyGrid& grid) { return state_->update(grid, nullptr); }

const Segmentation& IncrementalSegmenter::update(const OccupancyGrid& grid, const cv::Rect& changed) {
  return state_->update(grid, &changed);
}

const Segmentation& IncrementalSegmenter::result() const { return state_->result; }

const IncrementalUpdateReport& IncrementalSegmenter::last_update() const { return state_->report; }

const IncrementalOptions& IncrementalSegmenter::options() const { return state_->options; }

std::size_t IncrementalSegmenter::state_bytes() const {
  const State& s = *state_;
  std::size_t bytes = s.cells.total() * s.cells.elemSize() + s.bin.total() * s.bin.elemSize() +
                      s.result.labels.total() * s.result.labels.elemSize();
  bytes += s.rooms.capacity() * sizeof(RoomState);
  bytes += s.result.rooms.capacity() * sizeof(Room);
  for (const Room& room : s.result.rooms) bytes += polygon_bytes(room.polygon);
  bytes += s.result.passages.capacity() * sizeof(Passage);
  return bytes;
}

void IncrementalSegmenter::reset() {
  IncrementalOptions options = state_->options;
  state_ = std::make_unique<State>();
  state_->options = options;
}

}  // namespace topocut
