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
  void redecompose(const OccupancyGrid& grid, std::vector<int> region_ids, cv::Rect window, bool whole_map,
                   std::vector<int>& touched_rooms);
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
  const cv::Size size = grid.cells.size();
  const BinarizeOptions& binarize = options.segment.binarize;
  const bool trivial = trivial_binarization(binarize);
  const int reach = binarization_reach(binarize, resolution);

  // The binarized free space can change up to `reach` cells away from a changed cell; computing
  // it there needs the cells up to `reach` farther again.
  const cv::Rect window = grown(changed, reach, size);
  cv::Mat new_bin;
  if (!window.empty()) {
    if (trivial) {
      new_bin = grid.cells(window) == kFree;
    } else {
      const cv::Rect context = grown(window, reach, size);
      OccupancyGrid sub;
      sub.cells = grid.cells(context);
      sub.resolution = grid.resolution;
      new_bin = free_space_mask(sub, binarize)(window - context.tl()).clone();
    }
  }

  // The change mask over the window, then the new cells and free space become the state.
  cv::Mat change = cv::Mat::zeros(window.size(), CV_8UC1);
  int changed_cells = 0;
  for (int r = 0; r < window.height; ++r) {
    const unsigned char* old_cell = cells.ptr<unsigned char>(window.y + r) + window.x;
    const unsigned char* new_cell = grid.cells.ptr<unsigned char>(window.y + r) + window.x;
    const unsigned char* old_bin = bin.ptr<unsigned char>(window.y + r) + window.x;
    const unsigned char* nb = new_bin.ptr<unsigned char>(r);
    unsigned char* d = change.ptr<unsigned char>(r);
    for (int c = 0; c < window.width; ++c) {
      const bool was = old_cell[c] == kFree, is = new_cell[c] == kFree;
      if (is && !was) d[c] = kGained;
      else if (was && !is) d[c] = kLost;
      else if (was && is && (old_bin[c] != 0) != (nb[c] != 0)) d[c] = kReshaped;
      changed_cells += d[c] != 0;
    }
  }
  if (!changed.empty()) grid.cells(changed).copyTo(cells(changed));
  if (!window.empty()) new_bin.copyTo(bin(window));
  report.changed_cells = changed_cells;
  if (changed_cells == 0 && batch_reason.empty()) {
    report.kind = IncrementalUpdateReport::Kind::kUnchanged;
    return;
  }

  bool whole_map = !batch_reason.empty();
  report.reason = batch_reason;
  if (!whole_map && static_cast<double>(changed_cells) > options.batch_fraction * static_cast<double>(free_cells)) {
    whole_map = true;
    report.reason = free_cells == 0 ? "first free space" : "more than the batch fraction of the free space changed";
  }

  // Blobs of changed cells and the rooms each one touches (old labels of its cells and of the
  // cells around its newly free cells).
  struct Blob {
    int gained = 0;
    bool structural = false;  // lost or reshaped cells: the touched rooms must be decomposed again
    std::vector<int> touched;
    cv::Rect box;
    bool absorb = false;
  };
  std::vector<Blob> blobs;
  cv::Mat blob_of;
  cv::Mat& labels = result.labels;
  const int h = size.height, w = size.width;
  if (changed_cells > 0) {
    cv::Mat stats, centroids;
    const int n = cv::connectedComponentsWithStats(change != 0, blob_of, stats, centroids, 8, CV_32S);
    blobs.resize(static_cast<std::size_t>(n));
    for (int b = 1; b < n; ++b)
      blobs[static_cast<std::size_t>(b)].box =
          cv::Rect(stats.at<int>(b, cv::CC_STAT_LEFT) + window.x, stats.at<int>(b, cv::CC_STAT_TOP) + window.y,
                   stats.at<int>(b, cv::CC_STAT_WIDTH), stats.at<int>(b, cv::CC_STAT_HEIGHT));
    for (int r = 0; r < window.height; ++r) {
      const unsigned char* d = change.ptr<unsigned char>(r);
      const int* b = blob_of.ptr<int>(r);
      for (int c = 0; c < window.width; ++c) {
        if (d[c] == 0) continue;
        Blob& blob = blobs[static_cast<std::size_t>(b[c])];
        const int gr = window.y + r, gc = window.x + c;
        if (d[c] & (kLost | kReshaped)) {
          blob.structural = true;
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
  }

  // Decide per blob: join the one room it touches (small, only newly free cells) or be decomposed
  // again together with every room it touches.
  const long long absorb_cells =
      static_cast<long long>(std::floor(options.absorb_area / (resolution * resolution) + 1e-9));
  std::vector<int> region_ids;
  std::vector<char> in_region(rooms.size(), 0);
  auto add_region = [&](int id) {
    if (!in_region[static_cast<std::size_t>(id)]) {
      in_region[static_cast<std::size_t>(id)] = 1;
      region_ids.push_back(id);
    }
  };
  if (whole_map)
    for (std::size_t id = 1; id < rooms.size(); ++id)
      if (rooms[id].alive) add_region(static_cast<int>(id));
  cv::Rect region_box;
  // A room takes newly seen cells without a decomposition until they add up to its allowance.
  auto allowance = [&](const RoomState& room) {
    return std::max(absorb_cells, static_cast<long long>(options.absorb_fraction * static_cast<double>(room.cells)));
  };
  for (std::size_t b = 1; b < blobs.size(); ++b) {
    Blob& blob = blobs[b];
    // A blob touching several rooms joins them (a door seen open): always decomposed again.
    blob.absorb = !whole_map && !blob.structural && blob.touched.size() == 1;
    if (blob.absorb) {
      RoomState& room = rooms[static_cast<std::size_t>(blob.touched.front())];
      blob.absorb = room.absorbed + blob.gained <= allowance(room);
      if (blob.absorb) room.absorbed += blob.gained;  // counted now, so later blobs see it
    }
    if (blob.absorb) {
      ++report.absorbed_blobs;
    } else {
      for (const int id : blob.touched) add_region(id);
      region_box = unite(region_box, blob.box);
    }
  }

  // Apply the cell changes to the labels: lost cells leave their room, absorbed ones join theirs,
  // the others wait for the decomposition.
  std::vector<int> touched_rooms;  // rooms whose area or cells changed (for result.rooms)
  for (int r = 0; r < window.height; ++r) {
    const unsigned char* d = change.ptr<unsigned char>(r);
    const int* b = blob_of.empty() ? nullptr : blob_of.ptr<int>(r);
    int* l = labels.ptr<int>(window.y + r) + window.x;
    for (int c = 0; c < window.width; ++c) {
      if (d[c] == kLost && l[c] > 0) {
        RoomState& room = rooms[static_cast<std::size_t>(l[c])];
        --room.cells;
        room.sum_c -= window.x + c;
        room.sum_r -= window.y + r;
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

  report.kind = whole_map ? IncrementalUpdateReport::Kind::kBatch : IncrementalUpdateReport::Kind::kIncremental;
  if (!region_ids.empty() || !region_box.empty()) {
    redecompose(grid, region_ids, region_box, whole_map, touched_rooms);
  }
  for (const int id : touched_rooms) refresh_room(id, nullptr);
}

// Decomposes again the free cells of the rooms in region_ids plus the pending cells in window, with
// the batch stages, and gives the pieces ids (an old room's id goes to the piece that covers at
// least half of it). Updates labels, room states, result.rooms and passages.
void IncrementalSegmenter::State::redecompose(const OccupancyGrid& grid, std::vector<int> region_ids, cv::Rect window,
                                              bool whole_map, std::vector<int>& touched_rooms) {
  cv::Mat& labels = result.labels;
  const int h = labels.rows;
  std::vector<char> in_region(rooms.size(), 0);
  for (const int id : region_ids) in_region[static_cast<std::size_t>(id)] = 1;
  // The rooms next to the region go with it (one ring, through the passages): batch decides on
  // the cuts between them again when it finds doors and merges pieces into rooms, and can only do
  // so with both sides in view. A door found while one side was only partly seen (or cut short by
  // the region's border) is not final, hence doors too unless options say otherwise.
  const std::size_t core = region_ids.size();
  for (std::size_t k = 0; k < result.passages.size(); ++k) {
    if (passage_door[k] && !options.neighbours_across_doors) continue;
    const Passage& p = result.passages[k];
    const bool a_in = in_region[static_cast<std::size_t>(p.room_a)] != 0;
    const bool b_in = in_region[static_cast<std::size_t>(p.room_b)] != 0;
    if (a_in == b_in) continue;
    const int other = a_in ? p.room_b : p.room_a;
    if (std::find(region_ids.begin() + static_cast<std::ptrdiff_t>(core), region_ids.end(), other) == region_ids.end())
      region_ids.push_back(other);
  }
  for (std::size_t k = core; k < region_ids.size(); ++k) in_region[static_cast<std::size_t>(region_ids[k])] = 1;
  for (const int id : region_ids) window = unite(window, rooms[static_cast<std::size_t>(id)].box);

  // The region's masks: raw free cells (to be labelled) and binarized ones (to be decomposed).
  cv::Mat raw, binarized;
  PieceSet set;
  cv::Mat local;
  int region_cells = 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    raw.create(window.size(), CV_8UC1);
    binarized.create(window.size(), CV_8UC1);
    region_cells = 0;
    int binarized_cells = 0;
    // member[id + 1]: 255 if cells labelled id are in the region (kPending = -1 always is).
    std::vector<unsigned char> member(rooms.size() + 1, 0);
    member[0] = 255;
    for (std::size_t id = 1; id < rooms.size(); ++id) member[id + 1] = in_region[id] ? 255 : 0;
    const unsigned char* lut = member.data() + 1;
    for (int r = 0; r < window.height; ++r) {
      const int* l = labels.ptr<int>(window.y + r) + window.x;
      const unsigned char* b = bin.ptr<unsigned char>(window.y + r) + window.x;
      unsigned char* out_raw = raw.ptr<unsigned char>(r);
      unsigned char* out_bin = binarized.ptr<unsigned char>(r);
      for (int c = 0; c < window.width; ++c) {
        const unsigned char in = lut[l[c]];  // labels are >= kPending
        out_raw[c] = in;
        out_bin[c] = in & b[c];
        region_cells += in & 1;
        binarized_cells += out_bin[c] & 1;
      }
    }
    set = PieceSet{};
    if (binarized_cells > 0) {
      const FreeSpacePolygons polygons = free_space_polygons(binarized, resolution, options.segment.contours);
      for (const FreeSpaceComponent& component : polygons.components)
        set.append(decompose_component(component, resolution, options.segment));
    }
    if (region_cells == 0 || !set.pieces.empty()) break;
    // Free cells but nothing left after binarization here: as batch would, take the whole map.
    if (whole_map || attempt == 1)
      throw Error("no free space is left after inflating obstacles by the robot radius and filtering");
    whole_map = true;
    for (std::size_t id = 1; id < rooms.size(); ++id)
      if (rooms[id].alive && !in_region[id]) {
        in_region[id] = 1;
        region_ids.push_back(static_cast<int>(id));
        window = unite(window, rooms[id].box);
      }
    report.kind = IncrementalUpdateReport::Kind::kBatch;
    report.reason = "no binarized free space in the changed region";
  }
  report.region = window;
  report.region_cells = region_cells;
  report.redecomposed_rooms = static_cast<int>(region_ids.size());
  bool every_room = !region_ids.empty();
  for (std::size_t id = 1; id < rooms.size() && every_room; ++id) every_room = !rooms[id].alive || in_region[id];
  if (!whole_map && every_room) {
    report.kind = IncrementalUpdateReport::Kind::kBatch;
    report.reason = "the change touched every room";
  }

  const int pieces = static_cast<int>(set.pieces.size());
  if (pieces > 0) {
    local = rasterize_polygons(set.pieces, window.size());
    fill_free_space_labels(local, raw);
  } else {
    local = cv::Mat::zeros(window.size(), CV_32SC1);
  }

  // One pass over the region: every piece's overlap with every old room of the region, its cell
  // count, first cell, coordinate sums and bounding box.
  const int n_old = static_cast<int>(region_ids.size());
  std::vector<int> old_index(rooms.size(), -1);
  for (int j = 0; j < n_old; ++j) old_index[static_cast<std::size_t>(region_ids[static_cast<std::size_t>(j)])] = j;
  const std::size_t slots = static_cast<std::size_t>(pieces) + 1;
  std::vector<long long> overlap(slots * static_cast<std::size_t>(n_old + 1), 0);  // column n_old: pending
  std::vector<long long> piece_cells(slots, 0), first_cell(slots, LLONG_MAX), sum_c(slots, 0), sum_r(slots, 0);
  std::vector<int> min_c(slots, INT_MAX), max_c(slots, -1), min_r(slots, INT_MAX), max_r(slots, -1);
  for (int r = 0; r < window.height; ++r) {
    const int* l = labels.ptr<int>(window.y + r) + window.x;
    const int* k = local.ptr<int>(r);
    const unsigned char* in = raw.ptr<unsigned char>(r);
    const int gr = window.y + r;
    for (int c = 0; c < window.width; ++c) {
      if (!in[c]) continue;
      const int piece = k[c];
      if (piece <= 0) throw Error("internal: a free cell of the re-decomposed region got no room");
      const std::size_t p = static_cast<std::size_t>(piece);
      if (piece_cells[p]++ == 0) first_cell[p] = static_cast<long long>(r) * window.width + c;
      const int j = l[c] > 0 ? old_index[static_cast<std::size_t>(l[c])] : n_old;
      ++overlap[p * static_cast<std::size_t>(n_old + 1) + static_cast<std::size_t>(j)];
      const int gc = window.x + c;
      sum_c[p] += gc;
      sum_r[p] += gr;
      min_c[p] = std::min(min_c[p], gc);
      max_c[p] = std::max(max_c[p], gc);
      min_r[p] = std::min(min_r[p], gr);
      max_r[p] = std::max(max_r[p], gr);
    }
  }
  struct Candidate {
    long long count;
    int piece;
    int old;
  };
  std::vector<Candidate> candidates;
  for (int p = 1; p <= pieces; ++p)
    for (int j = 0; j < n_old; ++j) {
      const long long count = overlap[static_cast<std::size_t>(p) * static_cast<std::size_t>(n_old + 1) + static_cast<std::size_t>(j)];
      if (count > 0) candidates.push_back({count, p, region_ids[static_cast<std::size_t>(j)]});
    }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return std::tie(b.count, a.piece, a.old) < std::tie(a.count, b.piece, b.old);
  });
  std::vector<int> id_of_piece(static_cast<std::size_t>(pieces) + 1, 0);
  std::vector<char> reused(rooms.size(), 0);
  for (const Candidate& candidate : candidates) {
    if (id_of_piece[static_cast<std::size_t>(candidate.piece)] != 0 || reused[static_cast<std::size_t>(candidate.old)]) continue;
    if (2 * candidate.count < rooms[static_cast<std::size_t>(candidate.old)].cells) continue;
    id_of_piece[static_cast<std::size_t>(candidate.piece)] = candidate.old;
    reused[static_cast<std::size_t>(candidate.old)] = 1;
  }
  // New ids in raster order of the pieces' first cells (deterministic, like batch numbering).
  std::vector<int> fresh;
  for (int p = 1; p <= pieces; ++p)
    if (id_of_piece[static_cast<std::size_t>(p)] == 0 && piece_cells[static_cast<std::size_t>(p)] > 0) fresh.push_back(p);
  std::sort(fresh.begin(), fresh.end(), [&](int a, int b) {
    return first_cell[static_cast<std::size_t>(a)] < first_cell[static_cast<std::size_t>(b)];
  });
  for (const int p : fresh) id_of_piece[static_cast<std::size_t>(p)] = next_id++;
  report.new_rooms = static_cast<int>(fresh.size());
  rooms.resize(static_cast<std::size_t>(next_id));

  // Old rooms of the region die unless reused; pieces' rooms are rebuilt from their cells.
  std::vector<int> removed;
  for (const int id : region_ids)
    if (!reused[static_cast<std::size_t>(id)]) {
      rooms[static_cast<std::size_t>(id)] = RoomState{};
      removed.push_back(id);
    }
  report.removed_rooms = static_cast<int>(removed.size());
  for (int r = 0; r < window.height; ++r) {
    int* l = labels.ptr<int>(window.y + r) + window.x;
    const int* k = local.ptr<int>(r);
    const unsigned char* in = raw.ptr<unsigned char>(r);
    for (int c = 0; c < window.width; ++c)
      if (in[c]) l[c] = id_of_piece[static_cast<std::size_t>(k[c])];
  }

  // Pieces' polygons in world metres: window grid coordinates -> world.
  const double y_offset = h - window.height - window.y;
  auto to_world = [&](const Point2& p) {
    return Point2{origin.x + (p.x + window.x + 0.5) * resolution, origin.y + (p.y + y_offset + 0.5) * resolution};
  };
  auto to_window = [&](const Point2& p) {
    return Point2{(p.x - origin.x) / resolution - 0.5 - window.x, (p.y - origin.y) / resolution - 0.5 - y_offset};
  };
  for (const int id : removed) refresh_room(id, nullptr);
  for (int p = 1; p <= pieces; ++p) {
    const std::size_t piece = static_cast<std::size_t>(p);
    if (piece_cells[piece] == 0) continue;
    const int id = id_of_piece[piece];
    RoomState& room = rooms[static_cast<std::size_t>(id)];
    room.alive = true;
    room.cells = piece_cells[piece];
    room.sum_c = static_cast<double>(sum_c[piece]);
    room.sum_r = static_cast<double>(sum_r[piece]);
    room.absorbed = 0;
    room.box = cv::Rect(min_c[piece], min_r[piece], max_c[piece] - min_c[piece] + 1, max_r[piece] - min_r[piece] + 1);
    PolygonWithHoles world;
    for (const Point2& v : set.pieces[piece - 1].outer) world.outer.push_back(to_world(v));
    for (const Ring& hole : set.pieces[piece - 1].holes) {
      Ring ring;
      ring.reserve(hole.size());
      for (const Point2& v : hole) ring.push_back(to_world(v));
      world.holes.push_back(std::move(ring));
    }
    world = normalized_orientation(world);
    refresh_room(id, &world);
  }
  // Rooms absorbed into this decomposition are refreshed here; the caller must not revive them.
  touched_rooms.erase(std::remove_if(touched_rooms.begin(), touched_rooms.end(),
                                     [&](int id) { return in_region[static_cast<std::size_t>(id)] != 0; }),
                      touched_rooms.end());

  // Passages: cuts on the region's border keep their outside room and find their inside one again;
  // cuts inside the region are replaced by the new decomposition's cuts.
  auto room_of = [&](const Point2& window_point) {
    const int piece = piece_containing(set.pieces, window_point);
    if (piece < 0) return 0;
    const std::size_t p = static_cast<std::size_t>(piece) + 1;
    return piece_cells[p] > 0 ? id_of_piece[p] : 0;
  };
  auto sides = [&](const Point2& a, const Point2& b, Point2& left, Point2& right) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double length = std::hypot(dx, dy);
    if (!(length > 0.0) || !std::isfinite(length)) return false;
    const double eps = 1e-3;  // cells; as rooms_from_pieces
    const Point2 mid{(a.x + b.x) / 2.0, (a.y + b.y) / 2.0};
    left = {mid.x - dy / length * eps, mid.y + dx / length * eps};
    right = {mid.x + dy / length * eps, mid.y - dx / length * eps};
    return true;
  };
  // The room of this region on the other side of an old cut from `outside`. The region's pieces
  // follow pixel edges while an old cut may run diagonally, so the cut's own side test can miss
  // them: look at the labelled cells across the cut instead, nearest first.
  std::vector<char> region_room(rooms.size(), 0);
  for (int p = 1; p <= pieces; ++p)
    if (piece_cells[static_cast<std::size_t>(p)] > 0) region_room[static_cast<std::size_t>(id_of_piece[static_cast<std::size_t>(p)])] = 1;
  auto region_room_beside = [&](const Point2& a, const Point2& b, int outside) {
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
  };
  std::vector<Passage> passages;
  std::vector<char> doors;
  passages.reserve(result.passages.size() + set.cuts.size());
  for (std::size_t k = 0; k < result.passages.size(); ++k) {
    const Passage& passage = result.passages[k];
    const bool a_in = in_region[static_cast<std::size_t>(passage.room_a)] != 0;
    const bool b_in = in_region[static_cast<std::size_t>(passage.room_b)] != 0;
    if (!a_in && !b_in) {
      passages.push_back(passage);
      doors.push_back(passage_door[k]);
      continue;
    }
    if (a_in && b_in) continue;
    const int outside = a_in ? passage.room_b : passage.room_a;
    const int inside = region_room_beside(to_window(passage.cut.a), to_window(passage.cut.b), outside);
    if (inside == 0) continue;
    Passage kept = passage;
    kept.room_a = std::min(inside, outside);
    kept.room_b = std::max(inside, outside);
    passages.push_back(kept);
    doors.push_back(passage_door[k]);
  }
  for (const Segment2& cut : set.cuts) {
    Point2 left, right;
    if (!sides(cut.a, cut.b, left, right)) continue;
    const int a = room_of(left), b = room_of(right);
    if (a == 0 || b == 0 || a == b) continue;
    Passage passage;
    passage.room_a = std::min(a, b);
    passage.room_b = std::max(a, b);
    passage.cut = {to_world(cut.a), to_world(cut.b)};
    passage.width = std::hypot(cut.b.x - cut.a.x, cut.b.y - cut.a.y) * resolution;
    passage.door = is_door(passage, options.segment.doors);
    passages.push_back(passage);
    doors.push_back(std::find(set.doors.begin(), set.doors.end(), cut) != set.doors.end());
  }
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
    passage_door.push_back(doors[k]);
  }
}

IncrementalSegmenter::IncrementalSegmenter(const IncrementalOptions& options) : state_(std::make_unique<State>()) {
  if (!std::isfinite(options.absorb_area) || options.absorb_area < 0.0)
    throw Error("the absorb area must be a finite, non-negative number of square metres");
  if (!std::isfinite(options.absorb_fraction) || options.absorb_fraction < 0.0)
    throw Error("the absorb fraction must be a finite, non-negative number");
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
