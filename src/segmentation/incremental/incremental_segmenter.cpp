#include "topocut/segmentation/incremental_segmenter.h"

#include "segmentation/incremental/incremental_state.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <numeric>
#include <set>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/map/binarize.h"
#include "topocut/map/free_space_cleaning.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/map/rasterize.h"
#include "topocut/segmentation/carried_ids.h"
#include "topocut/segmentation/room_kinds.h"
#include "topocut/segmentation/rooms_from_pieces.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace topocut {

using namespace incremental;

namespace {

// Widens [first, last] to the columns where the n bytes of a and b differ; whether they differ (a
// memcmp first, so equal rows cost a fraction of a cell-by-cell comparison).
bool differing_columns(const unsigned char* a, const unsigned char* b, int n, int& first, int& last) {
  if (std::memcmp(a, b, static_cast<std::size_t>(n)) == 0) return false;
  int c0 = 0;
  while (a[c0] == b[c0]) ++c0;
  int c1 = n - 1;
  while (a[c1] == b[c1]) --c1;
  first = std::min(first, c0);
  last = std::max(last, c1);
  return true;
}

// Bounding box of the cells that differ between a and b inside window.
cv::Rect changed_box(const cv::Mat& a, const cv::Mat& b, const cv::Rect& window) {
  if (window.empty()) return {};
  int top = -1, bottom = -1, left = INT_MAX, right = -1;  // columns within window
  for (int r = window.y; r < window.y + window.height; ++r) {
    if (!differing_columns(a.ptr<unsigned char>(r) + window.x, b.ptr<unsigned char>(r) + window.x, window.width, left, right))
      continue;
    if (top < 0) top = r;
    bottom = r;
  }
  if (top < 0) return {};
  return cv::Rect(window.x + left, top, right - left + 1, bottom - top + 1);
}

std::size_t polygon_bytes(const PolygonWithHoles& p) {
  std::size_t n = p.outer.capacity();
  for (const Ring& h : p.holes) n += h.capacity();
  return n * sizeof(Point2) + p.holes.capacity() * sizeof(Ring);
}

}  // namespace

void IncrementalSegmenter::State::start_frame(const OccupancyGrid& grid) {
  resolution = grid.resolution;
  origin = grid.origin;
  cells = cv::Mat(grid.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
  floor = cv::Mat::zeros(grid.cells.size(), CV_8UC1);
  labelled = cells.clone();
  result.labels = cv::Mat::zeros(grid.cells.size(), CV_32SC1);
  result.resolution = grid.resolution;
  result.origin = grid.origin;
  result.rooms.clear();
  result.passages.clear();
  ledger.clear(grid.cells.size());
  rooms.assign(static_cast<std::size_t>(ledger.next_id()), RoomState{});
  refreshed.clear();  // segment() measured every room's kind
  free_cells = 0;
  initialised = true;
  take_loaded_ledger();
}

// A loaded ledger (load_ledger()) in the new frame: its rooms become the previous ones, so that the
// first update carries their ids. Ignored when the saved map does not lie on whole cells of this one.
void IncrementalSegmenter::State::take_loaded_ledger() {
  if (!loaded) return;
  SavedLedger saved = std::move(*loaded);
  loaded.reset();
  const Segmentation& old = saved.published;
  cv::Point shift;
  if (std::abs(old.resolution - resolution) > 1e-9 * resolution ||
      !frame_shift(old.origin, old.labels.rows, origin, cells.rows, resolution, shift))
    return;
  const cv::Rect kept = cv::Rect(shift, old.labels.size()) & cv::Rect(cv::Point(), cells.size());
  if (!kept.empty()) old.labels(kept - shift).copyTo(result.labels(kept));
  ledger = std::move(saved.ledger);
  ledger.move(shift, cells.size());
  rooms.assign(static_cast<std::size_t>(ledger.next_id()), RoomState{});
}

// Re-embeds the state into grid's frame (same resolution). Returns false when the new frame does
// not contain the old one (what falls outside is dropped) or is offset by a fraction of a cell
// (the state is restarted).
bool IncrementalSegmenter::State::move_frame(const OccupancyGrid& grid, bool& restarted) {
  cv::Point shift;
  if (!frame_shift(origin, cells.rows, grid.origin, grid.height(), resolution, shift)) {
    start_frame(grid);
    restarted = true;
    return false;
  }
  const cv::Rect all(0, 0, grid.width(), grid.height());
  const cv::Rect old_in_new(shift.x, shift.y, cells.cols, cells.rows);
  const cv::Rect kept = old_in_new & all;
  auto moved = [&](const cv::Mat& old, int type, double fill) {
    cv::Mat out(grid.cells.size(), type, cv::Scalar(fill));
    if (!kept.empty()) old(kept - shift).copyTo(out(kept));
    return out;
  };
  cells = moved(cells, CV_8UC1, kUnknown);
  floor = moved(floor, CV_8UC1, 0);
  labelled = moved(labelled, CV_8UC1, kUnknown);
  result.labels = moved(result.labels, CV_32SC1, 0);
  report.shift = shift;
  ledger.move(shift, grid.cells.size());
  result.origin = grid.origin;
  origin = grid.origin;
  for (RoomState& room : rooms) {
    if (!room.alive) continue;
    room.box = (room.box + shift) & all;
    room.sum_c += static_cast<double>(room.cells) * shift.x;
    room.sum_r += static_cast<double>(room.cells) * shift.y;
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

// Brings result.rooms (sorted by id) up to date for one room: erased if dead, else labelled area and
// centroid from its state and, when given, the new polygon.
void IncrementalSegmenter::State::refresh_room(int id, const PolygonWithHoles* polygon) {
  auto it = std::lower_bound(result.rooms.begin(), result.rooms.end(), id,
                             [](const Room& room, int value) { return room.id < value; });
  const bool present = it != result.rooms.end() && it->id == id;
  const RoomState& state = rooms[static_cast<std::size_t>(id)];
  refreshed.push_back(id);
  if (!state.alive) {
    if (present) result.rooms.erase(it);
    return;
  }
  if (!present) {
    it = result.rooms.insert(it, Room{});
    it->id = id;
  }
  if (polygon != nullptr) it->polygon = *polygon;
  it->area = area(it->polygon);
  it->labelled_area = static_cast<double>(state.cells) * resolution * resolution;
  it->centroid = room_centroid(state, cells.rows);
}

// Runs work on the state; never keeps a half-updated state: after an exception the next update
// starts from scratch (ids stay unique).
template <class Work>
void IncrementalSegmenter::State::guarded(const Work& work) {
  try {
    work();
  } catch (...) {
    State fresh;
    fresh.options = options;
    const int keep_next = ledger.next_id();
    fresh.ledger = IdLedger(keep_next, cv::Mat());
    fresh.rooms.assign(static_cast<std::size_t>(keep_next), RoomState{});
    *this = std::move(fresh);
    throw;
  }
}

// Copy on write: a caller that still holds the previous labels keeps them unchanged.
void IncrementalSegmenter::State::detach_labels() {
  if (!result.labels.empty() && result.labels.u != nullptr && result.labels.u->refcount > 1)
    result.labels = result.labels.clone();
}

const Segmentation& IncrementalSegmenter::State::update(const OccupancyGrid& grid, const cv::Rect* hint) {
  validate(grid);  // the options were checked once, by the constructor (they cannot change after)
  report = {};
  detach_labels();

  std::string whole_reason;
  bool restarted = false;  // a hint is only trusted against a state in the same place
  if (!initialised) {
    start_frame(grid);
    whole_reason = "first update";
    restarted = true;
  } else if (std::abs(grid.resolution - resolution) > 1e-12 * resolution) {
    start_frame(grid);
    whole_reason = "the resolution changed";
    restarted = true;
  } else if (grid.cells.size() != cells.size() || !(grid.origin == origin)) {
    if (!move_frame(grid, restarted))
      whole_reason = restarted ? "the origin moved by a fraction of a cell" : "the new map does not contain the previous one";
  }
  const cv::Rect all(0, 0, grid.width(), grid.height());
  const cv::Rect search = (hint != nullptr && !restarted) ? (*hint & all) : all;
  const cv::Rect changed = changed_box(grid.cells, cells, search);
  report.changed = changed;
  if (changed.empty() && whole_reason.empty()) {
    report.kind = IncrementalUpdateReport::Kind::kUnchanged;
    report.every_room_relabelled = false;
    return result;
  }
  if (whole_reason.empty() && !options.windowed) whole_reason = "every update segments the whole map";
  guarded([&] {
    if (whole_reason.empty()) process(grid, changed);
    else segment_whole(grid, whole_reason);
  });
  return result;
}

const Segmentation& IncrementalSegmenter::State::resegment() {
  if (!initialised) return result;
  report = {};
  detach_labels();
  const OccupancyGrid grid{cells.clone(), resolution, origin};
  report.changed = cv::Rect(0, 0, grid.width(), grid.height());
  guarded([&] { segment_whole(grid, "resegmented as a whole", true); });
  return result;
}


// segment() on the whole grid, its rooms taking the ids of the rooms they overlap most (carried_ids):
// the state becomes batch's, holds and absorbed cells forgotten. Only at_rest (or with every update whole)
// does it leave out what the leave-out rows would (without_leave_out()).
void IncrementalSegmenter::State::segment_whole(const OccupancyGrid& grid, const std::string& reason, bool at_rest) {
  report.kind = IncrementalUpdateReport::Kind::kBatch;
  report.reason = reason;
  report.every_room_relabelled = true;
  report.relabelled_rooms.clear();
  report.relabelled_box = {};
  if (report.changed_cells == 0) report.changed_cells = cv::countNonZero(cells != grid.cells);
  cells = grid.cells.clone();
  Segmentation batch;
  if (cv::countNonZero(grid.cells == kFree) > 0) {
    SegmentationInput input;
    // While windowed updates go on, what a leave-out row takes out would come back with the next one.
    batch = segment(grid, at_rest || !options.windowed ? options.segment : without_leave_out(options.segment), &input);
    floor = input.floor;
    uncleaned = options.segment.clean && input.cleaned.floor.empty();
    labelled = input.labelled.cells.data == grid.cells.data ? cells.clone() : input.labelled.cells;
  } else {  // nothing free yet (a map before the first scan): no room, as before any update
    floor = cv::Mat::zeros(grid.cells.size(), CV_8UC1);
    labelled = cells.clone();
    uncleaned = false;
    batch.labels = cv::Mat::zeros(grid.cells.size(), CV_32SC1);
    batch.resolution = grid.resolution;
    batch.origin = grid.origin;
  }
  const int first_new = ledger.next_id();
  const int count = static_cast<int>(batch.rooms.size());
  const std::vector<int> ids = ledger.carry(result.labels, batch.labels, count);
  int kept = 0;
  for (std::size_t id = 1; id < rooms.size(); ++id) kept += rooms[id].alive;
  report.redecomposed_rooms = kept;
  report.new_rooms = static_cast<int>(std::count_if(ids.begin() + 1, ids.end(), [&](int id) { return id >= first_new; }));
  report.removed_rooms = kept - (count - report.new_rooms);
  Segmentation carried = renamed(std::move(batch), ids);
  result.labels = carried.labels;
  result.rooms = std::move(carried.rooms);
  result.passages = std::move(carried.passages);
  result.resolution = grid.resolution;
  result.origin = grid.origin;
  rooms.assign(static_cast<std::size_t>(ledger.next_id()), RoomState{});
  for (const Room& room : result.rooms) rooms[static_cast<std::size_t>(room.id)].alive = true;
  recount_rooms();
  for (RoomState& room : rooms) room.whole_cells = room.cells;
  report.region = cv::Rect(0, 0, grid.width(), grid.height());
  report.region_cells = static_cast<int>(free_cells);
}

void IncrementalSegmenter::State::process(const OccupancyGrid& grid, const cv::Rect& changed) {
  if (uncleaned) {
    segment_whole(grid, "the cleaning leaves the map no floor, so it is decomposed uncleaned and as a whole");
    return;
  }
  const ChangeMask mask = take_changes(grid, changed);
  // Before "unchanged": a window whose cleaning judged nothing new can still hide what only the whole
  // map's cleaning sees (its floor gone everywhere, a thin part judged by all its cells).
  if (options.segment.clean && cv::countNonZero(floor(mask.window)) == 0 && cv::countNonZero(floor) == 0) {
    segment_whole(grid, "the cleaning leaves the map no floor, so it is decomposed uncleaned and as a whole");
    return;
  }
  if (mask.judged_beyond) {
    segment_whole(grid, "a thin part of the free space runs beyond the cleaning's window (a ray or not, by all of it)");
    return;
  }
  report.changed_cells = mask.changed_cells;
  if (mask.changed_cells == 0) {
    report.kind = IncrementalUpdateReport::Kind::kUnchanged;
    report.every_room_relabelled = false;
    return;
  }
  if (static_cast<double>(mask.changed_cells) > options.batch_fraction * static_cast<double>(free_cells)) {
    segment_whole(grid, free_cells == 0 ? "first free space" : "more than the batch fraction of the free space changed");
    return;
  }
  cv::Mat blob_of;
  std::vector<Blob> blobs = find_blobs(mask, blob_of);
  Region region = choose_region(blobs);
  std::vector<int> nearest;  // cells that take the nearest room's label
  std::vector<int> touched_rooms = apply_changes(mask, blob_of, blobs, nearest);  // rooms whose area or cells changed
  relabelled = touched_rooms;  // the decomposition adds those whose runs change their id
  report.kind = IncrementalUpdateReport::Kind::kIncremental;
  if ((!region.ids.empty() || !region.window.empty()) && !redecompose(std::move(region), touched_rooms)) {
    segment_whole(grid, "no free space to decompose in the changed rooms");
    return;
  }
  label_from_nearest_rooms(nearest, touched_rooms);
  for (const int id : touched_rooms) refresh_room(id, nullptr);
  relabelled.insert(relabelled.end(), touched_rooms.begin(), touched_rooms.end());
  report_relabelled();
  update_kinds();
}

// The rooms whose cells this windowed update changed: those of the cells it lost, absorbed or gave
// the nearest room (apply_changes(), label_from_nearest_rooms()), and both rooms of every run of the
// decomposed region whose id changed (retire_old_rooms()); a room decomposed again into the same
// cells is not one of them. No other label is written.
void IncrementalSegmenter::State::report_relabelled() {
  std::vector<int>& ids = report.relabelled_rooms;
  ids.swap(relabelled);
  relabelled.clear();
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  report.relabelled_box = {};
  for (const int id : ids)
    if (rooms[static_cast<std::size_t>(id)].alive) report.relabelled_box = unite(report.relabelled_box, rooms[static_cast<std::size_t>(id)].box);
  report.every_room_relabelled = false;
}

// The kinds of the rooms this update changed and of their neighbours (how many rooms a room opens
// onto changes with theirs): room_shapes() on the box holding them, grown by a sample and with its
// corner on the sampling grid of the whole labels, so that a room's kind depends on the labels alone,
// not on which update measured it. A pass over the whole labels cost half of a median update.
void IncrementalSegmenter::State::update_kinds() {
  std::set<int> ids(refreshed.begin(), refreshed.end());
  refreshed.clear();
  std::vector<int> neighbours;
  for (const Passage& p : result.passages) {
    if (ids.count(p.room_a)) neighbours.push_back(p.room_b);
    if (ids.count(p.room_b)) neighbours.push_back(p.room_a);
  }
  ids.insert(neighbours.begin(), neighbours.end());
  cv::Rect box;
  for (const int id : ids)
    if (id > 0 && static_cast<std::size_t>(id) < rooms.size() && rooms[static_cast<std::size_t>(id)].alive)
      box |= rooms[static_cast<std::size_t>(id)].box;
  if (box.empty()) return;
  const RoomKindOptions& options_kinds = options.segment.kinds;
  const int step = room_kind_sample_step(options_kinds, resolution);
  const cv::Rect grown_box = grown(box, step, result.labels.size());
  const cv::Point corner(grown_box.x / step * step, grown_box.y / step * step);
  const cv::Rect crop = cv::Rect(corner, grown_box.br()) & cv::Rect(cv::Point(), result.labels.size());
  const std::vector<RoomShape> shapes = room_shapes(result.labels(crop), resolution, options_kinds);
  for (Room& room : result.rooms) {
    if (!ids.count(room.id)) continue;
    const auto i = static_cast<std::size_t>(room.id - 1);
    room.kind = i < shapes.size() ? room_kind(shapes[i], options_kinds) : RoomKind::kRoom;
  }
}

// The state's cells, floor and labelled cells are the grid's from here on; the returned mask is all
// that remains of how they were.
ChangeMask IncrementalSegmenter::State::take_changes(const OccupancyGrid& grid, const cv::Rect& changed) {
  ChangeMask mask;
  if (changed.empty()) return mask;
  // segment()'s front end over the window (segmentation_input): what lies farther keeps its last cleaning.
  SegmentationInput input;
  if (!local_input(grid, changed, mask, input)) {
    mask.window = grown(changed, front_end_reach(options.segment, resolution), grid.cells.size());
    input = window_input(grid, mask);
    if (mask.judged_beyond) return mask;  // the whole map is segmented instead
  }
  const cv::Rect& window = mask.window;
  const cv::Mat& new_floor = input.floor;
  const cv::Mat& new_labelled = input.labelled.cells;

  mask.change = cv::Mat::zeros(window.size(), CV_8UC1);
  int top = -1, bottom = -1, left = INT_MAX, right = -1;  // the changed cells' box
  for (int r = 0; r < window.height; ++r) {
    const unsigned char* old_cell = labelled.ptr<unsigned char>(window.y + r) + window.x;
    const unsigned char* new_cell = new_labelled.ptr<unsigned char>(r);
    const unsigned char* old_floor = floor.ptr<unsigned char>(window.y + r) + window.x;
    const unsigned char* nf = new_floor.ptr<unsigned char>(r);
    // Most of the window is as before: only the columns where a byte differs are looked at.
    int c0 = INT_MAX, c1 = -1;
    differing_columns(old_cell, new_cell, window.width, c0, c1);
    differing_columns(old_floor, nf, window.width, c0, c1);
    unsigned char* d = mask.change.ptr<unsigned char>(r);
    int changed_in_row = 0;
    for (int c = c0; c <= c1; ++c) {
      const bool was = old_cell[c] == kFree, is = new_cell[c] == kFree;
      d[c] = static_cast<unsigned char>((is && !was ? kGained : 0) | (was && !is ? kLost : 0) |
                                        ((old_floor[c] != 0) != (nf[c] != 0) ? kFloorChanged : 0));
      if (d[c] == 0) continue;
      ++changed_in_row;
      left = std::min(left, c);
      right = std::max(right, c);
    }
    if (changed_in_row == 0) continue;
    mask.changed_cells += changed_in_row;
    if (top < 0) top = r;
    bottom = r;
  }
  if (top >= 0) mask.active = cv::Rect(left, top, right - left + 1, bottom - top + 1);
  grid.cells(changed).copyTo(cells(changed));
  new_floor.copyTo(floor(window));
  new_labelled.copyTo(labelled(window));
  return mask;
}

namespace {

// Whether cells == kFree and floor == 0 anywhere (two views of one box): a free cell the cleaning
// removed (a ray, inside or outside the building), when the binarization leaves the free cells as they are.
bool removes_free_cells(const cv::Mat& cells, const cv::Mat& floor) {
  for (int r = 0; r < cells.rows; ++r) {
    const unsigned char* c = cells.ptr<unsigned char>(r);
    const unsigned char* f = floor.ptr<unsigned char>(r);
    int any = 0;
    for (int k = 0; k < cells.cols; ++k) any |= static_cast<int>(c[k] == kFree) & static_cast<int>(f[k] == 0);
    if (any != 0) return true;
  }
  return false;
}

}  // namespace

// segment()'s front end over the changed box grown by the floor tests' reach only, when that is all
// the change can move: the cleaning removed no free cell within the full reach before, and removes
// none in the small window now, nor cuts a thin part reaching into it (so no inside or outside is
// judged near the change, and the inside closing's reach and context, 2 m twice over, are not
// needed: a window of a tenth of the cells for a change of a few cells). False: the full window.
bool IncrementalSegmenter::State::local_input(const OccupancyGrid& grid, const cv::Rect& changed, ChangeMask& mask,
                                              SegmentationInput& input) const {
  const SegmentOptions& o = options.segment;
  const int local = front_end_local_reach(o, resolution);
  if (local < 0) return false;
  const cv::Rect full = grown(changed, front_end_reach(o, resolution), grid.cells.size());
  if (removes_free_cells(cells(full), floor(full))) return false;
  const cv::Rect window = grown(changed, local, grid.cells.size());
  input = segmentation_input(grid, window, o, local);
  if (!input.thin_parts_cut.empty() || removes_free_cells(grid.cells(window), input.floor)) return false;
  mask.window = window;
  return true;
}

// segment()'s front end over mask.window, grown until no thin part reaching into it runs out of the
// context the cleaning is given (such a part is judged a ray or not by all its cells): each round the
// window takes the parts' box and its context reaches farther along them. A window that would cover
// more than half the map is given up (judged_beyond): a whole-map update costs no more.
SegmentationInput IncrementalSegmenter::State::window_input(const OccupancyGrid& grid, ChangeMask& mask) const {
  const long long map_cells = static_cast<long long>(grid.width()) * grid.height();
  for (;;) {
    SegmentationInput input = segmentation_input(grid, mask.window, options.segment);
    if (input.thin_parts_cut.empty()) return input;
    const cv::Rect wider = mask.window | input.thin_parts_cut;
    if (2LL * wider.area() > map_cells || wider == mask.window) {
      mask.judged_beyond = true;
      return input;
    }
    mask.window = wider;
  }
}

// Blobs of changed cells (8-connected), each with the rooms it touches in raster order of first
// contact: the order in which choose_region adds them, so region ids never depend on history. A
// labelled cell touches its own room, any other cell the rooms around it.
std::vector<Blob> IncrementalSegmenter::State::find_blobs(const ChangeMask& mask, cv::Mat& blob_of) const {
  const cv::Rect& window = mask.window;
  const cv::Mat& labels = result.labels;
  const int h = labels.rows, w = labels.cols;
  // The changed cells lie mostly well inside the window (grown by the front end's reach): the
  // components are found within their bounding box (blob_of covers that box only).
  const cv::Rect& active = mask.active;
  cv::Mat stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask.change(active) != 0, blob_of, stats, centroids, 8, CV_32S);
  std::vector<Blob> blobs(static_cast<std::size_t>(n));
  for (int b = 1; b < n; ++b)
    blobs[static_cast<std::size_t>(b)].box =
        cv::Rect(stats.at<int>(b, cv::CC_STAT_LEFT) + window.x + active.x, stats.at<int>(b, cv::CC_STAT_TOP) + window.y + active.y,
                 stats.at<int>(b, cv::CC_STAT_WIDTH), stats.at<int>(b, cv::CC_STAT_HEIGHT));
  for (int r = active.y; r < active.y + active.height; ++r) {
    const unsigned char* d = mask.change.ptr<unsigned char>(r);
    const int* b = blob_of.ptr<int>(r - active.y);
    int open_before = INT_MIN;  // column of the row's last unlabelled changed cell
    for (int c = active.x; c < active.x + active.width; ++c) {
      if (d[c] == 0) continue;
      Blob& blob = blobs[static_cast<std::size_t>(b[c - active.x])];
      const int gr = window.y + r, gc = window.x + c;
      blob.gained += (d[c] & kGained) != 0;
      blob.lost += (d[c] & kLost) != 0;
      if (d[c] & kFloorChanged) {
        blob.floor = true;
        blob.structural = blob.structural || floor.at<unsigned char>(gr, gc) == 0;  // floor lost
      }
      const int own = labels.at<int>(gr, gc);
      if (own > 0) {
        add_unique(blob.touched, own);
        continue;
      }
      // The cell before it in the row (the same blob) looked at all but the column on its right.
      const int first_column = open_before == c - 1 ? gc + 1 : std::max(0, gc - 1);
      open_before = c;
      for (int nr = std::max(0, gr - 1); nr <= std::min(h - 1, gr + 1); ++nr) {
        const int* row = labels.ptr<int>(nr);
        for (int nc = first_column; nc <= std::min(w - 1, gc + 1); ++nc)
          if (row[nc] > 0) add_unique(blob.touched, row[nc]);
      }
    }
  }
  return blobs;
}

// Decides per blob: its cells only take the nearest room's label (the floor did not change), join
// the one room it touches (small, the floor only grew), take the nearest of the rooms it touches
// (small, the floor only grew, where they already meet), or be decomposed again together with every
// room it touches. A room's allowance is charged as its blobs are seen, so later blobs see what
// earlier ones took.
Region IncrementalSegmenter::State::choose_region(std::vector<Blob>& blobs) {
  const long long absorb_cells =
      static_cast<long long>(std::floor(options.absorb_area / (resolution * resolution) + 1e-9));
  Region region;
  std::vector<char> in_region(rooms.size(), 0);
  auto add_region = [&](int id) {
    if (!in_region[static_cast<std::size_t>(id)]) {
      in_region[static_cast<std::size_t>(id)] = 1;
      region.ids.push_back(id);
    }
  };
  // A room takes newly seen cells without a decomposition until they add up to its allowance.
  auto allowance = [&](const RoomState& room) {
    return std::max(absorb_cells, static_cast<long long>(options.absorb_fraction * static_cast<double>(room.cells)));
  };
  for (std::size_t b = 1; b < blobs.size(); ++b) {
    Blob& blob = blobs[b];
    if (!blob.floor) continue;  // labels only (label_from_nearest_rooms)
    // A blob touching several rooms may join them (a door seen open): decomposed again unless it is
    // small and lies where they already meet.
    const long long taken = blob.gained + blob.lost;
    const bool across = blob.touched.size() > 1 && options.absorb_across_rooms && !blob.structural &&
                        taken <= absorb_cells && rooms_meet_at(blob);
    blob.absorb = across || (blob.touched.size() == 1 && (!blob.structural || is_speck(blob)));
    for (const int id : blob.touched) {
      const RoomState& room = rooms[static_cast<std::size_t>(id)];
      blob.absorb = blob.absorb && room.absorbed + taken <= allowance(room);
    }
    if (blob.absorb) {
      for (const int id : blob.touched) rooms[static_cast<std::size_t>(id)].absorbed += taken;  // later blobs see it
      ++report.absorbed_blobs;
    } else {
      for (const int id : blob.touched) add_region(id);
      region.window = unite(region.window, blob.box);
    }
  }
  return region;
}

// Whether the rooms a blob touches already meet next to it (cells of two of them side by side within
// a cell of its box), all of them linked so: the blob then lies at their cut and cannot connect rooms
// that were apart.
bool IncrementalSegmenter::State::rooms_meet_at(const Blob& blob) const {
  const std::vector<int>& ids = blob.touched;
  std::vector<std::size_t> group(ids.size());  // union-find over the touched rooms
  std::iota(group.begin(), group.end(), std::size_t{0});
  const auto find = [&group](std::size_t i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  std::size_t groups = ids.size();
  const auto link = [&](int a, int b) {
    if (a == b || a <= 0 || b <= 0) return;
    const auto i = std::find(ids.begin(), ids.end(), a), j = std::find(ids.begin(), ids.end(), b);
    if (i == ids.end() || j == ids.end()) return;
    const std::size_t gi = find(static_cast<std::size_t>(i - ids.begin())), gj = find(static_cast<std::size_t>(j - ids.begin()));
    if (gi == gj) return;
    group[std::max(gi, gj)] = std::min(gi, gj);
    --groups;
  };
  const cv::Mat& labels = result.labels;
  const cv::Rect around = grown(blob.box, 1, labels.size());
  for (int r = around.y; r < around.y + around.height && groups > 1; ++r) {
    const int* row = labels.ptr<int>(r);
    const int* below = r + 1 < around.y + around.height ? labels.ptr<int>(r + 1) : nullptr;
    for (int c = around.x; c < around.x + around.width; ++c) {
      if (c + 1 < around.x + around.width) link(row[c], row[c + 1]);
      if (below) link(row[c], below[c]);
    }
  }
  return groups == 1;
}

// A speck: a small structural blob of one room (an obstacle seen inside it, a wall's edge moved by
// a few centimetres, free cells that only change the decomposed free space). Newly free cells can
// only join parts of the room; lost ones could cut it, so the room's cells around them (in the
// box grown by one cell, with the newly free ones) must stay one 4-connected piece, or none when
// they were a detached island: any path of the room through the box can then go round.
bool IncrementalSegmenter::State::is_speck(const Blob& blob) const {
  if (blob.lost == 0) return true;  // only the decomposed free space changed: absorbed like any new free blob
  const int limit = static_cast<int>(std::floor(options.speck_size / resolution + 1e-9));
  if (blob.box.width > limit || blob.box.height > limit) return false;
  const int id = blob.touched.front();
  if (rooms[static_cast<std::size_t>(id)].cells <= blob.lost) return false;  // nothing of the room would be left
  const cv::Rect around = grown(blob.box, 1, cells.size());
  cv::Mat room(around.size(), CV_8UC1);
  for (int r = 0; r < around.height; ++r) {
    const unsigned char* cell = labelled.ptr<unsigned char>(around.y + r) + around.x;
    const int* label = result.labels.ptr<int>(around.y + r) + around.x;
    unsigned char* out = room.ptr<unsigned char>(r);
    for (int c = 0; c < around.width; ++c) out[c] = cell[c] == kFree && (label[c] == id || label[c] == 0) ? 255 : 0;
  }
  cv::Mat components;
  return cv::connectedComponents(room, components, 4, CV_32S) <= 2;  // background and at most one piece
}

// Applies the cell changes to the labels: lost cells leave their room, absorbed ones join theirs,
// cells of blobs that left the floor alone wait for the nearest room (listed in nearest), the others
// wait (kPending) for the decomposition. Returns the rooms whose cells changed (those decomposed
// again are refreshed by the decomposition).
std::vector<int> IncrementalSegmenter::State::apply_changes(const ChangeMask& mask, const cv::Mat& blob_of,
                                                            const std::vector<Blob>& blobs, std::vector<int>& nearest) {
  const cv::Rect& window = mask.window;
  const cv::Rect& active = mask.active;  // every changed cell lies in it
  cv::Mat& labels = result.labels;
  std::vector<int> touched_rooms;
  for (int r = active.y; r < active.y + active.height; ++r) {
    const unsigned char* d = mask.change.ptr<unsigned char>(r);
    const int* b = blob_of.ptr<int>(r - active.y);
    int* l = labels.ptr<int>(window.y + r) + window.x;
    for (int c = active.x; c < active.x + active.width; ++c) {
      if (d[c] & kLost) {
        --free_cells;
        if (l[c] <= 0) continue;
        RoomState& room = rooms[static_cast<std::size_t>(l[c])];
        --room.cells;
        room.sum_c -= window.x + c;
        room.sum_r -= window.y + r;
        add_unique(touched_rooms, l[c]);
        l[c] = 0;
      } else if (d[c] & kGained) {
        ++free_cells;
        const Blob& blob = blobs[static_cast<std::size_t>(b[c - active.x])];
        // An absorbed blob of several rooms (where they meet): each cell takes the nearest of them.
        if (!blob.floor || (blob.absorb && blob.touched.size() > 1)) {
          l[c] = 0;
          nearest.push_back((window.y + r) * labels.cols + window.x + c);
          continue;
        }
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

// Each listed cell (row * cols + column, unlabelled) takes the label of the nearest room along the
// cells left free, else in a straight line, as segment() labels the free cells no piece covers.
void IncrementalSegmenter::State::label_from_nearest_rooms(const std::vector<int>& cells_to_label,
                                                           std::vector<int>& touched_rooms) {
  if (cells_to_label.empty()) return;
  cv::Mat& labels = result.labels;
  label_near_cells(cells_to_label);
  const int* data = labels.ptr<int>(0);
  for (const int index : cells_to_label) {
    const int id = data[index];
    if (id <= 0) continue;  // no room anywhere yet
    RoomState& room = rooms[static_cast<std::size_t>(id)];
    const int r = index / labels.cols, c = index % labels.cols;
    ++room.cells;
    room.sum_c += c;
    room.sum_r += r;
    room.box = unite(room.box, cv::Rect(c, r, 1, 1));
    add_unique(touched_rooms, id);
  }
}

// The listed cells labelled from the rooms within a margin around them first (a few scans' cells on a
// map of millions: the whole map's free mask and label index would cost more than the labelling);
// the whole map only for cells that finds no room for.
void IncrementalSegmenter::State::label_near_cells(const std::vector<int>& cells_to_label) {
  cv::Mat& labels = result.labels;
  const int cols = labels.cols;
  int c0 = INT_MAX, c1 = -1, r0 = INT_MAX, r1 = -1;
  for (const int index : cells_to_label) {
    c0 = std::min(c0, index % cols), c1 = std::max(c1, index % cols);
    r0 = std::min(r0, index / cols), r1 = std::max(r1, index / cols);
  }
  constexpr int kMargin = 64;  // cells: beyond a room's reach of a speck on any map seen so far
  const cv::Rect box = grown(cv::Rect(c0, r0, c1 - c0 + 1, r1 - r0 + 1), kMargin, labels.size());
  if (box.area() * 4 >= labels.size().area()) {
    complete_unlabelled_cells(labels, labelled == kFree, cells_to_label);
    return;
  }
  cv::Mat local = labels(box).clone();
  std::vector<int> local_cells;
  local_cells.reserve(cells_to_label.size());
  for (const int index : cells_to_label) local_cells.push_back((index / cols - box.y) * box.width + index % cols - box.x);
  complete_unlabelled_cells(local, labelled(box) == kFree, local_cells);
  std::vector<int> rest;  // no room within the box
  int* data = labels.ptr<int>(0);
  const int* found = local.ptr<int>(0);
  for (std::size_t k = 0; k < cells_to_label.size(); ++k) {
    const int id = found[local_cells[k]];
    if (id > 0) data[cells_to_label[k]] = id;
    else rest.push_back(cells_to_label[k]);
  }
  if (!rest.empty()) complete_unlabelled_cells(labels, labelled == kFree, rest);
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
  state_->options = options;
}

IncrementalSegmenter::~IncrementalSegmenter() = default;
IncrementalSegmenter::IncrementalSegmenter(IncrementalSegmenter&&) noexcept = default;
IncrementalSegmenter& IncrementalSegmenter::operator=(IncrementalSegmenter&&) noexcept = default;

const Segmentation& IncrementalSegmenter::update(const OccupancyGrid& grid) {
  ++results_;
  return state_->update(grid, nullptr);
}

const Segmentation& IncrementalSegmenter::update(const OccupancyGrid& grid, const cv::Rect& changed) {
  ++results_;
  return state_->update(grid, &changed);
}

const Segmentation& IncrementalSegmenter::resegment() {
  ++results_;
  return state_->resegment();
}

const Segmentation& IncrementalSegmenter::result() const { return state_->result; }

const IncrementalUpdateReport& IncrementalSegmenter::last_update() const { return state_->report; }

const IncrementalOptions& IncrementalSegmenter::options() const { return state_->options; }

std::size_t IncrementalSegmenter::state_bytes() const {
  const State& s = *state_;
  std::size_t bytes = s.cells.total() * s.cells.elemSize() + s.floor.total() * s.floor.elemSize() +
                      s.ledger.bytes() +
                      s.labelled.total() * s.labelled.elemSize() + s.result.labels.total() * s.result.labels.elemSize();
  bytes += s.rooms.capacity() * sizeof(RoomState);
  bytes += s.result.rooms.capacity() * sizeof(Room);
  for (const Room& room : s.result.rooms) bytes += polygon_bytes(room.polygon);
  bytes += s.result.passages.capacity() * sizeof(Passage);
  return bytes;
}

void IncrementalSegmenter::save_ledger(std::ostream& out) const {
  const State& s = *state_;
  if (!s.initialised) throw Error("there are no rooms to save ids of yet (no update so far)");
  write_ledger(out, s.ledger, s.result);
}

void IncrementalSegmenter::load_ledger(std::istream& in) {
  SavedLedger saved = read_ledger(in);  // throws before anything is forgotten
  reset();
  state_->ledger = IdLedger(saved.ledger.next_id(), cv::Mat());
  state_->loaded = std::move(saved);
}

void IncrementalSegmenter::reset() {
  ++results_;
  IncrementalOptions options = state_->options;
  state_ = std::make_unique<State>();
  state_->options = options;
}

}  // namespace topocut
