#include "topocut/segmentation/incremental_segmenter.h"

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/core/geometry.h"
#include "topocut/segmentation/segmenter.h"
#include "segmentation/growing_map.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;

// A synthetic floor plan (15 m x 8 m at 0.05 m): a corridor along the bottom and four rooms above
// it, each with an 18-cell door into the corridor. Walls are 4 cells thick.
struct FloorPlan {
  OccupancyGrid world;
  cv::Rect corridor;
  std::vector<cv::Rect> rooms;  // interiors
  std::vector<cv::Rect> doors;  // openings in the corridor wall
};

FloorPlan floor_plan() {
  FloorPlan plan;
  plan.world.cells = cv::Mat(160, 300, CV_8UC1, cv::Scalar(kOccupied));
  plan.world.resolution = kRes;
  plan.corridor = cv::Rect(4, 124, 292, 32);
  plan.world.cells(plan.corridor).setTo(kFree);
  const int widths[4] = {70, 60, 80, 66};
  int x = 4;
  for (int i = 0; i < 4; ++i) {
    const cv::Rect room(x, 4, widths[i], 116);
    plan.rooms.push_back(room);
    plan.world.cells(room).setTo(kFree);
    const cv::Rect door(x + widths[i] / 2 - 9, 120, 18, 4);
    plan.doors.push_back(door);
    plan.world.cells(door).setTo(kFree);
    x += widths[i] + 4;
  }
  return plan;
}

// The grid a robot knows when only the given parts of the world have been seen: those rectangles,
// grown by the wall thickness so that walls show as obstacles, copied from the world; the rest
// unknown.
OccupancyGrid reveal(const FloorPlan& plan, const std::vector<cv::Rect>& seen) {
  OccupancyGrid grid = plan.world;
  grid.cells = cv::Mat(plan.world.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
  const cv::Rect all(0, 0, grid.width(), grid.height());
  for (const cv::Rect& r : seen) {
    const cv::Rect g = cv::Rect(r.x - 4, r.y - 4, r.width + 8, r.height + 8) & all;
    plan.world.cells(g).copyTo(grid.cells(g));
  }
  return grid;
}

// Every cell that segment()'s cleaning leaves free (with options) labelled exactly once with the id of
// a listed room, nothing else labelled, rooms sorted by unique id with area and centroid of their cells.
void expect_valid(const OccupancyGrid& grid, const Segmentation& s, const SegmentOptions& options = IncrementalOptions{}.segment) {
  ASSERT_EQ(s.labels.size(), grid.cells.size());
  ASSERT_EQ(s.labels.type(), CV_32SC1);
  SegmentationInput input;
  segment(grid, options, &input);
  const cv::Mat& labelled = input.labelled.cells;
  std::map<int, long long> count;
  std::map<int, std::pair<double, double>> sums;
  for (int r = 0; r < grid.height(); ++r)
    for (int c = 0; c < grid.width(); ++c) {
      const int l = s.labels.at<int>(r, c);
      if (labelled.at<unsigned char>(r, c) == kFree) {
        ASSERT_GT(l, 0) << "free cell (" << c << ", " << r << ") unlabelled";
        ++count[l];
        sums[l].first += c;
        sums[l].second += r;
      } else {
        ASSERT_EQ(l, 0) << "non-free cell (" << c << ", " << r << ") labelled";
      }
    }
  ASSERT_EQ(count.size(), s.rooms.size());
  for (std::size_t i = 0; i < s.rooms.size(); ++i) {
    const Room& room = s.rooms[i];
    if (i > 0) {
      EXPECT_LT(s.rooms[i - 1].id, room.id);
    }
    ASSERT_TRUE(count.count(room.id)) << "room " << room.id << " labels no cell";
    const long long n = count[room.id];
    EXPECT_NEAR(room.labelled_area, n * kRes * kRes, 1e-9);
    EXPECT_NEAR(room.area, area(room.polygon), 1e-9);
    const double cx = grid.origin.x + (sums[room.id].first / n + 0.5) * kRes;
    const double cy = grid.origin.y + (grid.height() - sums[room.id].second / n - 0.5) * kRes;
    EXPECT_NEAR(room.centroid.x, cx, 1e-6);
    EXPECT_NEAR(room.centroid.y, cy, 1e-6);
    EXPECT_GE(room.polygon.outer.size(), 3u);
  }
  for (const Passage& p : s.passages) {
    EXPECT_LT(p.room_a, p.room_b);
    EXPECT_TRUE(count.count(p.room_a) && count.count(p.room_b));
  }
}

// Cells of each room id.
std::map<int, std::vector<int>> cells_by_room(const cv::Mat& labels) {
  std::map<int, std::vector<int>> out;
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      if (const int l = labels.at<int>(r, c); l > 0) out[l].push_back(r * labels.cols + c);
  return out;
}

// Rooms the change cannot reach must keep their id and exactly their cells: rooms of before
// farther than one cell from every cell whose free state changed, and not sharing a passage with
// such a near room (the segmenter decomposes those neighbours again with it, as batch would decide
// on the cuts between them again) unless through_passages is false (no neighbours decomposed).
void expect_untouched_stable(const OccupancyGrid& before_grid, const Segmentation& before, const OccupancyGrid& after_grid,
                             const Segmentation& after, bool through_passages = true) {
  const cv::Mat changed = (before_grid.cells == kFree) != (after_grid.cells == kFree);
  cv::Mat near_change;
  cv::dilate(changed, near_change, cv::Mat::ones(3, 3, CV_8UC1));
  const auto old_rooms = cells_by_room(before.labels);
  const auto new_rooms = cells_by_room(after.labels);
  std::set<int> reached;
  for (const auto& [id, cells] : old_rooms)
    if (std::any_of(cells.begin(), cells.end(), [&](int i) { return near_change.data[i] != 0; })) reached.insert(id);
  const std::set<int> near = reached;
  for (const Passage& p : before.passages) {
    if (!through_passages) break;
    if (near.count(p.room_a)) reached.insert(p.room_b);
    if (near.count(p.room_b)) reached.insert(p.room_a);
  }
  for (const auto& [id, cells] : old_rooms) {
    if (reached.count(id)) continue;
    ASSERT_TRUE(new_rooms.count(id)) << "untouched room " << id << " lost its id";
    EXPECT_EQ(new_rooms.at(id), cells) << "untouched room " << id << " changed its cells";
  }
}

// Number of rooms sharing a passage with room id.
int passage_neighbours(const Segmentation& s, int id) {
  std::set<int> out;
  for (const Passage& p : s.passages) {
    if (p.room_a == id) out.insert(p.room_b);
    if (p.room_b == id) out.insert(p.room_a);
  }
  return static_cast<int>(out.size());
}

// Agreement of two labellings of the same free cells, in the shape of precision and recall with b
// as the reference: mean over a's segments of their best overlap fraction with a b segment, and
// the reverse.
std::pair<double, double> agreement(const cv::Mat& a, const cv::Mat& b) {
  std::map<std::pair<int, int>, long long> joint;
  std::map<int, long long> na, nb;
  for (int i = 0; i < static_cast<int>(a.total()); ++i) {
    const int la = a.at<int>(i), lb = b.at<int>(i);
    if (la <= 0 || lb <= 0) continue;
    ++joint[{la, lb}];
    ++na[la];
    ++nb[lb];
  }
  std::map<int, long long> best_a, best_b;
  for (const auto& [key, n] : joint) {
    best_a[key.first] = std::max(best_a[key.first], n);
    best_b[key.second] = std::max(best_b[key.second], n);
  }
  double precision = 0.0, recall = 0.0;
  for (const auto& [l, n] : na) precision += static_cast<double>(best_a[l]) / n;
  for (const auto& [l, n] : nb) recall += static_cast<double>(best_b[l]) / n;
  return {precision / na.size(), recall / nb.size()};
}

// The room pairs joined by passages, with a's ids translated to b's by largest overlap.
std::set<std::pair<int, int>> passage_pairs_in(const Segmentation& a, const Segmentation& b) {
  std::map<int, std::map<int, long long>> overlap;
  for (int i = 0; i < static_cast<int>(a.labels.total()); ++i)
    if (a.labels.at<int>(i) > 0 && b.labels.at<int>(i) > 0) ++overlap[a.labels.at<int>(i)][b.labels.at<int>(i)];
  std::map<int, int> to_b;
  for (const auto& [id, counts] : overlap)
    to_b[id] = std::max_element(counts.begin(), counts.end(), [](auto x, auto y) { return x.second < y.second; })->first;
  std::set<std::pair<int, int>> pairs;
  for (const Passage& p : a.passages) {
    const int x = to_b[p.room_a], y = to_b[p.room_b];
    if (x != y) pairs.insert({std::min(x, y), std::max(x, y)});
  }
  return pairs;
}

std::set<std::pair<int, int>> passage_pairs(const Segmentation& s) {
  std::set<std::pair<int, int>> pairs;
  for (const Passage& p : s.passages) pairs.insert({p.room_a, p.room_b});
  return pairs;
}

IncrementalOptions trivial_options() {
  IncrementalOptions options;
  options.segment.decompose = false;  // one room per free-space component: answers by hand
  options.split_after = options.merge_after = 1;  // nothing held back: each update as batch would
  return options;
}

TEST(IncrementalSegmenter, FirstUpdateEqualsBatch) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter segmenter;
  const Segmentation& s = segmenter.update(plan.world);
  expect_valid(plan.world, s);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kBatch);
  const Segmentation batch = segment(plan.world);
  // Same pieces, numbered the same way (both by first cell in raster order on a fresh start).
  EXPECT_EQ(cv::countNonZero(s.labels != batch.labels), 0);
  ASSERT_EQ(s.rooms.size(), batch.rooms.size());
  EXPECT_EQ(s.passages.size(), batch.passages.size());
}

TEST(IncrementalSegmenter, FirstUpdateEqualsBatchOnANoisyMap) {
  // Speckle, diagonal pinches, tiny free islands and unknown patches: the paths where labels come
  // from the breadth-first fill and the straight-line rule, not from the pieces.
  FloorPlan plan = floor_plan();
  std::mt19937 rng(12345);
  cv::Mat& cells = plan.world.cells;
  for (int i = 0; i < 3000; ++i) {
    const int r = static_cast<int>(rng() % cells.rows), c = static_cast<int>(rng() % cells.cols);
    const unsigned v = rng() % 3;
    cells.at<unsigned char>(r, c) = v == 0 ? kOccupied : (v == 1 ? kFree : kUnknown);
  }
  IncrementalSegmenter segmenter;
  const Segmentation& s = segmenter.update(plan.world);
  expect_valid(plan.world, s);
  // Batch with the segmenter's own options (segment()'s defaults, the real-map cleaning included).
  const Segmentation batch = segment(plan.world, IncrementalOptions{}.segment);
  EXPECT_EQ(cv::countNonZero(s.labels != batch.labels), 0);
  ASSERT_EQ(s.rooms.size(), batch.rooms.size());
  for (std::size_t i = 0; i < s.rooms.size(); ++i) {
    EXPECT_EQ(s.rooms[i].id, batch.rooms[i].id);
    EXPECT_EQ(s.rooms[i].polygon, batch.rooms[i].polygon);
  }
}

TEST(IncrementalSegmenter, SeparateRoomsRevealedOneByOneKeepTheirIds) {
  // Trivial mode, rooms without doors: each revealed room is its own component, so it must get a
  // new id while every earlier room keeps its id and cells.
  FloorPlan plan = floor_plan();
  for (const cv::Rect& door : plan.doors) plan.world.cells(door).setTo(kOccupied);
  IncrementalOptions options = trivial_options();
  options.batch_fraction = 10.0;  // each room is nearly as large as all before it: stay incremental
  IncrementalSegmenter segmenter(options);
  std::vector<cv::Rect> seen{plan.corridor};
  OccupancyGrid previous = reveal(plan, seen);
  Segmentation before = segmenter.update(previous);
  expect_valid(previous, before);
  ASSERT_EQ(before.rooms.size(), 1u);
  const int corridor_id = before.rooms[0].id;
  std::set<int> ids{corridor_id};
  for (std::size_t k = 0; k < plan.rooms.size(); ++k) {
    seen.push_back(plan.rooms[k]);
    const OccupancyGrid grid = reveal(plan, seen);
    const Segmentation after = segmenter.update(grid);
    expect_valid(grid, after);
    expect_untouched_stable(previous, before, grid, after);
    ASSERT_EQ(after.rooms.size(), k + 2);
    // The room just revealed has a fresh id; all earlier ids are still there.
    const cv::Point inside(plan.rooms[k].x + 5, plan.rooms[k].y + 5);
    const int new_id = after.labels.at<int>(inside);
    EXPECT_FALSE(ids.count(new_id)) << "revealed room reused id " << new_id;
    ids.insert(new_id);
    for (const Room& room : after.rooms) EXPECT_TRUE(ids.count(room.id));
    EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kIncremental);
    EXPECT_EQ(segmenter.last_update().redecomposed_rooms, 0);
    EXPECT_EQ(segmenter.last_update().new_rooms, 1);
    previous = grid;
    before = after;
  }
  EXPECT_EQ(before.labels.at<int>(plan.corridor.y + 2, plan.corridor.x + 2), corridor_id);
}

TEST(IncrementalSegmenter, DoorOpeningMergesIntoTheLargerRoomsId) {
  // Trivial mode: opening a door joins two components; the joined room covers all of both old
  // rooms, so the first candidate by overlap (the larger old room) keeps its id.
  FloorPlan plan = floor_plan();
  for (const cv::Rect& door : plan.doors) plan.world.cells(door).setTo(kOccupied);
  IncrementalSegmenter segmenter(trivial_options());
  const Segmentation first = segmenter.update(plan.world);
  ASSERT_EQ(first.rooms.size(), 5u);
  const int corridor_id = first.labels.at<int>(plan.corridor.y + 1, plan.corridor.x + 1);
  const int room0_id = first.labels.at<int>(plan.rooms[0].y + 1, plan.rooms[0].x + 1);
  OccupancyGrid opened = plan.world;
  opened.cells = plan.world.cells.clone();
  opened.cells(plan.doors[0]).setTo(kFree);
  const Segmentation second = segmenter.update(opened);
  expect_valid(opened, second);
  ASSERT_EQ(second.rooms.size(), 4u);
  // corridor 292x32 = 9344 cells > room 0 70x116 = 8120 cells.
  EXPECT_EQ(second.labels.at<int>(plan.rooms[0].y + 1, plan.rooms[0].x + 1), corridor_id);
  EXPECT_FALSE(std::any_of(second.rooms.begin(), second.rooms.end(), [&](const Room& r) { return r.id == room0_id; }));
  for (int k = 1; k < 4; ++k)
    EXPECT_EQ(second.labels.at<int>(plan.rooms[k].y + 1, plan.rooms[k].x + 1),
              first.labels.at<int>(plan.rooms[k].y + 1, plan.rooms[k].x + 1));
  EXPECT_EQ(segmenter.last_update().redecomposed_rooms, 2);

  // Closed again: room 0 comes back where its id last lay and takes that id back, no new one.
  const Segmentation third = segmenter.update(plan.world);
  expect_valid(plan.world, third);
  ASSERT_EQ(third.rooms.size(), 5u);
  EXPECT_EQ(third.labels.at<int>(plan.rooms[0].y + 1, plan.rooms[0].x + 1), room0_id);
  EXPECT_EQ(third.labels.at<int>(plan.corridor.y + 1, plan.corridor.x + 1), corridor_id);
  EXPECT_EQ(segmenter.last_update().new_rooms, 0);
}

TEST(IncrementalSegmenter, DoorClosingSplitsAndTheLargerPartKeepsTheId) {
  FloorPlan plan = floor_plan();
  for (std::size_t k = 1; k < plan.doors.size(); ++k) plan.world.cells(plan.doors[k]).setTo(kOccupied);
  IncrementalSegmenter segmenter(trivial_options());
  const Segmentation first = segmenter.update(plan.world);
  ASSERT_EQ(first.rooms.size(), 4u);  // corridor + room 0 joined, rooms 1..3
  const int joined = first.labels.at<int>(plan.rooms[0].y + 1, plan.rooms[0].x + 1);
  OccupancyGrid closed = plan.world;
  closed.cells = plan.world.cells.clone();
  closed.cells(plan.doors[0]).setTo(kOccupied);
  const Segmentation second = segmenter.update(closed);
  expect_valid(closed, second);
  ASSERT_EQ(second.rooms.size(), 5u);
  // The corridor is more than half of the joined room: it keeps the id; room 0 gets a new one.
  EXPECT_EQ(second.labels.at<int>(plan.corridor.y + 1, plan.corridor.x + 1), joined);
  const int room0 = second.labels.at<int>(plan.rooms[0].y + 1, plan.rooms[0].x + 1);
  EXPECT_NE(room0, joined);
  for (const Room& r : first.rooms) EXPECT_NE(r.id, room0) << "the split-off room reused an old id";
  expect_untouched_stable(plan.world, first, closed, second);
}

// A grid of obstacles (rows x cols at kRes) with the given rectangles free.
OccupancyGrid walled(int rows, int cols, const std::vector<cv::Rect>& free) {
  OccupancyGrid grid;
  grid.resolution = kRes;
  grid.cells = cv::Mat(rows, cols, CV_8UC1, cv::Scalar(kOccupied));
  for (const cv::Rect& r : free) grid.cells(r).setTo(kFree);
  return grid;
}

// A copy of grid with the cells of every rectangle set to value.
OccupancyGrid with_cells(const OccupancyGrid& grid, const std::vector<cv::Rect>& rects, unsigned char value) {
  OccupancyGrid out = grid;
  out.cells = grid.cells.clone();
  for (const cv::Rect& r : rects) out.cells(r).setTo(value);
  return out;
}

TEST(IncrementalSegmenter, ARoomCutIntoThreeKeepsItsIdOnItsLargestPart) {
  // Doors 0 and 1 open: corridor, room 0 and room 1 are one room. Closing both cuts it in three;
  // the corridor, its largest part, is less than half of it (9344 of 24424 cells and the doors)
  // and still keeps its id.
  FloorPlan plan = floor_plan();
  for (std::size_t k = 2; k < plan.doors.size(); ++k) plan.world.cells(plan.doors[k]).setTo(kOccupied);
  IncrementalSegmenter segmenter(trivial_options());
  const Segmentation first = segmenter.update(plan.world);
  ASSERT_EQ(first.rooms.size(), 3u);  // corridor + rooms 0 and 1 joined, rooms 2 and 3
  const int joined = first.labels.at<int>(plan.corridor.y + 1, plan.corridor.x + 1);
  const auto joined_room = std::find_if(first.rooms.begin(), first.rooms.end(), [&](const Room& r) { return r.id == joined; });
  ASSERT_NE(joined_room, first.rooms.end());
  const double corridor_area = plan.corridor.area() * kRes * kRes;
  ASSERT_LT(2.0 * corridor_area, joined_room->area);
  const OccupancyGrid closed = with_cells(plan.world, {plan.doors[0], plan.doors[1]}, kOccupied);
  const Segmentation second = segmenter.update(closed);
  expect_valid(closed, second);
  ASSERT_EQ(second.rooms.size(), 5u);
  EXPECT_EQ(second.labels.at<int>(plan.corridor.y + 1, plan.corridor.x + 1), joined);
  for (int k = 0; k < 2; ++k) {
    const int part = second.labels.at<int>(plan.rooms[k].y + 1, plan.rooms[k].x + 1);
    for (const Room& r : first.rooms) EXPECT_NE(r.id, part) << "a smaller part of the cut room took an old id";
  }
  expect_untouched_stable(plan.world, first, closed, second);
}

// The floor plan after its first update, and the same with an obstacle filling `speck`.
struct SpeckCase {
  FloorPlan plan;
  OccupancyGrid with_speck;
};

SpeckCase speck_case(const cv::Rect& speck) {
  const FloorPlan plan = floor_plan();
  return {plan, with_cells(plan.world, {speck}, kOccupied)};
}

// The last update (after, of grid) took in one blob of changed cells without decomposing a room: a
// valid windowed result whose labels outside changed are before's, with as many rooms.
void expect_one_blob_absorbed(const IncrementalSegmenter& segmenter, const OccupancyGrid& grid, const Segmentation& before,
                              const Segmentation& after, const cv::Rect& changed) {
  expect_valid(grid, after);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kIncremental);
  EXPECT_EQ(segmenter.last_update().redecomposed_rooms, 0);
  EXPECT_EQ(segmenter.last_update().absorbed_blobs, 1);
  cv::Mat differs = before.labels != after.labels;
  differs(changed).setTo(0);
  EXPECT_EQ(cv::countNonZero(differs), 0);
  EXPECT_EQ(after.rooms.size(), before.rooms.size());
}

TEST(IncrementalSegmenter, ASpeckInsideARoomChangesNoOtherLabel) {
  // A cupboard of 8 x 7 cells (larger than the cleaning's obstacle specks, which stay floor) in the
  // middle of room 0: its cells leave the room, no room is decomposed again and every other label
  // stays; with speck_size 0 the room is decomposed again.
  const FloorPlan plan = floor_plan();
  const cv::Rect speck(plan.rooms[0].x + 30, plan.rooms[0].y + 50, 8, 7);
  const SpeckCase c = speck_case(speck);
  IncrementalSegmenter segmenter;
  const Segmentation before = segmenter.update(c.plan.world);
  const Segmentation after = segmenter.update(c.with_speck);
  expect_one_blob_absorbed(segmenter, c.with_speck, before, after, speck);
  EXPECT_EQ(cv::countNonZero(after.labels(speck)), 0);

  IncrementalOptions every_speck;
  every_speck.speck_size = 0.0;
  IncrementalSegmenter strict(every_speck);
  strict.update(c.plan.world);
  expect_valid(c.with_speck, strict.update(c.with_speck));
  EXPECT_GE(strict.last_update().redecomposed_rooms, 1);
}

TEST(IncrementalSegmenter, ASpeckThatWouldSplitARoomIsDecomposed) {
  // An obstacle closing door 0 (18 x 4 cells) is small, but it cuts room 0 off the corridor: the
  // joined room is decomposed again into two (trivial mode: one room per component).
  FloorPlan plan = floor_plan();
  for (std::size_t k = 1; k < plan.doors.size(); ++k) plan.world.cells(plan.doors[k]).setTo(kOccupied);
  IncrementalOptions options = trivial_options();
  options.speck_size = 1.0;  // 20 cells: the door fits
  IncrementalSegmenter segmenter(options);
  const Segmentation first = segmenter.update(plan.world);
  ASSERT_EQ(first.rooms.size(), 4u);
  const OccupancyGrid closed = with_cells(plan.world, {plan.doors[0]}, kOccupied);
  const Segmentation second = segmenter.update(closed);
  expect_valid(closed, second);
  EXPECT_EQ(second.rooms.size(), 5u);
  EXPECT_EQ(segmenter.last_update().absorbed_blobs, 0);
  EXPECT_NE(second.labels.at<int>(plan.corridor.y + 1, plan.corridor.x + 1),
            second.labels.at<int>(plan.rooms[0].y + 1, plan.rooms[0].x + 1));
}

TEST(IncrementalSegmenter, CellsSeenWhereTwoRoomsMeetTakeTheNearestWithoutADecomposition) {
  // Door 0 widened by two columns of its jamb (8 cells, next to room 0 and the corridor, which meet
  // across the door): absorbed, each new cell labelled, no room decomposed again and no other label
  // moved. Switched off, both rooms are decomposed again.
  const FloorPlan plan = floor_plan();
  const cv::Rect jamb(plan.doors[0].x - 2, plan.doors[0].y, 2, plan.doors[0].height);
  const OccupancyGrid wider = with_cells(plan.world, {jamb}, kFree);
  IncrementalSegmenter segmenter;
  const Segmentation before = segmenter.update(plan.world);
  const Segmentation after = segmenter.update(wider);
  expect_one_blob_absorbed(segmenter, wider, before, after, jamb);
  const int room = before.labels.at<int>(plan.rooms[0].y + 1, plan.rooms[0].x + 1);
  const int corridor = before.labels.at<int>(plan.corridor.y + 1, plan.corridor.x + 1);
  for (int r = jamb.y; r < jamb.y + jamb.height; ++r) {
    for (int c = jamb.x; c < jamb.x + jamb.width; ++c) {
      const int id = after.labels.at<int>(r, c);
      EXPECT_TRUE(id == room || id == corridor) << "cell " << c << "," << r << " took room " << id;
    }
  }

  IncrementalOptions apart;
  apart.absorb_across_rooms = false;
  IncrementalSegmenter strict(apart);
  strict.update(plan.world);
  expect_valid(wider, strict.update(wider));
  EXPECT_GE(strict.last_update().redecomposed_rooms, 2);
}

TEST(IncrementalSegmenter, ADoorSeenBetweenRoomsThatDidNotMeetIsDecomposed) {
  // An opening of 4 x 8 cells in the wall between rooms 0 and 1, which met only through the corridor:
  // small enough to absorb, but it may join them, so both are decomposed again.
  const FloorPlan plan = floor_plan();
  const cv::Rect opening(plan.rooms[0].br().x, plan.rooms[0].y + 50, plan.rooms[1].x - plan.rooms[0].br().x, 8);
  const OccupancyGrid opened = with_cells(plan.world, {opening}, kFree);
  IncrementalSegmenter segmenter;
  segmenter.update(plan.world);
  expect_valid(opened, segmenter.update(opened));
  EXPECT_EQ(segmenter.last_update().absorbed_blobs, 0);
  EXPECT_GE(segmenter.last_update().redecomposed_rooms, 2);
}

// A 10 m x 5 m hall whose middle narrows, update after update, into a 0.6 m door: wall stubs from
// both long walls, one cell thicker each time (too long to be specks).
OccupancyGrid narrowing_hall(int thickness) {
  OccupancyGrid grid;
  grid.resolution = kRes;
  grid.cells = cv::Mat(100, 200, CV_8UC1, cv::Scalar(kOccupied));
  grid.cells(cv::Rect(4, 4, 192, 92)).setTo(kFree);
  if (thickness > 0) {
    grid.cells(cv::Rect(100, 4, thickness, 40)).setTo(kOccupied);
    grid.cells(cv::Rect(100, 56, thickness, 40)).setTo(kOccupied);
  }
  return grid;
}

TEST(IncrementalSegmenter, ADoorCutIsMadeOnlyWhenSplitAfterDecompositionsInARowFindIt) {
  ASSERT_EQ(segment(narrowing_hall(2)).rooms.size(), 2u);  // batch cuts the hall at the door
  for (const int split_after : {1, 3}) {
    IncrementalOptions options;
    options.split_after = split_after;
    IncrementalSegmenter segmenter(options);
    const Segmentation first = segmenter.update(narrowing_hall(0));
    ASSERT_EQ(first.rooms.size(), 1u);
    const int hall = first.rooms[0].id;
    for (int k = 1; k <= 3; ++k) {
      const OccupancyGrid grid = narrowing_hall(k + 1);
      const Segmentation& s = segmenter.update(grid);
      expect_valid(grid, s);
      ASSERT_GE(segmenter.last_update().redecomposed_rooms, 1) << "update " << k;
      const std::size_t expected = k < split_after ? 1u : 2u;
      EXPECT_EQ(s.rooms.size(), expected) << "split_after " << split_after << ", update " << k;
      // The hall keeps its id on its left part throughout; held back, the right part has it too.
      EXPECT_EQ(s.labels.at<int>(50, 20), hall);
      EXPECT_EQ(s.labels.at<int>(50, 180) == hall, k < split_after) << "split_after " << split_after << ", update " << k;
    }
  }
}

TEST(IncrementalSegmenter, AMergeUndoneBeforeMergeAfterDecompositionsKeepsBothIds) {
  // Trivial mode, every door closed: five rooms. Opening door 0 joins room 0 to the corridor; held
  // back (merge_after 3), room 0 keeps its id and its cells, and closing the door again changes no
  // id. Left open for three decompositions in a row, the merge is made on the third.
  FloorPlan plan = floor_plan();
  for (const cv::Rect& door : plan.doors) plan.world.cells(door).setTo(kOccupied);
  IncrementalOptions options = trivial_options();
  options.merge_after = 3;
  options.absorb_area = 0.0;  // every change is decomposed: each update votes
  options.absorb_fraction = 0.0;
  options.speck_size = 0.0;
  IncrementalSegmenter segmenter(options);
  const Segmentation closed = segmenter.update(plan.world);
  ASSERT_EQ(closed.rooms.size(), 5u);
  const cv::Point in_room0(plan.rooms[0].x + 1, plan.rooms[0].y + 1), in_corridor(plan.corridor.x + 1, plan.corridor.y + 1);
  const int room0 = closed.labels.at<int>(in_room0), corridor = closed.labels.at<int>(in_corridor);
  const OccupancyGrid opened = with_cells(plan.world, {plan.doors[0]}, kFree);

  const Segmentation held = segmenter.update(opened);
  expect_valid(opened, held);
  EXPECT_EQ(held.rooms.size(), 5u);
  EXPECT_EQ(cells_by_room(held.labels).at(room0), cells_by_room(closed.labels).at(room0));
  EXPECT_EQ(held.labels.at<int>(plan.doors[0].y + 1, plan.doors[0].x + 1), corridor);  // the new cells join the partner
  // The corridor's outline is traced from its own cells: it does not cover room 0 (pixel-edge
  // rings: its area is its cells' area).
  for (const Room& room : held.rooms) {
    if (room.id == corridor) {
      EXPECT_NEAR(room.area, room.labelled_area, 1e-6);
    }
  }
  const Segmentation undone = segmenter.update(plan.world);
  expect_valid(plan.world, undone);
  EXPECT_EQ(cv::countNonZero(undone.labels != closed.labels), 0);
  EXPECT_EQ(segmenter.last_update().new_rooms, 0);
  EXPECT_EQ(segmenter.last_update().removed_rooms, 0);

  // Open again, and keep changing a corner of the corridor so that each update decomposes it.
  const cv::Rect corner(plan.corridor.x + 200, plan.corridor.y + 10, 8, 8);  // no cleaning speck
  const std::vector<OccupancyGrid> steps{opened, with_cells(opened, {corner}, kOccupied), opened};
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const Segmentation& s = segmenter.update(steps[k]);
    expect_valid(steps[k], s);
    ASSERT_GE(segmenter.last_update().redecomposed_rooms, 2) << "update " << k;
    EXPECT_EQ(s.labels.at<int>(in_corridor), corridor);
    EXPECT_EQ(s.labels.at<int>(in_room0) == room0, k < 2) << "update " << k;
    EXPECT_EQ(s.rooms.size(), k < 2 ? 5u : 4u) << "update " << k;
  }
}

TEST(IncrementalSegmenter, RoomsRevealedThroughDoorsMatchBatchAtTheEnd) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter segmenter;
  std::vector<cv::Rect> seen{plan.corridor};
  for (const cv::Rect& d : plan.doors) seen.push_back(d);
  OccupancyGrid previous = reveal(plan, seen);
  Segmentation before = segmenter.update(previous);
  expect_valid(previous, before);
  for (std::size_t k = 0; k < plan.rooms.size(); ++k) {
    // Each room is seen in two halves, as a robot walking in would.
    cv::Rect half = plan.rooms[k];
    half.y += half.height / 2;
    half.height -= half.height / 2;
    for (const cv::Rect& part : {half, plan.rooms[k]}) {
      seen.push_back(part);
      const OccupancyGrid grid = reveal(plan, seen);
      const Segmentation after = segmenter.update(grid);
      SCOPED_TRACE("room " + std::to_string(k) + ", " + std::to_string(part.height) + " rows");
      expect_valid(grid, after);
      expect_untouched_stable(previous, before, grid, after);
      previous = grid;
      before = after;
    }
  }
  const Segmentation batch = segment(previous);
  EXPECT_EQ(before.rooms.size(), batch.rooms.size());
  const auto [precision, recall] = agreement(before.labels, batch.labels);
  EXPECT_GT(precision, 0.95);
  EXPECT_GT(recall, 0.95);
  // The room graph survives the re-decompositions: every door is still a passage.
  EXPECT_GE(batch.passages.size(), 4u);
  EXPECT_EQ(passage_pairs_in(before, batch), passage_pairs(batch));
}

TEST(IncrementalSegmenter, DoorClosingWithDecompositionMatchesBatch) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter segmenter;
  const Segmentation first = segmenter.update(plan.world);
  OccupancyGrid closed = plan.world;
  closed.cells = plan.world.cells.clone();
  closed.cells(plan.doors[2]).setTo(kOccupied);
  const Segmentation second = segmenter.update(closed);
  expect_valid(closed, second);
  expect_untouched_stable(plan.world, first, closed, second);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kIncremental);
  EXPECT_GE(segmenter.last_update().redecomposed_rooms, 1);
  const Segmentation batch = segment(closed);
  EXPECT_EQ(second.rooms.size(), batch.rooms.size());
  EXPECT_EQ(passage_pairs_in(second, batch), passage_pairs(batch));
  const auto [precision, recall] = agreement(second.labels, batch.labels);
  EXPECT_GT(precision, 0.95);
  EXPECT_GT(recall, 0.95);
}

TEST(IncrementalSegmenter, PassagesAcrossSlantedDoorsSurviveLaterUpdates) {
  // The floor plan turned by 30 degrees: cuts across its doors run diagonally, while the pieces of
  // a re-decomposed region follow pixel edges; the passage between a room that stays and the room
  // re-decomposed next to it must still be found.
  const FloorPlan plan = floor_plan();
  const cv::Point2f centre(150.0f, 80.0f);
  const cv::Mat turn = cv::getRotationMatrix2D(centre, 30.0, 1.0);
  const cv::Size size(340, 300);
  cv::Mat shift = turn.clone();
  shift.at<double>(0, 2) += 20.0;
  shift.at<double>(1, 2) += 70.0;
  auto turned = [&](const cv::Mat& cells, unsigned char outside) {
    cv::Mat out;
    cv::warpAffine(cells, out, shift, size, cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(outside));
    return out;
  };
  OccupancyGrid world = plan.world;
  world.cells = turned(plan.world.cells, kUnknown);
  // Parts revealed in turn: the corridor with the doors, then each room.
  std::vector<cv::Mat> parts;
  cv::Mat corridor = cv::Mat::zeros(plan.world.cells.size(), CV_8UC1);
  corridor(cv::Rect(0, 116, 300, 44)).setTo(255);
  parts.push_back(corridor);
  for (const cv::Rect& room : plan.rooms) {
    cv::Mat part = cv::Mat::zeros(plan.world.cells.size(), CV_8UC1);
    part(cv::Rect(room.x - 4, 0, room.width + 8, 124)).setTo(255);
    parts.push_back(part);
  }
  IncrementalSegmenter segmenter;
  OccupancyGrid grid = world;
  grid.cells = cv::Mat(size, CV_8UC1, cv::Scalar(kUnknown));
  Segmentation result;
  cv::Mat seen = cv::Mat::zeros(size, CV_8UC1);
  for (const cv::Mat& part : parts) {
    seen |= turned(part, 0);
    world.cells.copyTo(grid.cells, seen);
    result = segmenter.update(grid);
    expect_valid(grid, result);
  }
  const Segmentation batch = segment(grid);
  EXPECT_EQ(result.rooms.size(), batch.rooms.size());
  bool diagonal = false;
  for (const Passage& p : batch.passages) diagonal = diagonal || (p.cut.a.x != p.cut.b.x && p.cut.a.y != p.cut.b.y);
  EXPECT_TRUE(diagonal) << "the plan no longer produces a slanted cut; the test would prove nothing";
  EXPECT_GE(batch.passages.size(), 4u);
  EXPECT_EQ(passage_pairs_in(result, batch), passage_pairs(batch));
}

// Embeds grid into a larger one: `left` columns added on the left, `top` rows on top, `bottom`
// rows below; the origin moves accordingly (ROS: origin = lower-left corner).
OccupancyGrid grown_grid(const OccupancyGrid& grid, int left, int top, int bottom) {
  OccupancyGrid out;
  out.resolution = grid.resolution;
  out.cells = cv::Mat(grid.height() + top + bottom, grid.width() + left, CV_8UC1, cv::Scalar(kUnknown));
  grid.cells.copyTo(out.cells(cv::Rect(left, top, grid.width(), grid.height())));
  out.origin = {grid.origin.x - left * grid.resolution, grid.origin.y - bottom * grid.resolution};
  return out;
}

TEST(IncrementalSegmenter, MapGrowingLeftUpAndDownKeepsRoomsInTheWorld) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter segmenter;
  OccupancyGrid first = reveal(plan, {plan.corridor, plan.doors[0], plan.rooms[0], plan.doors[1], plan.rooms[1]});
  first.origin = {3.0, -2.0};
  const Segmentation before = segmenter.update(first);
  expect_valid(first, before);

  // Grow by 40 columns on the left and 30 rows on top, and reveal a new room out there.
  OccupancyGrid second = grown_grid(first, 40, 30, 0);
  EXPECT_DOUBLE_EQ(second.origin.x, 3.0 - 40 * kRes);
  EXPECT_DOUBLE_EQ(second.origin.y, -2.0);
  const cv::Rect extra(2, 2, 36, 60);  // a closed room in the new area
  second.cells(cv::Rect(0, 0, 40, 64)).setTo(kOccupied);
  second.cells(extra).setTo(kFree);
  const Segmentation after = segmenter.update(second);
  expect_valid(second, after);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kIncremental);
  EXPECT_EQ(segmenter.last_update().redecomposed_rooms, 0);
  ASSERT_EQ(after.rooms.size(), before.rooms.size() + 1);
  for (const Room& old_room : before.rooms) {
    const auto it = std::find_if(after.rooms.begin(), after.rooms.end(), [&](const Room& r) { return r.id == old_room.id; });
    ASSERT_NE(it, after.rooms.end());
    EXPECT_EQ(it->polygon, old_room.polygon);  // world metres: unchanged by the new frame
    EXPECT_NEAR(it->centroid.x, old_room.centroid.x, 1e-9);
    EXPECT_NEAR(it->centroid.y, old_room.centroid.y, 1e-9);
    EXPECT_DOUBLE_EQ(it->area, old_room.area);
  }
  // The old labels moved by (40, 30) cells.
  EXPECT_EQ(cv::countNonZero(after.labels(cv::Rect(40, 30, first.width(), first.height())) != before.labels), 0);

  // Grow downwards too: the origin's y moves, old cells stay where they were in the world.
  OccupancyGrid third = grown_grid(second, 0, 0, 25);
  EXPECT_DOUBLE_EQ(third.origin.y, -2.0 - 25 * kRes);
  const Segmentation last = segmenter.update(third, cv::Rect());  // hint: nothing changed
  expect_valid(third, last);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kUnchanged);
  EXPECT_EQ(cv::countNonZero(last.labels(cv::Rect(0, 0, second.width(), second.height())) != after.labels), 0);
  EXPECT_EQ(last.rooms.size(), after.rooms.size());
}

TEST(IncrementalSegmenter, GrowthWithAFloat32ResolutionIsAWholeCellShift) {
  // nav_msgs/MapMetaData carries the resolution as float32: 0.05 becomes 0.0500000007..., and an
  // origin moved by 80 cells reads as 79.9999988 cells. That is a growth, not a new frame.
  const FloorPlan plan = floor_plan();
  OccupancyGrid first = reveal(plan, {plan.corridor, plan.doors[0], plan.rooms[0]});
  first.resolution = static_cast<float>(kRes);
  first.origin = {10.0, 2.0};
  IncrementalSegmenter segmenter;
  const Segmentation before = segmenter.update(first);
  OccupancyGrid second = grown_grid(first, 80, 0, 0);
  second.origin.x = 6.0;  // as a map server writes it: whole metres, not origin - 80 * resolution
  const Segmentation after = segmenter.update(second);
  EXPECT_NE(segmenter.last_update().reason, "the origin moved by a fraction of a cell");
  EXPECT_EQ(cv::countNonZero(after.labels(cv::Rect(80, 0, first.width(), first.height())) != before.labels), 0);
}

TEST(IncrementalSegmenter, LoopClosureShiftFallsBackToBatchAndKeepsIds) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter segmenter;
  OccupancyGrid grid = plan.world;
  grid.cells = plan.world.cells.clone();
  const Segmentation before = segmenter.update(grid);
  // The whole map moves by 3 cells right and 2 down (a corrected pose graph).
  OccupancyGrid shifted = grid;
  shifted.cells = cv::Mat(grid.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
  grid.cells(cv::Rect(0, 0, grid.width() - 3, grid.height() - 2)).copyTo(shifted.cells(cv::Rect(3, 2, grid.width() - 3, grid.height() - 2)));
  const Segmentation after = segmenter.update(shifted);
  expect_valid(shifted, after);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kBatch);
  const Segmentation batch = segment(shifted);
  EXPECT_EQ(after.rooms.size(), batch.rooms.size());
  const auto [precision, recall] = agreement(after.labels, batch.labels);
  EXPECT_DOUBLE_EQ(precision, 1.0);
  EXPECT_DOUBLE_EQ(recall, 1.0);
  // Every room overlaps its shifted self by far more than half: all ids are kept.
  std::set<int> old_ids, new_ids;
  for (const Room& r : before.rooms) old_ids.insert(r.id);
  for (const Room& r : after.rooms) new_ids.insert(r.id);
  EXPECT_EQ(old_ids, new_ids);
}

TEST(IncrementalSegmenter, SmallNoiseIsAbsorbedOrRepairedLocally) {
  const FloorPlan plan = floor_plan();
  IncrementalOptions options;
  options.speck_size = 0.0;  // obstacle specks decomposed again (ASpeckInsideARoom... covers the rule)
  IncrementalSegmenter segmenter(options);
  OccupancyGrid grid = reveal(plan, {plan.corridor, plan.doors[0], plan.rooms[0], plan.doors[3], plan.rooms[3]});
  const Segmentation first = segmenter.update(grid);
  expect_valid(grid, first);

  // Two wall cells next to the corridor read as free (sensor noise): they touch one room and are
  // absorbed, nothing is decomposed again.
  OccupancyGrid noisy = grid;
  noisy.cells = grid.cells.clone();
  const cv::Point gap(plan.rooms[1].x + 10, plan.corridor.y - 1);  // wall cell just above the corridor
  ASSERT_EQ(noisy.cells.at<unsigned char>(gap), kOccupied);
  noisy.cells.at<unsigned char>(gap) = kFree;
  noisy.cells.at<unsigned char>(gap.y, gap.x + 1) = kFree;
  const Segmentation second = segmenter.update(noisy);
  expect_valid(noisy, second);
  EXPECT_EQ(segmenter.last_update().absorbed_blobs, 1);
  EXPECT_EQ(segmenter.last_update().redecomposed_rooms, 0);
  EXPECT_EQ(second.labels.at<int>(gap), second.labels.at<int>(plan.corridor.y + 1, gap.x));
  for (const Room& r : first.rooms) EXPECT_EQ(second.labels.at<int>(world_to_cell(grid, r.centroid)), r.id);

  // A small obstacle (larger than the cleaning's specks) appearing inside room 3: that room is
  // decomposed again with its neighbours through passages (here the corridor), the others are not.
  OccupancyGrid blocked = noisy;
  blocked.cells = noisy.cells.clone();
  blocked.cells(cv::Rect(plan.rooms[3].x + 20, plan.rooms[3].y + 30, 8, 8)).setTo(kOccupied);
  const int room3 = second.labels.at<int>(plan.rooms[3].y + 30, plan.rooms[3].x + 20);
  const Segmentation third = segmenter.update(blocked);
  expect_valid(blocked, third);
  expect_untouched_stable(noisy, second, blocked, third);
  EXPECT_EQ(segmenter.last_update().redecomposed_rooms, 1 + passage_neighbours(second, room3));
  EXPECT_GE(passage_neighbours(second, room3), 1);
}

TEST(IncrementalSegmenter, NeighboursBehindDoorsCanBeLeftAlone) {
  // With neighbours_across_doors off, a change inside a room that has only a door to the corridor
  // decomposes that room alone; the corridor keeps its cells.
  const FloorPlan plan = floor_plan();
  IncrementalOptions options;
  options.neighbours_across_doors = false;
  options.speck_size = 0.0;  // the obstacle below is a speck
  IncrementalSegmenter segmenter(options);
  const Segmentation first = segmenter.update(plan.world);
  OccupancyGrid blocked = plan.world;
  blocked.cells = plan.world.cells.clone();
  blocked.cells(cv::Rect(plan.rooms[1].x + 20, plan.rooms[1].y + 30, 8, 8)).setTo(kOccupied);
  const Segmentation second = segmenter.update(blocked);
  expect_valid(blocked, second);
  EXPECT_EQ(segmenter.last_update().redecomposed_rooms, 1);
  const int corridor = first.labels.at<int>(plan.corridor.y + 5, plan.corridor.x + 5);
  EXPECT_EQ(cells_by_room(second.labels).at(corridor), cells_by_room(first.labels).at(corridor));
  EXPECT_EQ(passage_pairs(second).size(), passage_pairs(first).size());
}

TEST(IncrementalSegmenter, WithoutNeighboursOnlyTheTouchedRoomsChange) {
  // A hall parted by a wall with a 3 m opening: batch cuts it there (found as a door). An obstacle
  // in the left half brings the right half in through the passage unless neighbours are off; with
  // neither doors nor other cuts bringing neighbours in, every room not next to a changed cell
  // keeps its id and cells exactly.
  OccupancyGrid hall;
  hall.resolution = kRes;
  hall.cells = cv::Mat(100, 200, CV_8UC1, cv::Scalar(kOccupied));
  hall.cells(cv::Rect(4, 4, 192, 92)).setTo(kFree);
  hall.cells(cv::Rect(100, 4, 2, 16)).setTo(kOccupied);
  hall.cells(cv::Rect(100, 80, 2, 16)).setTo(kOccupied);
  const OccupancyGrid blocked = with_cells(hall, {cv::Rect(40, 40, 8, 8)}, kOccupied);
  for (const bool neighbours : {true, false}) {
    IncrementalOptions options;
    options.neighbours_across_doors = neighbours;
    options.neighbours_across_cuts = neighbours;
    options.speck_size = 0.0;
    IncrementalSegmenter segmenter(options);
    const Segmentation first = segmenter.update(hall);
    ASSERT_EQ(first.rooms.size(), 2u);
    const Segmentation second = segmenter.update(blocked);
    expect_valid(blocked, second);
    EXPECT_EQ(segmenter.last_update().redecomposed_rooms, neighbours ? 2 : 1);
    if (!neighbours) expect_untouched_stable(hall, first, blocked, second, false);
  }
}

TEST(IncrementalSegmenter, LargeRoomsAbsorbGrowthUpToTheirAllowance) {
  // The corridor (292 x 32 = 9344 cells) grows by strips of newly seen cells: it takes them in
  // without a decomposition while they add up to at most 10 % of its size; the strip that does not
  // fit makes it decompose again, after which the allowance starts afresh.
  const FloorPlan plan = floor_plan();
  OccupancyGrid grid = reveal(plan, {plan.corridor});
  grid.cells(cv::Rect(4, 156, 292, 4)).setTo(kUnknown);  // the wall below the corridor: not seen yet
  IncrementalOptions options;
  options.absorb_area = 0.0;  // only the fraction counts here
  IncrementalSegmenter segmenter(options);
  segmenter.update(grid);
  const int corridor_id = segmenter.result().rooms.front().id;
  // Strips of the wall below turn out to be free (alcoves): 400, 480, 184 and 24 cells. The
  // allowance is 10 % of the room before each update: 400 <= 934, 880 <= 974, 1064 > 1022; after
  // the decomposition the count starts again: 24 <= 1040.
  const cv::Rect strips[4] = {{10, 156, 200, 2}, {10, 158, 240, 2}, {250, 156, 46, 4}, {4, 156, 6, 4}};
  const bool expect_absorbed[4] = {true, true, false, true};
  for (int k = 0; k < 4; ++k) {
    grid.cells = grid.cells.clone();
    grid.cells(strips[k]).setTo(kFree);
    segmenter.update(grid);
    expect_valid(grid, segmenter.result());
    const IncrementalUpdateReport& report = segmenter.last_update();
    EXPECT_EQ(report.absorbed_blobs, expect_absorbed[k] ? 1 : 0) << "strip " << k;
    EXPECT_EQ(report.redecomposed_rooms, expect_absorbed[k] ? 0 : 1) << "strip " << k;
    EXPECT_EQ(segmenter.result().labels.at<int>(150, 100), corridor_id);
  }
  // With no allowance at all every change is decomposed.
  IncrementalOptions strict;
  strict.absorb_area = 0.0;
  strict.absorb_fraction = 0.0;
  IncrementalSegmenter exact(strict);
  OccupancyGrid g = reveal(plan, {plan.corridor});
  exact.update(g);
  g.cells = g.cells.clone();
  g.cells(cv::Rect(50, 156, 200, 2)).setTo(kFree);
  exact.update(g);
  EXPECT_EQ(exact.last_update().absorbed_blobs, 0);
  EXPECT_EQ(exact.last_update().redecomposed_rooms, 1);
}

TEST(IncrementalSegmenter, ALongCorridorGrowingAtItsFarEndIsDecomposedOnlyThere) {
  // A corridor 30 m x 2 m (60 m²) whose east end wall later shows a 0.9 m door into a 4.4 m x
  // 6.5 m room. With partial_area 20 m² only the corridor's cells within partial_margin (3 m) of
  // the change are decomposed with the new cells: the piece touching the rest of the corridor keeps
  // its id, the room beyond the door is new, and the labels equal batch's on the same grid. A
  // closed room elsewhere keeps the change from touching every room (a batch update).
  const cv::Rect corridor(4, 100, 600, 40);
  const cv::Rect closed_room(4, 4, 100, 60), new_room(608, 20, 88, 130), door(604, 112, 4, 18);
  const OccupancyGrid world = walled(160, 700, {corridor, closed_room, new_room, door});
  OccupancyGrid before = world;
  before.cells = world.cells.clone();
  before.cells(cv::Rect(604, 0, 96, 160)).setTo(kUnknown);
  before.cells(cv::Rect(604, 96, 4, 48)).setTo(kOccupied);  // the end wall, door closed
  const int new_cells = cv::countNonZero(world.cells == kFree) - cv::countNonZero(before.cells == kFree);

  for (const double partial_area : {20.0, 0.0}) {
    IncrementalOptions options;
    options.absorb_area = 0.0;  // every change decomposed
    options.absorb_fraction = 0.0;
    options.partial_area = partial_area;
    IncrementalSegmenter segmenter(options);
    const Segmentation first = segmenter.update(before);
    ASSERT_EQ(first.rooms.size(), 2u);
    const int corridor_id = first.labels.at<int>(corridor.y, corridor.x);
    const Segmentation second = segmenter.update(world);
    expect_valid(world, second);
    const IncrementalUpdateReport& report = segmenter.last_update();
    ASSERT_EQ(report.kind, IncrementalUpdateReport::Kind::kIncremental) << report.reason;
    if (partial_area == 0.0) {  // the whole corridor goes again: what the option saves
      EXPECT_EQ(report.partial_rooms, 0);
      EXPECT_EQ(report.region_cells, corridor.area() + new_cells);
      continue;
    }
    EXPECT_EQ(report.partial_rooms, 1);
    const int margin = static_cast<int>(std::ceil(options.partial_margin / kRes));
    EXPECT_LE(report.region_cells, new_cells + (margin + 1) * corridor.height);
    // The corridor beyond the window keeps its id on every cell; all of it keeps the id.
    for (int r = corridor.y; r < corridor.y + corridor.height; ++r)
      for (int c = corridor.x; c < corridor.x + corridor.width; ++c)
        ASSERT_EQ(second.labels.at<int>(r, c), corridor_id) << "corridor cell (" << c << ", " << r << ")";
    // The same rooms as batch, cell for cell: the corridor and the new room parted at the door.
    const Segmentation batch = segment(world, options.segment);
    ASSERT_EQ(batch.rooms.size(), 3u);
    ASSERT_EQ(second.rooms.size(), 3u);
    const auto [precision, recall] = agreement(second.labels, batch.labels);
    EXPECT_DOUBLE_EQ(precision, 1.0);
    EXPECT_DOUBLE_EQ(recall, 1.0);
    EXPECT_EQ(passage_pairs_in(second, batch), passage_pairs(batch));
  }
}

TEST(IncrementalSegmenter, ALargeRoomGrowingUnderPartialDecompositionIsCutOnceItHasGrownByThePartialArea) {
  // A corridor 20 m x 2 m opening without a door into a 10 m x 10 m hall, seen 1 m further east each
  // update. With partial_area 20 m² the corridor is decomposed only near its growing end, where
  // every piece touches its rest and so joins it: the hall would grow inside the corridor for good.
  // Once the corridor has grown by 20 m² since it was last decomposed whole, it is decomposed whole
  // again and the hall is cut off as segment() cuts it.
  const cv::Rect corridor(4, 110, 400, 40), hall(404, 30, 200, 200), closed_room(4, 4, 100, 60);
  const OccupancyGrid world = walled(240, 620, {corridor, hall, closed_room});
  IncrementalOptions options;
  options.partial_area = 20.0;
  options.split_after = options.merge_after = 1;
  IncrementalSegmenter segmenter(options);
  int partial = 0;
  for (int seen = 424; seen <= 620; seen += 20) {
    OccupancyGrid grid = world;
    grid.cells = world.cells.clone();
    if (seen < 620) grid.cells(cv::Rect(seen, 0, 620 - seen, 240)).setTo(kUnknown);
    segmenter.update(grid);
    partial += segmenter.last_update().partial_rooms;
  }
  EXPECT_GT(partial, 0);  // the corridor was decomposed near the change only, some of the time
  const Segmentation batch = segment(world, options.segment);
  ASSERT_GE(batch.rooms.size(), 3u);  // the hall is no part of the corridor in batch
  const Segmentation& live = segmenter.result();
  EXPECT_NE(live.labels.at<int>(corridor.y + 20, corridor.x + 20), live.labels.at<int>(hall.y + 100, hall.x + 150));
  EXPECT_EQ(live.rooms.size(), batch.rooms.size());
}

TEST(IncrementalSegmenter, AnIsolatedSpeckTakesTheNearestRoomWithoutADecomposition) {
  // Two rooms; beyond the wall of the right one a ray seen through a gap leaves a line of free
  // cells one cell wide: touching no room and gone after the 0.15 m opening, it can be no room. It
  // joins the nearest room, as segment() labels it, and nothing else changes.
  const OccupancyGrid before = walled(100, 200, {cv::Rect(4, 4, 90, 80), cv::Rect(100, 4, 80, 80)});
  const OccupancyGrid after = with_cells(before, {cv::Rect(184, 10, 1, 30)}, kFree);
  for (const bool clean : {true, false}) {
    IncrementalOptions options;
    options.segment.binarize.opening_size = 0.15;
    options.segment.clean = clean;
    IncrementalSegmenter segmenter(options);
    const Segmentation first = segmenter.update(before);
    ASSERT_EQ(first.rooms.size(), 2u);
    const int right = first.labels.at<int>(50, 150);
    const Segmentation second = segmenter.update(after);
    expect_valid(after, second);
    const IncrementalUpdateReport& report = segmenter.last_update();
    EXPECT_EQ(report.kind, IncrementalUpdateReport::Kind::kIncremental);
    EXPECT_EQ(report.region_cells, 0);
    for (int r = 10; r < 40; ++r) EXPECT_EQ(second.labels.at<int>(r, 184), right);
    const int left = first.labels.at<int>(50, 50);
    EXPECT_EQ(cells_by_room(second.labels).at(left), cells_by_room(first.labels).at(left));
    EXPECT_EQ(cells_by_room(second.labels).at(right).size(), cells_by_room(first.labels).at(right).size() + 30);
    // The same labels as batch on the same grid (ids aside).
    const auto [precision, recall] = agreement(second.labels, segment(after, options.segment).labels);
    EXPECT_DOUBLE_EQ(precision, 1.0);
    EXPECT_DOUBLE_EQ(recall, 1.0);
  }
}

TEST(IncrementalSegmenter, HintGivesTheSameResultAsAFullComparison) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter with_hint, without_hint;
  std::vector<cv::Rect> seen{plan.corridor};
  OccupancyGrid previous = reveal(plan, seen);
  with_hint.update(previous);
  without_hint.update(previous);
  for (std::size_t k = 0; k < plan.rooms.size(); ++k) {
    seen.push_back(plan.doors[k]);
    seen.push_back(plan.rooms[k]);
    const OccupancyGrid grid = reveal(plan, seen);
    cv::Rect hint = cv::boundingRect(grid.cells != previous.cells);
    const Segmentation& a = with_hint.update(grid, hint);
    const Segmentation& b = without_hint.update(grid);
    EXPECT_EQ(cv::countNonZero(a.labels != b.labels), 0);
    ASSERT_EQ(a.rooms.size(), b.rooms.size());
    for (std::size_t i = 0; i < a.rooms.size(); ++i) {
      EXPECT_EQ(a.rooms[i].id, b.rooms[i].id);
      EXPECT_EQ(a.rooms[i].polygon, b.rooms[i].polygon);
    }
    EXPECT_EQ(a.passages.size(), b.passages.size());
    previous = grid;
  }
}

TEST(IncrementalSegmenter, CopiesOfAResultDoNotChangeOnTheNextUpdate) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter segmenter;
  const OccupancyGrid first = reveal(plan, {plan.corridor});
  const Segmentation kept = segmenter.update(first);  // shares the label image with the state
  const cv::Mat snapshot = kept.labels.clone();
  const OccupancyGrid second = reveal(plan, {plan.corridor, plan.doors[1], plan.rooms[1]});
  segmenter.update(second);
  EXPECT_EQ(cv::countNonZero(kept.labels != snapshot), 0);
  expect_valid(second, segmenter.result());
}

TEST(IncrementalSegmenter, UnchangedGridReturnsTheSameResult) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter segmenter;
  const Segmentation first = segmenter.update(plan.world);
  const Segmentation second = segmenter.update(plan.world);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kUnchanged);
  EXPECT_EQ(cv::countNonZero(first.labels != second.labels), 0);
  // Unknown turning into obstacle changes no free cell: nothing to do either.
  OccupancyGrid partial = reveal(plan, {plan.corridor});
  segmenter.reset();
  segmenter.update(partial);
  partial.cells = partial.cells.clone();
  partial.cells(cv::Rect(0, 0, 10, 10)).setTo(kOccupied);
  segmenter.update(partial);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kUnchanged);
}

TEST(IncrementalSegmenter, InflationIsRecomputedLocally) {
  const FloorPlan plan = floor_plan();
  IncrementalOptions options;
  options.segment.binarize.robot_radius = 0.15;
  options.speck_size = 0.0;  // the obstacle below and its inflation form a speck
  IncrementalSegmenter segmenter(options);
  std::vector<cv::Rect> seen{plan.corridor};
  OccupancyGrid previous = reveal(plan, seen);
  Segmentation before = segmenter.update(previous);
  for (std::size_t k = 0; k < plan.rooms.size(); ++k) {
    seen.push_back(plan.doors[k]);
    seen.push_back(plan.rooms[k]);
    const OccupancyGrid grid = reveal(plan, seen);
    const Segmentation after = segmenter.update(grid);
    expect_valid(grid, after);
    expect_untouched_stable(previous, before, grid, after);
    previous = grid;
    before = after;
  }
  // An obstacle inside a room only changes inflated free space around it (and its own cells): that
  // room and its passage neighbours are decomposed again.
  OccupancyGrid blocked = previous;
  blocked.cells = previous.cells.clone();
  blocked.cells.at<unsigned char>(plan.rooms[2].y + 50, plan.rooms[2].x + 40) = kOccupied;
  const int room2 = before.labels.at<int>(plan.rooms[2].y + 50, plan.rooms[2].x + 41);
  const Segmentation after = segmenter.update(blocked);
  expect_valid(blocked, after);
  EXPECT_EQ(segmenter.last_update().redecomposed_rooms, 1 + passage_neighbours(before, room2));
  const Segmentation batch = segment(blocked, options.segment);
  EXPECT_EQ(after.rooms.size(), batch.rooms.size());
}

TEST(IncrementalSegmenter, DeterministicAcrossInstances) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter a, b;
  std::vector<cv::Rect> seen{plan.corridor};
  for (std::size_t k = 0; k < plan.rooms.size(); ++k) {
    seen.push_back(plan.doors[k]);
    seen.push_back(plan.rooms[k]);
    const OccupancyGrid grid = reveal(plan, seen);
    const Segmentation& sa = a.update(grid);
    const Segmentation& sb = b.update(grid);
    EXPECT_EQ(cv::countNonZero(sa.labels != sb.labels), 0);
    ASSERT_EQ(sa.passages.size(), sb.passages.size());
    for (std::size_t i = 0; i < sa.passages.size(); ++i) EXPECT_EQ(sa.passages[i].cut, sb.passages[i].cut);
  }
}

TEST(IncrementalSegmenter, BadInputIsOneClearError) {
  IncrementalSegmenter segmenter;
  OccupancyGrid empty;
  EXPECT_THROW(segmenter.update(empty), Error);
  IncrementalOptions bad;
  bad.segment.concavity = -1.0;
  EXPECT_THROW(IncrementalSegmenter{bad}, Error);
  IncrementalOptions bad_fraction;
  bad_fraction.batch_fraction = 0.0;
  EXPECT_THROW(IncrementalSegmenter{bad_fraction}, Error);
  IncrementalOptions no_merge;
  no_merge.merge_after = 0;
  EXPECT_THROW(IncrementalSegmenter{no_merge}, Error);
  IncrementalOptions no_margin;
  no_margin.partial_area = 10.0;
  no_margin.partial_margin = 0.0;
  EXPECT_THROW(IncrementalSegmenter{no_margin}, Error);
  IncrementalOptions covering;
  covering.segment.labels.cover_absorbed_obstacles = true;  // would label obstacle cells
  EXPECT_THROW(IncrementalSegmenter{covering}, Error);
  // After a failed update the segmenter still works.
  const FloorPlan plan = floor_plan();
  expect_valid(plan.world, segmenter.update(plan.world));
}

TEST(IncrementalSegmenter, TheReportListsEveryRoomWhoseCellsChanged) {
  const std::vector<OccupancyGrid> grids = testing::growing_map_sequence();
  IncrementalOptions partial;  // large rooms decomposed near the change only, holds of 3
  partial.partial_area = 5.0;
  partial.split_after = partial.merge_after = 3;
  for (const IncrementalOptions& options : {IncrementalOptions{}, trivial_options(), partial}) {
    IncrementalSegmenter segmenter(options);
    cv::Mat before;
    int windowed = 0, moved = 0, unlisted = 0;
    for (std::size_t step = 0; step < grids.size(); ++step) {
      const Segmentation& after = segmenter.update(grids[step]);
      const IncrementalUpdateReport& report = segmenter.last_update();
      EXPECT_EQ(report.every_room_relabelled, report.kind == IncrementalUpdateReport::Kind::kBatch &&
                                                  report.reason != "the change touched every room") << "step " << step;
      if (!before.empty() && !report.every_room_relabelled) {
        testing::expect_relabelled_rooms_listed(before, after, report, step);
        windowed += report.kind == IncrementalUpdateReport::Kind::kIncremental;
        moved += report.shift != cv::Point();
        for (const Room& room : after.rooms) unlisted += !std::binary_search(report.relabelled_rooms.begin(), report.relabelled_rooms.end(), room.id);
      }
      before = after.labels.clone();
    }
    EXPECT_GE(windowed, 3);
    EXPECT_GE(moved, 3);
    EXPECT_GT(unlisted, 0);  // some rooms left alone, so that the check above can fail
  }
}

TEST(IncrementalSegmenter, StateIsProportionalToTheMap) {
  const FloorPlan plan = floor_plan();
  IncrementalSegmenter segmenter;
  segmenter.update(plan.world);
  const std::size_t cells = plan.world.cells.total();
  // Grid copy, cleaned floor, labelled cells (a byte each), labels and retired ids (four each).
  EXPECT_GE(segmenter.state_bytes(), 11 * cells);
  EXPECT_LT(segmenter.state_bytes(), 13 * cells);
}

}  // namespace
}  // namespace topocut
