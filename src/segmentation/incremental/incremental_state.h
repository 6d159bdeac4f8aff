#pragma once
// The incremental segmenter's state and the working types of one update, shared by its three
// source files: incremental_segmenter.cpp (frames, changes, the public class), incremental_region.cpp
// (which rooms are decomposed again, and how) and incremental_ids.cpp (which room each new piece
// becomes: ids, held splits and merges, polygons, passages).
#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/segmentation/id_ledger.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/rooms_from_pieces.h"

namespace topocut::incremental {

// Label of a newly free cell that waits, within one update, for the room it will belong to.
constexpr int kPending = -1;

// What the state keeps per room id beside result.rooms: its cells' box, count and sums, and its holds.
struct RoomState {
  bool alive = false;
  cv::Rect box;              // contains every cell of the room (may be larger after it lost cells)
  long long cells = 0;
  double sum_c = 0.0;        // sums of the column and row indices of its cells, for the centroid
  double sum_r = 0.0;
  long long absorbed = 0;    // cells joined without a decomposition since the last one
  long long whole_cells = 0; // its cells when it was last decomposed whole (frame_region)
  int split_votes = 0;       // decompositions in a row that cut a piece off this room (held back)
  int merge_votes = 0;       // decompositions in a row that merged this room into merge_partner (held back)
  int merge_partner = 0;     // the room it is held apart from (0: none); decomposed together
};

inline cv::Rect grown(const cv::Rect& r, int margin, const cv::Size& size) {
  if (r.empty()) return r;
  return cv::Rect(r.x - margin, r.y - margin, r.width + 2 * margin, r.height + 2 * margin) &
         cv::Rect(0, 0, size.width, size.height);
}

inline cv::Rect unite(const cv::Rect& a, const cv::Rect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return a | b;
}

inline void add_unique(std::vector<int>& ids, int id) {
  if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
}

// Bits of ChangeMask::change: how a cell changed.
constexpr unsigned char kGained = 1;        // labelled now (free after the cleaning), not before
constexpr unsigned char kLost = 2;          // labelled before, not now
constexpr unsigned char kFloorChanged = 4;  // in the decomposed free space before or now, not both

// The changed cells of one update, over the window where the cleaned free space may differ.
struct ChangeMask {
  // The changed box grown by the binarization's and the cleaning's reach, and further to hold the thin
  // parts reaching into it (window_input())
  cv::Rect window;
  cv::Mat change;   // per window cell: the bits above, 0 unchanged
  cv::Rect active;  // the box of the changed cells, in window coordinates (empty: none)
  int changed_cells = 0;
  // A thin part of the free space in the window reaches so far that a window holding it would cover
  // most of the map: whether it is a ray depends on all of it, so the whole map is segmented.
  bool judged_beyond = false;
};

// A connected blob of changed cells and the rooms it touches (old labels of its cells and of the
// cells around its newly free cells).
struct Blob {
  int gained = 0;
  int lost = 0;
  bool floor = false;       // the decomposed free space changed: else its cells only take or leave labels
  bool structural = false;  // floor lost or reshaped: the touched rooms must be decomposed again
  std::vector<int> touched;
  cv::Rect box;
  bool absorb = false;  // with several rooms touched: absorbed where they meet, each cell to the nearest
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
  Segmentation rooms;        // segment_input() over the window: its rooms ("pieces"), labels and passages
  int pieces = 0;            // rooms.rooms.size()
  cv::Mat local;             // piece (rooms' label) of each cell of the window (0 outside the region)
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

// The first of the bytes [from, to) of row that is nonzero, to if none: eight at a time, since a
// region's window holds long stretches of other rooms, walls and unseen space between its runs.
inline int next_nonzero(const unsigned char* row, int from, int to) {
  int x = from;
  for (; x + 8 <= to; x += 8) {
    std::uint64_t word;
    std::memcpy(&word, row + x, sizeof word);
    if (word != 0) break;
  }
  while (x < to && row[x] == 0) ++x;
  return x;
}

// Calls f(row, begin, end, old, piece) for each run of the region's free cells (found.raw) in window
// that share their old room (labels, the map's frame) and their piece (found.local): row and the
// columns [begin, end) in the map's frame. Rooms and pieces are large, so runs are long and a pass
// costs about a step per run. f may rewrite the labels of its own run.
template <typename F>
void for_each_region_run(const cv::Rect& window, const cv::Mat& labels, const RegionPieces& found, F&& f) {
  for (int r = 0; r < window.height; ++r) {
    const int* l = labels.ptr<int>(window.y + r) + window.x;
    const int* k = found.local.ptr<int>(r);
    const unsigned char* in = found.raw.ptr<unsigned char>(r);
    for (int c = next_nonzero(in, 0, window.width); c < window.width;) {
      const int old = l[c], piece = k[c];
      int end = c + 1;
      while (end < window.width && in[end] && l[end] == old && k[end] == piece) ++end;
      f(window.y + r, window.x + c, window.x + end, old, piece);
      c = next_nonzero(in, end, window.width);
    }
  }
}

// Passages with their door flags, in the order they were found.
struct PassageList {
  std::vector<Passage> passages;
};

}  // namespace topocut::incremental

namespace topocut {

struct IncrementalSegmenter::State {
  // The update's working types (incremental_state.h), by their short names.
  using RoomState = incremental::RoomState;
  using ChangeMask = incremental::ChangeMask;
  using Blob = incremental::Blob;
  using Region = incremental::Region;
  using RegionPieces = incremental::RegionPieces;
  using WindowFrame = incremental::WindowFrame;
  using PassageList = incremental::PassageList;

  IncrementalOptions options;
  bool initialised = false;
  double resolution = 0.0;
  Point2 origin;
  cv::Mat cells;     // copy of the previous grid (CV_8UC1)
  cv::Mat floor;     // its free space as decomposed: binarized and cleaned (CV_8UC1, 255)
  // segment() decomposes a map its cleaning would leave without any floor uncleaned (whole-map
  // rule); a window's cleaning cannot see that, so such a map is segmented as a whole while it lasts.
  bool uncleaned = false;
  cv::Mat labelled;  // its cells as labelled (cells_after_cleaning(): kFree cells get a room)
  Segmentation result;               // result.labels is the state's label image
  std::vector<RoomState> rooms{1};   // by id; index 0 unused
  IdLedger ledger;   // the ids handed out and where rooms that disappeared lay (id_ledger.h)
  std::vector<int> refreshed;  // rooms refresh_room() changed since the kinds were last measured
  std::vector<int> relabelled;  // rooms that gained or lost a cell in this update (report_relabelled())
  std::optional<SavedLedger> loaded;  // a saved ledger, taken by the next whole-map update's frame
  long long free_cells = 0;
  IncrementalUpdateReport report;

  const Segmentation& update(const OccupancyGrid& grid, const cv::Rect* hint);
  const Segmentation& resegment();

 private:
  void start_frame(const OccupancyGrid& grid);
  bool move_frame(const OccupancyGrid& grid, bool& restarted);
  void recount_rooms();
  template <class Work>
  void guarded(const Work& work);
  void detach_labels();
  void process(const OccupancyGrid& grid, const cv::Rect& changed);
  void segment_whole(const OccupancyGrid& grid, const std::string& reason, bool at_rest = false);
  void take_loaded_ledger();
  ChangeMask take_changes(const OccupancyGrid& grid, const cv::Rect& changed);
  SegmentationInput window_input(const OccupancyGrid& grid, ChangeMask& mask) const;
  bool local_input(const OccupancyGrid& grid, const cv::Rect& changed, ChangeMask& mask, SegmentationInput& input) const;
  std::vector<Blob> find_blobs(const ChangeMask& mask, cv::Mat& blob_of) const;
  Region choose_region(std::vector<Blob>& blobs);
  bool rooms_meet_at(const Blob& blob) const;
  bool is_speck(const Blob& blob) const;
  std::vector<int> apply_changes(const ChangeMask& mask, const cv::Mat& blob_of, const std::vector<Blob>& blobs,
                                 std::vector<int>& nearest);
  void label_from_nearest_rooms(const std::vector<int>& cells_to_label, std::vector<int>& touched_rooms);
  void label_near_cells(const std::vector<int>& cells_to_label);
  bool redecompose(Region region, std::vector<int>& touched_rooms);
  void add_neighbour_rooms(Region& region) const;
  void frame_region(Region& region) const;
  void decompose_whole(Region& region) const;
  RegionPieces decompose_region(const Region& region) const;
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
  void adopt_pieces(const RegionPieces& found);
  void keep_border_passages(const Region& region, const RegionPieces& found, const WindowFrame& frame,
                            PassageList& out) const;
  void add_new_passages(const RegionPieces& found, PassageList& out) const;
  WindowFrame window_frame(const cv::Rect& window) const;
  void store_sorted(const PassageList& list);
  void refresh_room(int id, const PolygonWithHoles* polygon);
  void report_relabelled();
  void update_kinds();
  Point2 room_centroid(const RoomState& room, int height) const;
};

}  // namespace topocut
