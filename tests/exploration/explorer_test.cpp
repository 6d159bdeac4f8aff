#include "topocut/exploration/explorer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;

// 20 m x 12 m: a corridor along the bottom, three rooms above with doors, and a long room on the
// right reached through the corridor's end; walls 4 cells thick. Farther than 5 m from any single
// point, so the robot must move to see it all.
OccupancyGrid building() {
  OccupancyGrid g;
  g.resolution = kRes;
  g.origin = {-3.0, 2.0};
  g.cells = cv::Mat(240, 400, CV_8UC1, cv::Scalar(kOccupied));
  g.cells(cv::Rect(4, 190, 330, 46)).setTo(kFree);  // corridor
  int x = 4;
  for (const int width : {100, 120, 102}) {
    g.cells(cv::Rect(x, 4, width, 182)).setTo(kFree);
    g.cells(cv::Rect(x + width / 2 - 10, 186, 20, 4)).setTo(kFree);  // door
    x += width + 4;
  }
  g.cells(cv::Rect(338, 4, 58, 232)).setTo(kFree);  // right room
  g.cells(cv::Rect(334, 200, 4, 20)).setTo(kFree);  // its door
  g.cells(cv::Rect(150, 60, 12, 12)).setTo(kOccupied);  // a pillar
  g.cells(cv::Rect(40, 100, 30, 10)).setTo(kUnknown);   // furniture drawn grey: blocks the laser
  return g;
}

std::vector<cv::Mat> explore_all(Explorer& explorer, int cap = 100000) {
  std::vector<cv::Mat> maps;
  while (explorer.next() && cap-- > 0) maps.push_back(explorer.known_cells().clone());
  return maps;
}

TEST(Explorer, TerminatesHavingSeenTheReachableFreeSpace) {
  const OccupancyGrid world = building();
  Explorer explorer(world);
  const std::vector<cv::Mat> maps = explore_all(explorer);
  ASSERT_TRUE(explorer.finished());
  EXPECT_EQ(explorer.stop_reason(), "no reachable frontier left");
  EXPECT_GT(explorer.scans(), 10);
  EXPECT_FALSE(explorer.next());  // stays finished
  const int known_free = cv::countNonZero(explorer.known_cells() == kFree);
  const int reachable = reachable_free_cells(world, explorer.path().front());
  EXPECT_EQ(reachable, cv::countNonZero(world.cells == kFree));
  EXPECT_GT(known_free, 0.98 * reachable);
}

TEST(Explorer, KnownMapNeverContradictsTheGroundTruth) {
  const OccupancyGrid world = building();
  Explorer explorer(world);
  int checked = 0;
  while (explorer.next()) {
    const cv::Mat& known = explorer.known_cells();
    // Free only where the world is free; occupied only where the world blocks the laser.
    ASSERT_EQ(cv::countNonZero((known == kFree) & (world.cells != kFree)), 0) << "after scan " << explorer.scans();
    ASSERT_EQ(cv::countNonZero((known == kOccupied) & (world.cells == kFree)), 0) << "after scan " << explorer.scans();
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

TEST(Explorer, ChangedIsExactlyTheBoxOfTheCellsAScanChanged) {
  const OccupancyGrid world = building();
  Explorer explorer(world);
  cv::Mat before = explorer.known_cells().clone();
  int empty_scans = 0;
  while (explorer.next()) {
    const cv::Mat diff = explorer.known_cells() != before;
    const cv::Rect box = cv::countNonZero(diff) ? cv::boundingRect(diff) : cv::Rect();
    ASSERT_EQ(explorer.changed(), box) << "scan " << explorer.scans();
    empty_scans += box.empty();
    before = explorer.known_cells().clone();
  }
  EXPECT_GT(explorer.scans(), empty_scans);
}

TEST(Explorer, WalksThroughFreeSpaceInSteps) {
  const OccupancyGrid world = building();
  ExplorationOptions options;
  options.step = 0.5;
  Explorer explorer(world, options);
  explore_all(explorer);
  const std::vector<Point2>& path = explorer.path();
  ASSERT_EQ(static_cast<int>(path.size()), explorer.scans());
  double length = 0.0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const cv::Point cell = world_to_cell(world, path[i]);
    ASSERT_EQ(world.cells.at<unsigned char>(cell), kFree);
    if (i == 0) continue;
    const double d = distance(path[i - 1], path[i]);
    // A step is at most `step` along an 8-connected route (a straight line is never longer), and
    // at least one cell.
    EXPECT_LE(d, options.step + 1e-9);
    EXPECT_GE(d, kRes - 1e-9);
    length += d;
  }
  EXPECT_NEAR(explorer.path_length(), length, 1e-6);
}

TEST(Explorer, DeterministicForASeed) {
  const OccupancyGrid world = building();
  for (const std::uint32_t seed : {0u, 7u}) {
    ExplorationOptions options;
    options.seed = seed;
    Explorer a(world, options), b(world, options);
    explore_all(a);
    explore_all(b);
    EXPECT_EQ(a.path(), b.path());
    EXPECT_EQ(cv::countNonZero(a.known_cells() != b.known_cells()), 0);
  }
  ExplorationOptions seven, eight;
  seven.seed = 7;
  eight.seed = 8;
  Explorer s7(world, seven), s8(world, eight);
  s7.next();
  s8.next();
  EXPECT_NE(s7.path().front(), s8.path().front());
}

TEST(Explorer, DefaultStartIsTheMostOpenCellAndSeedsStartWithClearance) {
  // A square room of 59 x 59 free cells: its centre cell (30, 30) is the one farthest from walls.
  OccupancyGrid square;
  square.resolution = kRes;
  square.cells = cv::Mat(61, 61, CV_8UC1, cv::Scalar(kOccupied));
  square.cells(cv::Rect(1, 1, 59, 59)).setTo(kFree);
  Explorer centre(square);
  centre.next();
  EXPECT_EQ(world_to_cell(square, centre.path().front()), cv::Point(30, 30));

  // A wide room: many cells tie for the most open; the first in raster order wins.
  OccupancyGrid room;
  room.resolution = kRes;
  room.cells = cv::Mat(60, 100, CV_8UC1, cv::Scalar(kOccupied));
  room.cells(cv::Rect(1, 1, 98, 58)).setTo(kFree);
  cv::Mat clearance;
  cv::distanceTransform(room.cells == kFree, clearance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  double best = 0.0;
  cv::Point best_cell;
  cv::minMaxLoc(clearance, nullptr, &best, nullptr, &best_cell);  // first maximum in raster order
  Explorer wide(room);
  wide.next();
  EXPECT_EQ(world_to_cell(room, wide.path().front()), best_cell);

  ExplorationOptions seeded;
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    seeded.seed = seed;
    Explorer e(room, seeded);
    e.next();
    EXPECT_GE(clearance.at<float>(world_to_cell(room, e.path().front())), 0.3 / kRes - 1e-3);
  }
}

TEST(Explorer, GivenStartAndBadInput) {
  const OccupancyGrid world = building();
  ExplorationOptions options;
  options.start = Point2{-3.0 + 20 * kRes, 2.0 + (240 - 200) * kRes};  // cell (20, 199): corridor
  Explorer e(world, options);
  e.next();
  EXPECT_EQ(e.path().front(), *options.start);
  options.start = Point2{-3.0 + 0.5 * kRes, 2.0 + 0.5 * kRes};  // corner cell: wall
  EXPECT_THROW(Explorer(world, options), Error);
  options.start = Point2{100.0, 100.0};  // outside the map
  EXPECT_THROW(Explorer(world, options), Error);
  OccupancyGrid solid = world;
  solid.cells = cv::Mat(20, 20, CV_8UC1, cv::Scalar(kOccupied));
  EXPECT_THROW(Explorer{solid}, Error);
  for (auto bad : {&ExplorationOptions::range, &ExplorationOptions::step, &ExplorationOptions::angular_resolution}) {
    ExplorationOptions o;
    o.*bad = 0.0;
    EXPECT_THROW(Explorer(world, o), Error);
  }
  ExplorationOptions no_scans;
  no_scans.max_scans = 0;
  EXPECT_THROW(Explorer(world, no_scans), Error);
}

TEST(Explorer, ADrivableMaskKeepsTheRobotOutButNotTheLaser) {
  const OccupancyGrid world = building();
  // The right room (behind the corridor's end) may be seen but not entered.
  cv::Mat drivable = world.cells == kFree;
  const cv::Rect right_room(334, 0, 66, 240);
  drivable(right_room).setTo(0);
  ExplorationOptions options;
  options.start = Point2{-3.0 + 20.5 * kRes, 2.0 + (240 - 199.5) * kRes};  // corridor
  Explorer explorer(world, drivable, options);
  explore_all(explorer);
  ASSERT_TRUE(explorer.finished());
  for (const Point2& p : explorer.path()) {
    const cv::Point cell = world_to_cell(world, p);
    ASSERT_NE(drivable.at<unsigned char>(cell), 0) << p.x << ", " << p.y;
  }
  EXPECT_GT(cv::countNonZero(explorer.known_cells()(right_room) == kFree), 100);  // seen through its door
  // Without the mask the robot walks in.
  Explorer free_to_go(world, options);
  explore_all(free_to_go);
  const auto inside = [&](const Point2& p) { return right_room.contains(world_to_cell(world, p)); };
  EXPECT_TRUE(std::any_of(free_to_go.path().begin(), free_to_go.path().end(), inside));
  // The start must be drivable; the mask must fit the map.
  options.start = Point2{-3.0 + 360.5 * kRes, 2.0 + (240 - 100.5) * kRes};  // right room
  EXPECT_THROW(Explorer(world, drivable, options), Error);
  options.start.reset();
  EXPECT_THROW(Explorer(world, drivable(cv::Rect(0, 0, 10, 10)).clone(), options), Error);
  EXPECT_THROW(Explorer(world, cv::Mat::zeros(world.cells.size(), CV_8UC1), options), Error);
}

TEST(Explorer, ScanCapStopsExploration) {
  const OccupancyGrid world = building();
  ExplorationOptions options;
  options.max_scans = 5;
  Explorer explorer(world, options);
  explore_all(explorer);
  EXPECT_EQ(explorer.scans(), 5);
  EXPECT_NE(explorer.stop_reason().find("cap"), std::string::npos);
}

TEST(Explorer, ShortRangeNeedsMoreScans) {
  const OccupancyGrid world = building();
  ExplorationOptions short_range;
  short_range.range = 2.0;
  Explorer near(world, short_range), far(world);
  explore_all(near);
  explore_all(far);
  EXPECT_EQ(near.stop_reason(), "no reachable frontier left");
  EXPECT_GT(near.scans(), far.scans());
}

TEST(Explorer, GrowingMapPublishesTheSeenPartInItsWorldPlace) {
  const OccupancyGrid world = building();
  ExplorationOptions options;
  options.growing_map = true;
  Explorer explorer(world, options);
  int growths = 0;
  cv::Size last_size;
  while (explorer.next()) {
    const OccupancyGrid& grid = explorer.known_map();
    const cv::Rect window = explorer.window();
    ASSERT_EQ(grid.cells.size(), window.size());
    // Every known cell lies inside the window, and the window's cells are the known ones.
    ASSERT_EQ(cv::countNonZero(explorer.known_cells() != kUnknown), cv::countNonZero(grid.cells != kUnknown));
    ASSERT_EQ(cv::countNonZero(grid.cells != explorer.known_cells()(window)), 0);
    // Same world position for the same cell in both frames.
    const Point2 a = cell_center_world(grid, 3, 5);
    const Point2 b = cell_center_world(world, window.x + 3, window.y + 5);
    ASSERT_NEAR(a.x, b.x, 1e-9);
    ASSERT_NEAR(a.y, b.y, 1e-9);
    if (grid.cells.size() != last_size) ++growths;
    last_size = grid.cells.size();
    const cv::Rect inside(cv::Point(0, 0), grid.cells.size());
    ASSERT_EQ(explorer.changed() & inside, explorer.changed());
  }
  EXPECT_GT(growths, 1);
  EXPECT_LE(explorer.window().width, world.width());
}

}  // namespace
}  // namespace topocut
