// One segmenter, two schedules: the incremental segmenter runs segment()'s stages, so a map given at
// once gets segment()'s rooms cell for cell (ids included), under every rule switch of the one rule
// list, and a growing map segmented again as a whole ends on segment()'s rooms of the final map.
#include "topocut/segmentation/incremental_segmenter.h"

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "topocut/core/error.h"
#include "topocut/segmentation/segmentation_rules.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {
namespace {

// Read with OpenCV directly (segmentation does not use io): grey > 250 free, < 50 occupied, else unknown.
OccupancyGrid read_bundled(const std::string& name) {
  const std::string path = std::string(TOPOCUT_SOURCE_DIR "/maps/") + name + ".png";
  const cv::Mat grey = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (grey.empty()) throw Error("test map missing: " + path);
  OccupancyGrid grid{cv::Mat(grey.size(), CV_8UC1, cv::Scalar(kUnknown)), 0.05, {1.5, -2.0}};
  grid.cells.setTo(kFree, grey > 250);
  grid.cells.setTo(kOccupied, grey < 50);
  return grid;
}

// Two rooms and a corridor with a ray fan through a gap, unknown specks in the floor and a room
// bounded mostly by never-seen space: the cleaning and the open-room rule have work to do.
OccupancyGrid raw_slam_like_map() {
  OccupancyGrid grid{cv::Mat(140, 220, CV_8UC1, cv::Scalar(kUnknown)), 0.05, {0.0, 0.0}};
  cv::Mat& c = grid.cells;
  c(cv::Rect(10, 10, 200, 90)).setTo(kOccupied);
  c(cv::Rect(14, 14, 90, 82)).setTo(kFree);
  c(cv::Rect(108, 14, 98, 82)).setTo(kFree);
  c(cv::Rect(104, 14, 4, 82)).setTo(kOccupied);
  c(cv::Rect(104, 45, 4, 18)).setTo(kFree);                              // a door
  c(cv::Rect(150, 96, 6, 4)).setTo(kFree);                               // a gap in the wall ...
  for (int r = 100; r < 135; ++r) c(cv::Rect(150 - (r - 100) / 3, r, 6 + 2 * ((r - 100) / 3), 1)).setTo(kFree);  // ... and a fan
  for (int k = 0; k < 12; ++k) c.at<unsigned char>(30 + 5 * k, 40 + 4 * k) = kUnknown;  // floor nobody reported
  c(cv::Rect(206, 30, 4, 40)).setTo(kUnknown);                           // a wall never seen
  return grid;
}

void expect_identical(const Segmentation& a, const Segmentation& b) {
  ASSERT_EQ(a.labels.size(), b.labels.size());
  EXPECT_EQ(cv::countNonZero(a.labels != b.labels), 0);
  ASSERT_EQ(a.rooms.size(), b.rooms.size());
  for (std::size_t i = 0; i < a.rooms.size(); ++i) {
    EXPECT_EQ(a.rooms[i].id, b.rooms[i].id);
    EXPECT_EQ(a.rooms[i].polygon, b.rooms[i].polygon);
  }
  ASSERT_EQ(a.passages.size(), b.passages.size());
  for (std::size_t i = 0; i < a.passages.size(); ++i) {
    EXPECT_EQ(a.passages[i].room_a, b.passages[i].room_a);
    EXPECT_EQ(a.passages[i].room_b, b.passages[i].room_b);
    EXPECT_EQ(a.passages[i].door, b.passages[i].door);
  }
}

// The label of a in each room of b, if the two images are one partition under a renaming.
bool same_partition(const cv::Mat& a, const cv::Mat& b, std::map<int, int>* b_to_a = nullptr) {
  std::map<int, int> forward, backward;
  for (int r = 0; r < a.rows; ++r)
    for (int c = 0; c < a.cols; ++c) {
      const int x = a.at<int>(r, c), y = b.at<int>(r, c);
      if ((x == 0) != (y == 0)) return false;
      if (x == 0) continue;
      if (forward.emplace(x, y).first->second != y || backward.emplace(y, x).first->second != x) return false;
    }
  if (b_to_a) *b_to_a = backward;
  return true;
}

// Checks the carrying rule between two label images of one frame: a room of before with more than
// half its cells in one room of after, and the largest share of that room, passes its id on.
// Returns how many rooms it checked.
int expect_ids_carried(const cv::Mat& before, const cv::Mat& after) {
  std::map<int, std::map<int, long long>> to;  // before id -> after id -> cells
  std::map<int, long long> size;
  for (int r = 0; r < before.rows; ++r)
    for (int c = 0; c < before.cols; ++c) {
      const int a = before.at<int>(r, c), b = after.at<int>(r, c);
      if (a > 0) ++size[a];
      if (a > 0 && b > 0) ++to[a][b];
    }
  int checked = 0;
  for (const auto& [id, shares] : to)
    for (const auto& [now, cells] : shares) {
      if (2 * cells <= size[id]) continue;
      bool largest = true;
      for (const auto& [other, other_shares] : to)
        if (other != id && other_shares.count(now) && other_shares.at(now) > cells) largest = false;
      if (!largest) continue;
      EXPECT_EQ(now, id);
      ++checked;
    }
  return checked;
}

TEST(IncrementalBatch, AMapGivenAtOnceGetsBatchRoomsCellForCell) {
  std::vector<std::pair<std::string, OccupancyGrid>> maps{{"raw", raw_slam_like_map()}};
  for (const char* name : {"floorplan", "furnished", "corridor_l"}) maps.emplace_back(name, read_bundled(name));
  for (const auto& [name, grid] : maps) {
    SCOPED_TRACE(name);
    IncrementalSegmenter segmenter;
    const Segmentation& s = segmenter.update(grid);
    expect_identical(s, segment(grid));
    EXPECT_GE(s.rooms.size(), name == "corridor_l" ? 1u : 2u);  // an L-shaped corridor is one room
  }
}

TEST(IncrementalBatch, EveryRuleOfTheListIsLiveInTheIncrementalSegmenter) {
  // Each rule switched off in turn: the incremental segmenter follows segment() with the same
  // options, so a rule added to the list needs no code here.
  const OccupancyGrid grid = raw_slam_like_map();
  const Segmentation with_all = segment(grid);
  int rules_that_change_this_map = 0;
  for (const SegmentationRule& rule : segmentation_rules()) {
    if (!rule.turn_off) continue;  // on with its stage
    SCOPED_TRACE(rule.name);
    IncrementalOptions options;
    rule.turn_off(options.segment);
    const Segmentation batch = segment(grid, options.segment);
    IncrementalSegmenter segmenter(options);
    expect_identical(segmenter.update(grid), batch);
    rules_that_change_this_map += cv::countNonZero(batch.labels != with_all.labels) > 0;
  }
  EXPECT_GE(rules_that_change_this_map, 1);  // the map exercises the rules, not only the defaults
}

TEST(IncrementalBatch, AGrowingMovingMapSegmentedAgainAsAWholeEndsOnBatchRooms) {
  // furnished revealed in five growing windows, the origin moving as a SLAM map's does; resegment()
  // then gives segment()'s rooms of the final map, rooms keeping the ids of those they overlap most.
  const OccupancyGrid world = read_bundled("furnished");
  IncrementalSegmenter segmenter;
  OccupancyGrid grid;
  for (int k = 1; k <= 5; ++k) {
    const int w = world.width() * k / 5, h = world.height() * (k + 5) / 10;
    const cv::Rect window(world.width() - w, 0, w, h);  // grows leftwards and downwards
    grid = OccupancyGrid{world.cells(window).clone(), world.resolution,
                         {world.origin.x + window.x * world.resolution,
                          world.origin.y + (world.height() - window.br().y) * world.resolution}};
    segmenter.update(grid);
  }
  const Segmentation before = segmenter.result();
  const Segmentation& after = segmenter.resegment();
  const Segmentation batch = segment(grid);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kBatch);
  std::map<int, int> batch_to_after;
  ASSERT_TRUE(same_partition(after.labels, batch.labels, &batch_to_after));
  EXPECT_EQ(after.rooms.size(), batch.rooms.size());
  EXPECT_EQ(after.passages.size(), batch.passages.size());
  // Ids carried by overlap from the windowed result.
  EXPECT_GE(expect_ids_carried(before.labels, after.labels), static_cast<int>(after.rooms.size()) / 2);
  // Nothing changed since: the next update of the same grid returns the same rooms.
  const Segmentation again = segmenter.update(grid);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kUnchanged);
  EXPECT_EQ(cv::countNonZero(again.labels != after.labels), 0);
}

TEST(IncrementalBatch, WithoutWindowsEveryUpdateIsBatchWithCarriedIds) {
  // windowed = false: batch's own schedule, every update segment() with ids carried by overlap.
  const OccupancyGrid world = read_bundled("floorplan");
  IncrementalOptions options;
  options.windowed = false;
  IncrementalSegmenter segmenter(options);
  cv::Mat previous;
  for (int k = 1; k <= 3; ++k) {
    OccupancyGrid grid = world;
    grid.cells = cv::Mat(world.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
    const cv::Rect seen(0, 0, world.width() * k / 3, world.height());
    world.cells(seen).copyTo(grid.cells(seen));
    const Segmentation& s = segmenter.update(grid);
    EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kBatch);
    EXPECT_TRUE(same_partition(s.labels, segment(grid).labels));
    if (!previous.empty()) {
      EXPECT_GE(expect_ids_carried(previous, s.labels), 1);  // the map has such rooms: the check checks something
    }
    previous = s.labels.clone();
  }
}

// The cells segment() gives a room: what every update must label, whatever its schedule.
cv::Mat labelled_cells(const Segmentation& s) { return s.labels > 0; }

TEST(IncrementalBatch, AWallLessStripGrowingIsLabelledAsBatchLabelsIt) {
  // A free strip without walls, 6 cells high, 241 then 247 long: the cleaning leaves it no floor, so
  // segment() decomposes it uncleaned; a windowed update used to clean its window and label only
  // part of it (1068 of 1482 cells) while reporting a batch update.
  IncrementalSegmenter segmenter;
  segmenter.update(OccupancyGrid{cv::Mat(6, 241, CV_8UC1, cv::Scalar(kFree)), 0.05, {0.0, 0.0}});
  const OccupancyGrid grown{cv::Mat(6, 247, CV_8UC1, cv::Scalar(kFree)), 0.05, {0.0, 0.0}};
  const Segmentation& s = segmenter.update(grown);
  EXPECT_EQ(cv::countNonZero(labelled_cells(s) != labelled_cells(segment(grown))), 0);
  EXPECT_EQ(cv::countNonZero(s.labels), 6 * 247);
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kBatch);
  // Seen after nothing was: the window's cleaning finds no floor and nothing to label, which read
  // as "unchanged" and no room, while segment() labels the strip.
  IncrementalSegmenter after_nothing;
  OccupancyGrid strip{cv::Mat(25, 265, CV_8UC1, cv::Scalar(kUnknown)), 0.05, {0.0, 0.0}};
  after_nothing.update(strip);
  strip.cells(cv::Rect(1, 0, 185, 9)).setTo(kFree);
  EXPECT_EQ(cv::countNonZero(labelled_cells(after_nothing.update(strip)) != labelled_cells(segment(strip))), 0);
  EXPECT_EQ(cv::countNonZero(after_nothing.result().labels), 185 * 9);
}

// A map of size never seen but for a corridor along its top edge, length cells long and 10 wide
// (thinner than a person), walled along its top and at its left end only.
OccupancyGrid thin_strip(cv::Size size, int length) {
  OccupancyGrid g{cv::Mat(size, CV_8UC1, cv::Scalar(kUnknown)), 0.05, {0.0, 0.0}};
  g.cells(cv::Rect(0, 0, length, 1)).setTo(kOccupied);
  g.cells(cv::Rect(0, 0, 1, 11)).setTo(kOccupied);
  g.cells(cv::Rect(1, 1, length - 1, 10)).setTo(kFree);
  return g;
}

TEST(IncrementalBatch, AThinStripRunningOutOfTheWindowIsJudgedOnTheWholeMap) {
  // The strip seen further along: whether it is a ray depends on all of it, not on the window around
  // the change.
  const auto strip = [](int length) { return thin_strip({295, 22}, length); };
  IncrementalSegmenter segmenter;
  segmenter.update(strip(193));
  const OccupancyGrid longer = strip(216);
  const Segmentation& s = segmenter.update(longer);
  EXPECT_EQ(cv::countNonZero(labelled_cells(s) != labelled_cells(segment(longer))), 0);
  EXPECT_GT(cv::countNonZero(s.labels), 2000);
}

TEST(IncrementalBatch, AThinStripRunningOutOfTheWindowIsJudgedInAWindowGrownToHoldIt) {
  // The same corridor, 470 cells long, on a larger map with a walled room far below: seen further
  // along at its right end, it runs out of the context of the change's window, so that cleaning
  // alone would judge it a ray (the context's edge reads as never seen). The window grows to hold the
  // strip: the update stays windowed and labels what segment() labels.
  const auto map = [](int length) {
    OccupancyGrid g = thin_strip({700, 200}, length);
    g.cells(cv::Rect(100, 100, 120, 90)).setTo(kOccupied);
    g.cells(cv::Rect(104, 104, 112, 82)).setTo(kFree);
    return g;
  };
  IncrementalSegmenter segmenter;
  segmenter.update(map(470));
  for (const int length : {490, 510}) {
    SCOPED_TRACE(length);
    const OccupancyGrid longer = map(length);
    const Segmentation& s = segmenter.update(longer);
    EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kIncremental) << segmenter.last_update().reason;
    EXPECT_EQ(cv::countNonZero(labelled_cells(s) != labelled_cells(segment(longer))), 0);
    EXPECT_GT(cv::countNonZero(s.labels(cv::Rect(0, 0, length, 11))), 4000);  // the strip is kept: no ray
  }
}

// A world to reveal: a wall-less strip, or walled rooms with partitions and doorways, sometimes
// with specks of every kind.
cv::Mat random_world(std::mt19937& random, int h, int w) {
  const auto uniform = [&random](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  cv::Mat world(h, w, CV_8UC1, cv::Scalar(kFree));
  if (uniform(0, 2) == 0) return world;
  world.setTo(kOccupied);
  if (h > 2 && w > 2) world(cv::Rect(1, 1, w - 2, h - 2)).setTo(kFree);
  for (int k = uniform(0, 3); k > 0 && w > 4; --k) {
    const int x = uniform(2, w - 3);
    world.col(x).setTo(kOccupied);
    const int y = uniform(0, h - 1);
    world(cv::Rect(x, y, 1, std::min(4, h - y))).setTo(kFree);
  }
  for (int k = uniform(0, 12); k > 0; --k)
    world.at<unsigned char>(uniform(0, h - 1), uniform(0, w - 1)) = std::array<unsigned char, 3>{kFree, kOccupied, kUnknown}[static_cast<std::size_t>(uniform(0, 2))];
  return world;
}

TEST(IncrementalBatch, EveryUpdateOfRandomGrowingShrinkingShiftingGridsLabelsWhatSegmentLabels) {
  // Grids revealed part by part: the seen part grows, its frame grows or moves with it (the origin
  // follows the frame), sometimes shrinks; wall-less strips among them. After every update the
  // labelled cells are segment()'s on the same grid. Seeded: the same grids every run.
  std::mt19937 random(20251127);
  const auto uniform = [&random](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  int updates = 0, compared = 0;
  for (int sequence = 0; sequence < 200; ++sequence) {
    const int h = uniform(1, 40), w = uniform(5, 260);
    const cv::Mat world = random_world(random, h, w);
    IncrementalSegmenter segmenter;
    cv::Rect seen(0, 0, uniform(1, w), uniform(1, h));
    for (int step = 0; step < 6; ++step) {
      SCOPED_TRACE("sequence " + std::to_string(sequence) + ", step " + std::to_string(step));
      const cv::Rect frame = cv::Rect(std::max(0, seen.x - uniform(0, 2)), std::max(0, seen.y - uniform(0, 2)), w, h) &
                             cv::Rect(0, 0, w, h);
      OccupancyGrid grid{cv::Mat(frame.size(), CV_8UC1, cv::Scalar(kUnknown)), 0.05,
                         {frame.x * 0.05, (h - frame.br().y) * 0.05}};
      const cv::Rect inside = seen & frame;
      world(inside).copyTo(grid.cells(inside - frame.tl()));
      const Segmentation& s = segmenter.update(grid);
      ++updates;
      if (cv::countNonZero(grid.cells == kFree) > 0) {
        const cv::Mat batch = labelled_cells(segment(grid));
        ASSERT_EQ(cv::countNonZero(labelled_cells(s) != batch), 0) << "labelled " << cv::countNonZero(s.labels) << ", batch "
                                                                   << cv::countNonZero(batch);
        ++compared;
      }
      const int grow = uniform(0, 40), shrink = uniform(0, 4) == 0 ? uniform(0, 5) : 0;
      seen = cv::Rect(seen.x + shrink, seen.y, seen.width + grow - shrink, seen.height + uniform(0, 8)) & cv::Rect(0, 0, w, h);
      if (seen.empty()) seen = cv::Rect(0, 0, 1, 1);
    }
  }
  EXPECT_EQ(updates, 1200);
  EXPECT_GT(compared, 1000);  // most grids hold free space: the property is checked, not skipped
}

// Two buildings far apart: A (three rooms off a corridor) and, up and to the right, B (two rooms and a
// door), of which only the part left of column b_seen is known yet.
OccupancyGrid two_buildings(int b_seen) {
  OccupancyGrid grid{cv::Mat(200, 420, CV_8UC1, cv::Scalar(kUnknown)), 0.05, {-3.0, 7.5}};
  cv::Mat& c = grid.cells;
  c(cv::Rect(10, 60, 180, 130)).setTo(kOccupied);  // A
  c(cv::Rect(14, 64, 172, 30)).setTo(kFree);         // corridor
  for (int k = 0; k < 3; ++k) {
    c(cv::Rect(14 + 58 * k, 98, 54, 88)).setTo(kFree);
    c(cv::Rect(30 + 58 * k, 94, 16, 4)).setTo(kFree);  // doors to the corridor
  }
  cv::Mat b(grid.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
  b(cv::Rect(290, 10, 124, 80)).setTo(kOccupied);
  b(cv::Rect(294, 14, 56, 72)).setTo(kFree);
  b(cv::Rect(354, 14, 56, 72)).setTo(kFree);
  b(cv::Rect(350, 40, 4, 16)).setTo(kFree);  // the door
  if (b_seen == 0) return grid;
  const cv::Rect seen(0, 0, b_seen, grid.height());
  b(seen).copyTo(c(seen), b(seen) != kUnknown);
  return grid;
}

TEST(IncrementalBatch, WindowedUpdatesThatReDoABuildingGiveItsBatchRooms) {
  // The first update segments the whole map; the next ones reveal building B column by column, so
  // each is a windowed update re-doing B's rooms (the touched one and its neighbour across the
  // door) with segment()'s stages, A's rooms kept as they were: the partition is segment()'s.
  IncrementalSegmenter segmenter;
  int windowed = 0;
  cv::Mat previous;
  for (const int seen : {330, 372, 392, 420}) {
    SCOPED_TRACE(seen);
    const OccupancyGrid grid = two_buildings(seen);
    const Segmentation& s = segmenter.update(grid);
    const Segmentation batch = segment(grid);
    windowed += segmenter.last_update().kind == IncrementalUpdateReport::Kind::kIncremental;
    EXPECT_TRUE(same_partition(s.labels, batch.labels));
    EXPECT_EQ(s.rooms.size(), batch.rooms.size());
    ASSERT_EQ(s.passages.size(), batch.passages.size());
    for (std::size_t i = 0; i < s.passages.size(); ++i) EXPECT_EQ(s.passages[i].door, batch.passages[i].door);
    if (!previous.empty()) expect_ids_carried(previous, s.labels);
    previous = s.labels.clone();
  }
  EXPECT_EQ(windowed, 3);  // the checks above saw the windowed path
  EXPECT_EQ(segmenter.result().rooms.size(), 6u);  // A's corridor and three rooms, B's two
  // At rest: segment()'s rooms cell for cell, the ids those of the windowed rooms.
  const cv::Mat live = segmenter.result().labels.clone();
  const Segmentation& settled = segmenter.resegment();
  EXPECT_EQ(cv::countNonZero(settled.labels != live), 0);
}

TEST(IncrementalBatch, ASavedLedgerGivesARestartedSegmenterTheSameIds) {
  // B's rooms are seen last, so they carry the highest ids although they come first in raster order:
  // a fresh segmenter would number them first; one that loads the saved ledger gives them theirs.
  IncrementalSegmenter first;
  for (const int seen : {0, 372, 420}) first.update(two_buildings(seen));
  std::stringstream ledger;
  first.save_ledger(ledger);
  const OccupancyGrid final_map = two_buildings(420);
  IncrementalSegmenter fresh;
  ASSERT_NE(cv::countNonZero(fresh.update(final_map).labels != first.result().labels), 0);  // the check checks something

  IncrementalSegmenter restarted;
  restarted.load_ledger(ledger);
  // The map as the restarted node first sees it: grown by 30 cells on the left and 20 at the top.
  OccupancyGrid grown{cv::Mat(220, 450, CV_8UC1, cv::Scalar(kUnknown)), 0.05, {-3.0 - 30 * 0.05, 7.5}};
  final_map.cells.copyTo(grown.cells(cv::Rect(30, 20, 420, 200)));
  const Segmentation& s = restarted.update(grown);
  EXPECT_EQ(cv::countNonZero(s.labels(cv::Rect(30, 20, 420, 200)) != first.result().labels), 0);
  ASSERT_EQ(s.rooms.size(), first.result().rooms.size());
  for (std::size_t i = 0; i < s.rooms.size(); ++i) EXPECT_EQ(s.rooms[i].id, first.result().rooms[i].id);
  // A room seen after the restart takes an id never handed out before it.
  int highest = 0;
  for (const Room& room : first.result().rooms) highest = std::max(highest, room.id);
  grown.cells(cv::Rect(2, 2, 64, 64)).setTo(kOccupied);
  grown.cells(cv::Rect(4, 4, 60, 60)).setTo(kFree);
  const std::size_t rooms_before = s.rooms.size();  // s is the segmenter's result, about to change
  ASSERT_EQ(segment(grown).rooms.size(), rooms_before + 1);
  const Segmentation& more = restarted.update(grown);
  ASSERT_EQ(more.rooms.size(), rooms_before + 1);
  EXPECT_GT(more.rooms.back().id, highest);
}

TEST(IncrementalBatch, ALedgerCannotBeSavedBeforeTheFirstUpdateNorReadDamaged) {
  IncrementalSegmenter segmenter;
  std::stringstream out;
  EXPECT_THROW(segmenter.save_ledger(out), Error);
  segmenter.update(two_buildings(420));
  const cv::Mat before = segmenter.result().labels.clone();
  std::istringstream damaged("topocut-id-ledger 1\nnext_id x\n");
  EXPECT_THROW(segmenter.load_ledger(damaged), Error);
  // Refused before anything was forgotten: the next update of the same map changes nothing.
  segmenter.update(two_buildings(420));
  EXPECT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kUnchanged);
  EXPECT_EQ(cv::countNonZero(segmenter.result().labels != before), 0);
}

}  // namespace
}  // namespace topocut
