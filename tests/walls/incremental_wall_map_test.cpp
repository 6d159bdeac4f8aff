// The wall map built scan by scan equals build_wall_map() of the scans so far, with every segment as
// a wall, and reports exactly the cells each scan changed.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <span>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/scan/laser_simulator.h"
#include "topocut/walls/wall_extraction.h"
#include "topocut/walls/wall_map.h"
#include "topocut/walls/wall_map_replay.h"

namespace topocut {
namespace {

// Two rooms, 10 m by 6 m, joined by a 1 m door in the wall at x = 5; the robot walks through.
std::vector<PosedScan> walk() {
  const std::vector<Segment2> plan{{{0, 0}, {10, 0}}, {{10, 0}, {10, 6}}, {{10, 6}, {0, 6}},
                                   {{0, 6}, {0, 0}}, {{5, 0}, {5, 2.5}},  {{5, 3.5}, {5, 6}}};
  LaserSpec spec;
  spec.field_of_view = M_PI;
  spec.angular_resolution = M_PI / 180.0;
  spec.range_max = 8.0;
  spec.noise_stddev = 0.01;
  std::mt19937 rng(3);
  std::vector<PosedScan> scans;
  for (const Pose2 pose : {Pose2{1.5, 3.0, 0.0}, Pose2{2.5, 3.0, 0.3}, Pose2{2.5, 3.0, 0.3}, Pose2{5.0, 3.0, 0.0},
                           Pose2{7.5, 3.0, -1.0}, Pose2{8.0, 4.0, 2.0}}) {
    PosedScan s;
    s.scan = simulate_scan(plan, pose, spec, rng).scan;
    s.pose = pose;
    scans.push_back(s);
  }
  return scans;
}

std::vector<Wall> as_walls(const std::vector<WallSegment>& segments) {
  std::vector<Wall> walls;
  for (const WallSegment& s : segments) walls.push_back({s.segment, 0.0, 1, {}});
  return walls;
}

// Every scan's wall segments (default options), per scan and all together.
void extract_segments(const std::vector<PosedScan>& scans, std::vector<std::vector<WallSegment>>& per_scan,
                      std::vector<WallSegment>& all) {
  for (std::size_t i = 0; i < scans.size(); ++i) {
    per_scan.push_back(extract_wall_segments(scans[i].scan, scans[i].pose, {}, static_cast<int>(i)));
    all.insert(all.end(), per_scan.back().begin(), per_scan.back().end());
  }
}

TEST(IncrementalWallMap, EveryPrefixEqualsTheBatchMapOfThatPrefix) {
  const std::vector<PosedScan> scans = walk();
  std::vector<std::vector<WallSegment>> per_scan;
  std::vector<WallSegment> all;
  extract_segments(scans, per_scan, all);
  IncrementalWallMap map(scans, all);
  const OccupancyGrid full = build_wall_map(scans, as_walls(all));
  ASSERT_EQ(map.grid().cells.size(), full.cells.size());
  EXPECT_EQ(map.grid().origin.x, full.origin.x);
  EXPECT_EQ(cv::countNonZero(map.grid().cells != kUnknown), 0);

  std::vector<WallSegment> so_far;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const cv::Mat before = map.grid().cells.clone();
    const cv::Rect changed = map.add(scans[i], per_scan[i]);
    so_far.insert(so_far.end(), per_scan[i].begin(), per_scan[i].end());
    // The batch map of the prefix, in the full frame: two scans without beams at the frame's
    // corners (less the margin) make build_wall_map() choose the same frame and draw nothing.
    const WallMapOptions defaults;
    std::vector<PosedScan> prefix(scans.begin(), scans.begin() + static_cast<long>(i) + 1);
    const double min_x = full.origin.x + defaults.margin, min_y = full.origin.y + defaults.margin;
    prefix.push_back({{}, {min_x, min_y, 0.0}});
    prefix.push_back({{}, {min_x + (full.width() - 1.5) * full.resolution - 2.0 * defaults.margin,
                           min_y + (full.height() - 1.5) * full.resolution - 2.0 * defaults.margin, 0.0}});
    const OccupancyGrid batch = build_wall_map(prefix, as_walls(so_far));
    ASSERT_EQ(batch.cells.size(), full.cells.size());
    EXPECT_EQ(cv::countNonZero(map.grid().cells != batch.cells), 0) << "scan " << i;
    // The reported rectangle holds every changed cell, and is empty when nothing changed.
    const cv::Mat differs = before != map.grid().cells;
    EXPECT_EQ(cv::boundingRect(differs), changed) << "scan " << i;
  }
  // After the last scan the frames coincide and the grids are equal cell for cell.
  EXPECT_EQ(cv::countNonZero(map.grid().cells != full.cells), 0);
}

TEST(WallMapReplay, StepsThroughTheLogAsIncrementalWallMapDoes) {
  const std::vector<PosedScan> scans = walk();
  std::vector<std::vector<WallSegment>> per_scan;
  std::vector<WallSegment> all;
  extract_segments(scans, per_scan, all);
  IncrementalWallMap map(scans, all);
  WallMapReplay replay(scans);
  for (std::size_t i = 0; i < scans.size(); ++i) {
    ASSERT_TRUE(replay.next());
    EXPECT_EQ(replay.scans_added(), static_cast<int>(i) + 1);
    EXPECT_EQ(replay.changed(), map.add(scans[i], per_scan[i])) << "scan " << i;
    EXPECT_EQ(cv::countNonZero(replay.known_map().cells != map.grid().cells), 0) << "scan " << i;
    EXPECT_EQ(replay.pose().x, scans[i].pose.x);
  }
  // After the last scan there is no next one, and nothing changes any more.
  const cv::Mat last = replay.known_map().cells.clone();
  EXPECT_FALSE(replay.next());
  EXPECT_EQ(replay.scans_added(), static_cast<int>(scans.size()));
  EXPECT_EQ(cv::countNonZero(replay.known_map().cells != last), 0);
  EXPECT_THROW(WallMapReplay(std::vector<PosedScan>{}), Error);
}

TEST(IncrementalWallMap, RepeatedScanChangesNothing) {
  const std::vector<PosedScan> scans = walk();
  const auto segments = extract_wall_segments(scans[0].scan, scans[0].pose);
  IncrementalWallMap map(std::span<const PosedScan>(scans).first(1), segments);
  EXPECT_FALSE(map.add(scans[0], segments).empty());
  EXPECT_TRUE(map.add(scans[0], segments).empty());
}

// One beam from the origin along +x, hitting at 4 m, and a wall segment across it at x = 2 m.
PosedScan one_beam_through_wall() {
  PosedScan scan;
  scan.pose = {0.0, 0.0, 0.0};
  scan.scan.angles = {0.0};
  scan.scan.ranges = {4.0};
  return scan;
}
const WallSegment kWallAt2m{{{2.0, -1.0}, {2.0, 1.0}}, 0, 2};

TEST(IncrementalWallMap, WallsWinOverLaterRays) {
  // A wall segment seen first stays occupied when a later scan's ray crosses it.
  const PosedScan scan = one_beam_through_wall();
  const std::vector<WallSegment> wall{kWallAt2m};
  IncrementalWallMap map(std::span(&scan, 1), wall);
  map.add(scan, {});
  const OccupancyGrid& g = map.grid();
  const int row = g.height() - 1 - static_cast<int>(std::floor((0.0 - g.origin.y) / g.resolution));
  const int wall_column = static_cast<int>(std::floor((2.0 - g.origin.x) / g.resolution));
  EXPECT_EQ(g.cells.at<std::uint8_t>(row, wall_column), kFree);
  map.add(PosedScan{{}, scan.pose}, wall);
  EXPECT_EQ(g.cells.at<std::uint8_t>(row, wall_column), kOccupied);
  map.add(scan, {});
  EXPECT_EQ(g.cells.at<std::uint8_t>(row, wall_column), kOccupied);
}

TEST(IncrementalWallMap, WithEvidenceRepeatedScansSettleAndTheReplayFollows) {
  // The same scan again adds evidence to cells already published: nothing flips. The replay with
  // evidence steps as the map with evidence does, and its cells are free, occupied or unknown.
  const std::vector<PosedScan> scans = walk();
  std::vector<std::vector<WallSegment>> per_scan;
  std::vector<WallSegment> all;
  extract_segments(scans, per_scan, all);
  IncrementalWallMap map(scans, all, {}, OccupancyEvidenceOptions{});
  EXPECT_FALSE(map.add(scans[0], per_scan[0]).empty());
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(map.add(scans[0], per_scan[0]).empty()) << "repeat " << i;
  IncrementalWallMap fresh(scans, all, {}, OccupancyEvidenceOptions{});
  WallMapReplay replay(scans, {}, OccupancyEvidenceOptions{});
  for (std::size_t i = 0; i < scans.size(); ++i) {
    ASSERT_TRUE(replay.next());
    EXPECT_EQ(replay.changed(), fresh.add(scans[i], per_scan[i])) << "scan " << i;
    EXPECT_EQ(cv::countNonZero(replay.known_map().cells != fresh.grid().cells), 0) << "scan " << i;
  }
  const cv::Mat& cells = replay.known_map().cells;
  EXPECT_EQ(cv::countNonZero((cells != kFree) & (cells != kOccupied) & (cells != kUnknown)), 0);
  EXPECT_GT(cv::countNonZero(cells == kFree), 0);
  EXPECT_GT(cv::countNonZero(cells == kOccupied), 0);
}

TEST(IncrementalWallMap, WithEvidenceAWallSeenOnceFadesUnderLaterRays) {
  // Unlike the map drawn as it is (WallsWinOverLaterRays), evidence lets rays clear a wall seen
  // once, after enough of them: a person who stood there and walked away.
  const PosedScan scan = one_beam_through_wall();
  const std::vector<WallSegment> wall{kWallAt2m};
  IncrementalWallMap map(std::span(&scan, 1), wall, {}, OccupancyEvidenceOptions{});
  map.add(PosedScan{{}, scan.pose}, wall);
  const OccupancyGrid& g = map.grid();
  const int row = g.height() - 1 - static_cast<int>(std::floor((0.0 - g.origin.y) / g.resolution));
  const int wall_column = static_cast<int>(std::floor((2.0 - g.origin.x) / g.resolution));
  EXPECT_EQ(g.cells.at<std::uint8_t>(row, wall_column), kOccupied);
  map.add(scan, {});
  EXPECT_EQ(g.cells.at<std::uint8_t>(row, wall_column), kOccupied);  // one miss is not enough
  for (int i = 0; i < 5; ++i) map.add(scan, {});
  EXPECT_EQ(g.cells.at<std::uint8_t>(row, wall_column), kFree);
}

TEST(IncrementalWallMap, BadOptionsAreRefused) {
  const std::vector<PosedScan> scans = walk();
  WallMapOptions options;
  options.resolution = 0.0;
  EXPECT_THROW(IncrementalWallMap(scans, {}, options), Error);
  OccupancyEvidenceOptions evidence;
  evidence.hit_probability = 0.3;
  EXPECT_THROW(IncrementalWallMap(scans, {}, {}, evidence), Error);
}

}  // namespace
}  // namespace topocut
