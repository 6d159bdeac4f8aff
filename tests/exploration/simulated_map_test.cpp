#include "topocut/exploration/simulated_map.h"

#include <array>
#include <cstring>
#include <set>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {
namespace {

// A plan drawn like a Bormann map (free floor, everything else black): 12 m x 8 m, a building of
// 10 m x 6 m with walls 4 cells thick, a corridor along its bottom and three rooms above it, each
// behind a 0.9 m door. People's rooms: 1..3 the rooms, 4 the corridor; the doors in no room.
struct Plan {
  OccupancyGrid grid;
  cv::Mat rooms;                 // CV_32SC1
  std::array<cv::Rect, 3> room;  // the three rooms' floor, plan cells
};

Plan plan() {
  Plan p;
  p.grid.resolution = 0.05;
  p.grid.origin = {1.0, -2.0};
  p.grid.cells = cv::Mat(160, 240, CV_8UC1, cv::Scalar(kOccupied));
  p.rooms = cv::Mat::zeros(160, 240, CV_32SC1);
  const cv::Rect corridor(24, 100, 192, 36);
  p.grid.cells(corridor).setTo(kFree);
  p.rooms(corridor).setTo(4);
  p.room = {cv::Rect(24, 24, 60, 72), cv::Rect(88, 24, 60, 72), cv::Rect(152, 24, 64, 72)};
  for (int k = 0; k < 3; ++k) {
    p.grid.cells(p.room[k]).setTo(kFree);
    p.rooms(p.room[k]).setTo(k + 1);
    const int door = p.room[k].x + p.room[k].width / 2 - 9;
    p.grid.cells(cv::Rect(door, 96, 18, 4)).setTo(kFree);
  }
  return p;
}

// Every realism off but the ones a test turns on: exact laser and poses, no furniture.
SimulatedMapOptions plain_options() {
  SimulatedMapOptions o;
  o.range_noise = 0.0;
  o.drift = 0.0;
  o.drift_angle = 0.0;
  o.windows = 0.0;
  o.closed_doors = 0.0;
  o.furniture = 0.0;
  o.clutter = 0.0;
  o.wall_change = 0;
  o.outside_obstacles = 0.0;
  return o;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && a.isContinuous() && b.isContinuous() &&
         std::memcmp(a.data, b.data, a.total() * a.elemSize()) == 0;
}

// The plan's room k (0-based) in the map's frame, shrunk by margin cells (drift, thickened walls).
cv::Rect in_map(const Plan& p, const SimulatedMap& s, int k, int margin) {
  const cv::Rect r = p.room[k] + s.offset;
  return cv::Rect(r.x + margin, r.y + margin, r.width - 2 * margin, r.height - 2 * margin);
}

TEST(SimulatedMap, SameSeedSameBytesOtherSeedOtherMap) {
  const Plan p = plan();
  const SimulatedMapOptions defaults;
  const SimulatedMap a = simulate_map(p.grid, p.rooms, defaults, 7);
  const SimulatedMap b = simulate_map(p.grid, p.rooms, defaults, 7);
  EXPECT_TRUE(same(a.map.cells, b.map.cells));
  EXPECT_TRUE(same(a.rooms, b.rooms));
  EXPECT_EQ(a.map.origin.x, b.map.origin.x);
  EXPECT_EQ(a.map.origin.y, b.map.origin.y);
  const SimulatedMap c = simulate_map(p.grid, p.rooms, defaults, 8);
  EXPECT_FALSE(same(a.map.cells, c.map.cells));
}

TEST(SimulatedMap, NeitherRoomNumbersNorOpenCVThreadsChangeTheMap) {
  const Plan p = plan();
  const SimulatedMapOptions defaults;
  const SimulatedMap a = simulate_map(p.grid, p.rooms, defaults, 3);
  // The same rooms numbered the other way round (OpenCV's parallel labelling numbers them by its
  // thread count): the same map, the same rooms under their new numbers.
  cv::Mat renumbered = p.rooms.clone();
  for (auto it = renumbered.begin<int>(); it != renumbered.end<int>(); ++it) *it = *it == 0 ? 0 : 50 - *it;
  const SimulatedMap b = simulate_map(p.grid, renumbered, defaults, 3);
  EXPECT_TRUE(same(a.map.cells, b.map.cells));
  EXPECT_TRUE(same(rooms_image(a), rooms_image(b)));
  EXPECT_EQ(cv::countNonZero(b.rooms == 46), cv::countNonZero(a.rooms == 4));
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const SimulatedMap c = simulate_map(p.grid, p.rooms, defaults, 3);
  cv::setNumThreads(threads);
  EXPECT_TRUE(same(a.map.cells, c.map.cells));
  EXPECT_TRUE(same(a.rooms, c.rooms));
}

TEST(SimulatedMap, KeepsTheFrameInTheWorldAndTheResolution) {
  const Plan p = plan();
  SimulatedMapOptions o = plain_options();
  o.outside = 3.0;
  const SimulatedMap s = simulate_map(p.grid, p.rooms, o, 1);
  EXPECT_EQ(s.map.resolution, p.grid.resolution);
  EXPECT_EQ(s.map.cells.size(), s.rooms.size());
  EXPECT_EQ(s.map.cells.size(), s.world.cells.size());
  // 3 m of ground and the outer wall around the building's floor, so the 1 m plan margin grew.
  const int margin = static_cast<int>(std::ceil((o.outside + o.outer_wall) / p.grid.resolution));
  EXPECT_EQ(s.offset, cv::Point(margin - 24, margin - 24));
  // A plan cell and its map cell have one world position.
  const Point2 a = cell_center_world(p.grid, 30, 40), b = cell_center_world(s.map, 30 + s.offset.x, 40 + s.offset.y);
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
}

TEST(SimulatedMap, NeverSeenCellsStayUnknownAndAClosedRoomIsNotSeen) {
  const Plan p = plan();
  SimulatedMapOptions o = plain_options();
  const SimulatedMap open = simulate_map(p.grid, p.rooms, o, 3);
  EXPECT_GT(cv::countNonZero(open.map.cells == kUnknown), 0);
  for (int k = 0; k < 3; ++k) EXPECT_GT(cv::countNonZero(open.map.cells(in_map(p, open, k, 2)) == kFree), 3000) << "room " << k + 1;

  o.closed_doors = 1.0;
  const SimulatedMap closed = simulate_map(p.grid, p.rooms, o, 3);
  EXPECT_EQ(closed.doors, 3);
  EXPECT_EQ(closed.closed_doors, 3);
  std::set<int> seen_rooms;
  for (auto it = closed.rooms.begin<int>(); it != closed.rooms.end<int>(); ++it) seen_rooms.insert(*it);
  EXPECT_EQ(seen_rooms, (std::set<int>{0, 4}));  // the corridor only
  for (int k = 0; k < 3; ++k) {
    const cv::Mat inside = closed.map.cells(in_map(p, closed, k, 1));
    EXPECT_EQ(cv::countNonZero(inside == kUnknown), inside.total()) << "room " << k + 1;
  }
}

TEST(SimulatedMap, WindowsLetBeamsDrawFansOutsideAndClosedWallsNone) {
  const Plan p = plan();
  SimulatedMapOptions o;  // noise, drift, furniture and the rest as they come
  o.no_return_length = 2.0;
  o.windows = 0.4;
  const SimulatedMap open = simulate_map(p.grid, p.rooms, o, 11);
  EXPECT_GT(open.windows, 0);
  EXPECT_GT(cv::countNonZero((open.map.cells == kFree) & open.exterior), 200);
  o.windows = 0.0;
  for (const std::uint32_t seed : {11u, 12u, 13u}) {
    const SimulatedMap closed = simulate_map(p.grid, p.rooms, o, seed);
    EXPECT_EQ(closed.windows, 0);
    EXPECT_EQ(cv::countNonZero((closed.map.cells == kFree) & closed.exterior), 0) << "seed " << seed;
  }
}

TEST(SimulatedMap, RoomsLieOnSeenFreeCellsApartAndEverySeenRoomIsKept) {
  const Plan p = plan();
  for (const std::uint32_t seed : {1u, 2u, 3u, 4u}) {
    const SimulatedMap s = simulate_map(p.grid, p.rooms, SimulatedMapOptions{}, seed);
    EXPECT_EQ(cv::countNonZero((s.rooms > 0) & (s.map.cells != kFree)), 0) << "seed " << seed;
    // No two rooms touch, even diagonally: an 8-connected flood fill separates them.
    for (int r = 1; r < s.rooms.rows; ++r)
      for (int c = 1; c + 1 < s.rooms.cols; ++c) {
        const int a = s.rooms.at<int>(r, c);
        for (const int b : {s.rooms.at<int>(r - 1, c - 1), s.rooms.at<int>(r - 1, c), s.rooms.at<int>(r - 1, c + 1), s.rooms.at<int>(r, c - 1)})
          ASSERT_TRUE(a == 0 || b == 0 || a == b) << "seed " << seed << " at " << c << ", " << r;
      }
    // A room the map shows a good part of the floor of is kept, with most of those cells.
    cv::Mat plan_rooms = cv::Mat::zeros(s.rooms.size(), CV_32SC1);
    p.rooms.copyTo(plan_rooms(cv::Rect(s.offset.x, s.offset.y, p.rooms.cols, p.rooms.rows)));
    for (int room = 1; room <= 4; ++room) {
      const int seen = cv::countNonZero((plan_rooms == room) & (s.map.cells == kFree));
      if (seen < 500) continue;
      EXPECT_GT(cv::countNonZero(s.rooms == room), 0.8 * seen) << "seed " << seed << " room " << room;
    }
  }
}

TEST(SimulatedMap, TheRobotStaysInsideAndSeesTheBuilding) {
  const Plan p = plan();
  const SimulatedMap s = simulate_map(p.grid, p.rooms, plain_options(), 5);
  EXPECT_GT(s.scans, 5);
  EXPECT_GT(s.path_length, 2.0);
  EXPECT_EQ(cv::countNonZero(s.drivable & s.exterior), 0);
  EXPECT_EQ(cv::countNonZero(s.drivable & (s.world.cells != kFree)), 0);
  // Exact laser and poses: the map's free cells are free in the world, and most of the floor is seen.
  EXPECT_EQ(cv::countNonZero((s.map.cells == kFree) & (s.world.cells != kFree)), 0);
  const int floor = cv::countNonZero(p.grid.cells == kFree);
  EXPECT_GT(cv::countNonZero(s.map.cells == kFree), 0.9 * floor);
}

TEST(SimulatedMap, FurnitureAndClutterStandOnTheFloorAndLeaveDoorsOpen) {
  const Plan p = plan();
  SimulatedMapOptions o = plain_options();
  o.furniture = 0.2;
  o.clutter = 3.0;
  const SimulatedMap s = simulate_map(p.grid, p.rooms, o, 9);
  cv::Mat floor = cv::Mat::zeros(s.world.cells.size(), CV_8UC1);
  const cv::Mat drawn = p.grid.cells == kFree;
  drawn.copyTo(floor(cv::Rect(s.offset.x, s.offset.y, p.grid.width(), p.grid.height())));
  const int solid_floor = cv::countNonZero(floor & (s.world.cells != kFree));
  EXPECT_GT(solid_floor, 0.05 * cv::countNonZero(floor));
  // Every room is still reached: all three seen through open doors.
  for (int k = 0; k < 3; ++k) EXPECT_GT(cv::countNonZero(s.map.cells(in_map(p, s, k, 2)) == kFree), 1000) << "room " << k + 1;
}

TEST(SimulatedMap, WallsChangeByTheDrawnCells) {
  const Plan p = plan();
  SimulatedMapOptions o = plain_options();
  o.wall_change = 1;
  std::set<int> changes;
  for (std::uint32_t seed = 1; seed <= 12 && changes.size() < 3; ++seed) {
    const SimulatedMap s = simulate_map(p.grid, p.rooms, o, seed);
    changes.insert(s.wall_change);
    const cv::Rect box(s.offset.x, s.offset.y, p.grid.width(), p.grid.height());
    const int floor = cv::countNonZero((s.world.cells(box) == kFree) & ~s.exterior(box));
    const int drawn = cv::countNonZero(p.grid.cells == kFree);
    if (s.wall_change > 0) {
      EXPECT_LT(floor, drawn);
    } else if (s.wall_change < 0) {
      EXPECT_GT(floor, drawn);
    } else {
      EXPECT_EQ(floor, drawn);
    }
  }
  EXPECT_EQ(changes, (std::set<int>{-1, 0, 1}));
}

TEST(SimulatedMap, RejectsBadInput) {
  const Plan p = plan();
  EXPECT_THROW(simulate_map(p.grid, p.rooms(cv::Rect(0, 0, 100, 100)).clone(), {}, 1), Error);
  cv::Mat small;
  p.rooms.convertTo(small, CV_16U);
  EXPECT_THROW(simulate_map(p.grid, small, {}, 1), Error);
  EXPECT_THROW(simulate_map(p.grid, cv::Mat::zeros(p.rooms.size(), CV_32SC1), {}, 1), Error);  // no room
  cv::Mat negative = p.rooms.clone();
  negative.at<int>(0, 0) = -2;
  EXPECT_THROW(simulate_map(p.grid, negative, {}, 1), Error);
  const auto bad = [&](auto change) {
    SimulatedMapOptions o;
    change(o);
    EXPECT_THROW(validate(o), Error);
    EXPECT_THROW(simulate_map(p.grid, p.rooms, o, 1), Error);
  };
  bad([](SimulatedMapOptions& o) { o.range_to = 5.0; });  // below range_from
  bad([](SimulatedMapOptions& o) { o.range_from = 0.0; });
  bad([](SimulatedMapOptions& o) { o.angular_step_from = 0.0; });
  bad([](SimulatedMapOptions& o) { o.windows = 1.5; });
  bad([](SimulatedMapOptions& o) { o.closed_doors = -0.1; });
  bad([](SimulatedMapOptions& o) { o.furniture = 0.95; });
  bad([](SimulatedMapOptions& o) { o.wall_change = 9; });
  bad([](SimulatedMapOptions& o) { o.occupied_ratio = 0.0; });
  bad([](SimulatedMapOptions& o) { o.range_noise = std::nan(""); });
  bad([](SimulatedMapOptions& o) { o.max_scans = 0; });
}

TEST(SimulatedMap, OptionRowsSetWhatTheyName) {
  SimulatedMapOptions o;
  const auto* step = find_option(simulated_map_option_rows(), std::string("angular-step-to"));
  ASSERT_NE(step, nullptr);
  EXPECT_NEAR(step->get(o), 1.0, 1e-12);  // degrees
  set_option(*step, o, 0.5, "--angular-step-to");
  EXPECT_NEAR(o.angular_step_to, 0.5 * std::numbers::pi / 180.0, 1e-15);
  const auto* change = find_option(simulated_map_option_rows(), std::string("wall-change"));
  ASSERT_NE(change, nullptr);
  EXPECT_THROW(set_option(*change, o, 1.5, "--wall-change"), Error);
  EXPECT_THROW(set_option(*change, o, -1.0, "--wall-change"), Error);
  set_option(*change, o, 2.0, "--wall-change");
  EXPECT_EQ(o.wall_change, 2);
}

TEST(SimulatedMap, ImagesUseThePlanPalette) {
  const Plan p = plan();
  const SimulatedMap s = simulate_map(p.grid, p.rooms, SimulatedMapOptions{}, 2);
  const cv::Mat map = map_image(s), truth = rooms_image(s);
  EXPECT_EQ(cv::countNonZero(map == 255), cv::countNonZero(s.map.cells == kFree));
  EXPECT_EQ(cv::countNonZero(map == 0), cv::countNonZero(s.map.cells == kOccupied));
  EXPECT_EQ(cv::countNonZero(map == 205), cv::countNonZero(s.map.cells == kUnknown));
  EXPECT_EQ(cv::countNonZero(truth == 255), cv::countNonZero(s.rooms > 0));
  EXPECT_EQ(cv::countNonZero(truth), cv::countNonZero(truth == 255));
}

}  // namespace
}  // namespace topocut
