#include "topocut/walls/walls_json.h"
#include "topocut/walls/walls_pipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "walls/simulated_run.h"

namespace topocut {
namespace {

using test::simulated_run;

// Two rooms, 10 m by 6 m overall, split at x = 5 by a wall with a 1 m door (y from 2.5 to 3.5).
std::vector<Segment2> floor_plan() {
  return {{{0, 0}, {10, 0}}, {{10, 0}, {10, 6}}, {{10, 6}, {0, 6}}, {{0, 6}, {0, 0}},
          {{5, 0}, {5, 2.5}}, {{5, 3.5}, {5, 6}}};
}


const std::vector<Pose2> kPoses{{2.5, 3.0, 0.0}, {7.5, 3.0, M_PI}, {1.5, 1.5, 0.4}, {8.0, 4.5, -2.0},
                                {3.5, 5.0, 1.0}, {6.5, 1.0, 2.5}};

// Distance from p to the nearest wall of the plan.
double distance_to_plan(const Point2& p, const std::vector<Segment2>& plan) {
  double best = INFINITY;
  for (const Segment2& s : plan) best = std::min(best, distance_to_segment(p, s));
  return best;
}

TEST(WallsPipeline, WallsFromSimulatedScansMatchTheFloorPlan) {
  const auto plan = floor_plan();
  const auto scans = simulated_run(plan, kPoses);
  const WallsResult result = walls_from_scans(scans);
  ASSERT_FALSE(result.walls.empty());
  // Every merged wall lies on the plan: its end points and midpoint within 5 cm of a true wall.
  for (const Wall& w : result.walls) {
    const Point2 mid{0.5 * (w.segment.a.x + w.segment.b.x), 0.5 * (w.segment.a.y + w.segment.b.y)};
    EXPECT_LT(distance_to_plan(w.segment.a, plan), 0.05);
    EXPECT_LT(distance_to_plan(w.segment.b, plan), 0.05);
    EXPECT_LT(distance_to_plan(mid, plan), 0.05);
  }
  // Every true wall is covered: points every 5 cm along it (but 15 cm from its ends, where corners
  // round off) lie within 5 cm of a merged wall.
  for (const Segment2& truth : plan) {
    const double length = distance(truth.a, truth.b);
    int covered = 0, total = 0;
    for (double t = 0.15; t <= length - 0.15; t += 0.05) {
      const Point2 p{truth.a.x + t * (truth.b.x - truth.a.x) / length, truth.a.y + t * (truth.b.y - truth.a.y) / length};
      double best = INFINITY;
      for (const Wall& w : result.walls) best = std::min(best, distance_to_segment(p, w.segment));
      covered += best < 0.05;
      ++total;
    }
    EXPECT_GE(covered, total * 95 / 100) << "wall (" << truth.a.x << "," << truth.a.y << ")-(" << truth.b.x << ","
                                         << truth.b.y << ")";
  }
  // One merged wall per true wall, each seen from several poses.
  int long_walls = 0;
  for (const Wall& w : result.walls) long_walls += distance(w.segment.a, w.segment.b) > 1.0;
  EXPECT_EQ(long_walls, 6);
  EXPECT_GT(result.segments.size(), result.walls.size());
}

TEST(WallsPipeline, GridHasWallsFreeRoomsAndUnknownOutside) {
  const auto plan = floor_plan();
  const WallsResult result = walls_from_scans(simulated_run(plan, kPoses));
  const OccupancyGrid& g = result.grid;
  EXPECT_DOUBLE_EQ(g.resolution, 0.05);
  auto at = [&](double x, double y) {
    const cv::Point c = world_to_cell(g, {x, y});
    return g.cells.at<unsigned char>(c.y, c.x);
  };
  EXPECT_EQ(at(2.5, 3.0), kFree);   // pose of the first scan
  EXPECT_EQ(at(7.0, 2.0), kFree);   // middle of the right room
  EXPECT_EQ(at(5.0, 3.0), kFree);   // the door
  EXPECT_EQ(at(5.0, 1.0), kOccupied);
  EXPECT_EQ(at(0.0, 3.0), kOccupied);
  EXPECT_EQ(at(10.0, 5.0), kOccupied);
  // Outside the building nothing was seen.
  EXPECT_EQ(at(-0.5, 3.0), kUnknown);
  EXPECT_EQ(at(5.0, 6.6), kUnknown);
  // The grid holds everything plus the margin of 1 m.
  EXPECT_LE(g.origin.x, -1.0 + 1e-9);
  EXPECT_LE(g.origin.y, -1.0 + 1e-9);
  EXPECT_GE(g.origin.x + g.width() * g.resolution, 11.0 - 1e-9);
}

TEST(WallsPipeline, NoFreePathCrossesAWall) {
  // A closed room: flood filling the free cells from the pose never leaves the room's walls.
  const std::vector<Segment2> box{{{0, 0}, {4, 0}}, {{4, 0}, {4, 3}}, {{4, 3}, {0, 3}}, {{0, 3}, {0, 0}}};
  const WallsResult result = walls_from_scans(simulated_run(box, {{2, 1.5, 0.3}, {1, 1, 2.0}}));
  cv::Mat free = result.grid.cells == kFree;
  const cv::Point seed = world_to_cell(result.grid, {2, 1.5});
  cv::Mat mask = cv::Mat::zeros(free.rows + 2, free.cols + 2, CV_8UC1);
  cv::floodFill(free, mask, seed, cv::Scalar(100), nullptr, cv::Scalar(), cv::Scalar(), 8);
  for (int r = 0; r < free.rows; ++r) {
    for (int c = 0; c < free.cols; ++c) {
      if (free.at<unsigned char>(r, c) != 100) continue;
      const Point2 p = cell_center_world(result.grid, c, r);
      ASSERT_TRUE(p.x > -0.05 && p.x < 4.05 && p.y > -0.05 && p.y < 3.05) << p.x << "," << p.y;
    }
  }
}

TEST(WallsPipeline, WallPolygonIsACounterClockwiseCappedRectangle) {
  const Ring r = wall_polygon({{0, 0}, {4, 0}}, 0.2);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_NEAR(signed_area(r), 4.2 * 0.2, 1e-12);
  EXPECT_NEAR(r[0].x, -0.1, 1e-12);
  EXPECT_NEAR(r[0].y, -0.1, 1e-12);
  EXPECT_NEAR(r[2].x, 4.1, 1e-12);
  EXPECT_NEAR(r[2].y, 0.1, 1e-12);
  const Ring diagonal = wall_polygon({{1, 1}, {4, 5}}, 0.1);
  EXPECT_NEAR(signed_area(diagonal), 5.1 * 0.1, 1e-12);
}

TEST(WallsPipeline, BadInputIsRefused) {
  EXPECT_THROW(walls_from_scans(std::vector<PosedScan>{}), Error);
  auto scans = simulated_run(floor_plan(), {{2.5, 3.0, 0.0}});
  WallsOptions options;
  options.map.resolution = 0.0;
  EXPECT_THROW(walls_from_scans(scans, options), Error);
  // A pose far away makes the grid absurdly large: a clear error, not an allocation failure.
  auto far = scans;
  far.push_back(far.front());
  far.back().pose.x = 1e7;
  EXPECT_THROW(walls_from_scans(far), Error);
  auto nan = scans;
  nan.front().pose.theta = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(walls_from_scans(nan), Error);
}

// The grid's options are checked through their rows (wall_map_option_rows()), naming the option.
TEST(WallsPipeline, EveryGridOptionOutOfRangeIsRefusedByName) {
  for (const OptionRow<WallMapOptions>& row : wall_map_option_rows()) {
    WallMapOptions options;
    EXPECT_NO_THROW(validate(options));
    row.set(options, -1.0);
    try {
      validate(options);
      ADD_FAILURE() << row.name << " = -1 passes";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--" + row.name + " must ", 0), 0u) << e.what();
    }
  }
}

TEST(WallsPipeline, PosedScansFromACarmenLog) {
  const CarmenLog log = parse_carmen_log(
      "FLASER 3 1.5 50 nan 1 2 0.5 0 0 0 1 h 1\n"
      "FLASER 3 50 50 50 3 4 0 0 0 0 2 h 2\n"
      "FLASER 3 2 2 2 5 6 0 0 0 0 3 h 3\n",
      "x");
  ASSERT_DOUBLE_EQ(log.max_range, 49.9);
  const auto scans = posed_scans(log);
  ASSERT_EQ(scans.size(), 3u);
  EXPECT_EQ(scans[0].pose, (Pose2{1, 2, 0.5}));
  EXPECT_DOUBLE_EQ(scans[0].scan.angles[0], -M_PI / 2);
  EXPECT_DOUBLE_EQ(scans[0].scan.angles[2], M_PI / 2);
  EXPECT_TRUE(scans[0].scan.is_valid(0));
  EXPECT_EQ(scans[0].scan.ranges[1], std::numeric_limits<double>::infinity());  // no return
  EXPECT_FALSE(scans[0].scan.is_valid(1));
  EXPECT_FALSE(scans[0].scan.is_valid(2));
}

TEST(WallsPipeline, JsonListsTheWalls) {
  const auto scans = simulated_run(floor_plan(), kPoses);
  const WallsResult result = walls_from_scans(scans);
  const auto json = nlohmann::json::parse(walls_to_json(result, scans.size(), 0.1));
  EXPECT_EQ(json["scans"], scans.size());
  EXPECT_EQ(json["segments"], result.segments.size());
  ASSERT_EQ(json["walls"].size(), result.walls.size());
  const auto& w = json["walls"][0];
  EXPECT_NEAR(w["start"][0].get<double>(), result.walls[0].segment.a.x, 1e-6);
  EXPECT_EQ(w["polygon"].size(), 4u);
}

}  // namespace
}  // namespace topocut
