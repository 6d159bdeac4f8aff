// `topocut label` and `topocut walls` as a user runs them: the built binary, its exit codes, its
// output and the files it writes.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <zlib.h>

#include "topocut/io/map_loader.h"
#include "topocut/scan/laser_simulator.h"

#include "cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace topocut;

using topocut::testing::CliResult;
using topocut::testing::file_text;
using topocut::testing::run_cli_line;

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// Two rooms (5 m by 6 m each) joined by a 1 m door, seen by a 180° SICK-like laser (180 beams,
// 80 m saturation written as 81.83) from a few poses: a CARMEN log with ODOM noise around it.
std::string simulated_log() {
  const std::vector<Segment2> plan{{{0, 0}, {10, 0}}, {{10, 0}, {10, 6}}, {{10, 6}, {0, 6}}, {{0, 6}, {0, 0}},
                                   {{5, 0}, {5, 4.5}}, {{5, 5.5}, {5, 6}}};
  LaserSpec spec;
  spec.field_of_view = std::numbers::pi;
  spec.angular_resolution = std::numbers::pi / 179.0;
  spec.range_max = 80.0;
  spec.noise_stddev = 0.01;
  std::mt19937 rng(3);
  std::ostringstream log;
  log << "# message formats defined: PARAM SYNC ODOM FLASER\nPARAM robot_use_laser on nohost 0\n";
  const std::vector<Pose2> poses{{2.5, 3, 0}, {2.5, 3, std::numbers::pi}, {2.5, 3, 1.6}, {2.5, 3, -1.6},
                                 {7.5, 3, 0}, {7.5, 3, std::numbers::pi}, {7.5, 3, 1.6}, {7.5, 3, -1.6}};
  double time = 0;
  for (const Pose2& p : poses) {
    const SimulatedScan s = simulate_scan(plan, p, spec, rng);
    log << "ODOM " << p.x << " " << p.y << " " << p.theta << " 0 0 0 " << time << " host " << time << "\n";
    log << "FLASER " << s.scan.size();
    for (double r : s.scan.ranges) log << " " << (std::isfinite(r) ? r : 81.83);
    log << " " << p.x << " " << p.y << " " << p.theta << " " << p.x << " " << p.y << " " << p.theta << " " << time
        << " host " << time << "\n";
    time += 0.5;
  }
  return log.str();
}

class WallsCli : public ::testing::Test {
 protected:

  CliResult run(const std::string& args) const { return run_cli_line(dir_, args); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  topocut::testing::TempDir temp_;
  const fs::path dir_ = temp_.path();
};

TEST_F(WallsCli, LabelPrintsSegmentsAndCentres) {
  // Two walls: beams 0-3 at 1 m, beam 4 invalid, beams 5-8 at 3 m.
  std::string csv = "angle,range\n";
  for (int i = 0; i < 9; ++i) csv += std::to_string(-0.04 + 0.01 * i) + "," + (i < 4 ? "1" : i == 4 ? "nan" : "3") + "\n";
  write_text(path("scan.csv"), csv);
  const CliResult o = run("label '" + path("scan.csv") + "' --fcm 2");
  ASSERT_EQ(o.code, 0) << o.err;
  const auto json = nlohmann::json::parse(o.out);
  ASSERT_EQ(json["segments"].size(), 2u);
  EXPECT_EQ(json["segments"][0]["beams"], nlohmann::json({0, 1, 2, 3}));
  EXPECT_EQ(json["segments"][1]["beams"], nlohmann::json({5, 6, 7, 8}));
  EXPECT_EQ(json["invalid_beams"], nlohmann::json({4}));
  ASSERT_EQ(json["segments"][1]["centres"].size(), 2u);
  // Centres lie on the 3 m arc, ordered along it (first centre at the lower angle).
  const auto& c = json["segments"][1]["centres"];
  EXPECT_NEAR(std::hypot(c[0][0].get<double>(), c[0][1].get<double>()), 3.0, 0.01);
  EXPECT_LT(c[0][1].get<double>(), c[1][1].get<double>());
}

TEST_F(WallsCli, LabelRefusesBadInput) {
  const CliResult missing = run("label '" + path("nope.csv") + "'");
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("topocut label: error:"), std::string::npos) << missing.err;
  write_text(path("scan.csv"), "angle,range\n0,1\n");
  const CliResult element = run("label '" + path("scan.csv") + "' --element star");
  EXPECT_EQ(element.code, 2);
  EXPECT_NE(element.err.find("cross"), std::string::npos);
  // The labeling rows' ranges refuse a bad value where options enter: a usage error naming the flag.
  const CliResult cell = run("label '" + path("scan.csv") + "' --cell -1");
  EXPECT_EQ(cell.code, 2);
  EXPECT_NE(cell.err.find("--cell must lie in"), std::string::npos) << cell.err;
  const CliResult connectivity = run("label '" + path("scan.csv") + "' --connectivity 6");
  EXPECT_EQ(connectivity.code, 2);
  EXPECT_NE(connectivity.err.find("--connectivity must be 4 or 8, got 6"), std::string::npos) << connectivity.err;
  const CliResult dilate = run("label '" + path("scan.csv") + "' --dilate 1.5");
  EXPECT_EQ(dilate.code, 2);
  EXPECT_NE(dilate.err.find("--dilate must be a whole number >= 0"), std::string::npos) << dilate.err;
}

TEST_F(WallsCli, WallsRefusesBadOptionsBeforeReadingTheLog) {
  // The same rows as `label`: checked before the (here missing) log is opened.
  for (const std::string bad : {"--dilate -1", "--cell 0", "--connectivity 3", "--max-range -2", "--thickness -0.1"}) {
    const CliResult r = run("walls '" + path("missing.log") + "' " + bad);
    EXPECT_EQ(r.code, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find(bad.substr(0, bad.find(' '))), std::string::npos) << bad << ": " << r.err;
    EXPECT_EQ(r.err.find("missing.log"), std::string::npos) << bad << ": " << r.err;
  }
}

TEST_F(WallsCli, WallsWritesMapWallsAndRooms) {
  write_text(path("run.log"), simulated_log());
  const CliResult o = run("walls '" + path("run.log") + "' --out-map '" + path("map.yaml") + "' --out-walls '" +
                        path("walls.json") + "' --segment --out-color '" + path("rooms.png") + "' --out-rooms '" +
                        path("rooms.json") + "'");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("8 scans"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("rooms:"), std::string::npos) << o.out;
  // The map reads back: the wall between the rooms is occupied, the room centres free.
  const OccupancyGrid map = load_map(path("map.yaml"));
  EXPECT_DOUBLE_EQ(map.resolution, 0.05);
  auto at = [&](double x, double y) {
    const cv::Point c = world_to_cell(map, {x, y});
    return map.cells.at<unsigned char>(c.y, c.x);
  };
  EXPECT_EQ(at(2.5, 3.0), kFree);
  EXPECT_EQ(at(7.5, 1.0), kFree);
  EXPECT_EQ(at(5.0, 2.0), kOccupied);
  EXPECT_EQ(at(-0.6, 3.0), kUnknown);
  // The walls: the plan's six, each as a polygon.
  const auto walls = nlohmann::json::parse(file_text(path("walls.json")));
  EXPECT_EQ(walls["scans"], 8);
  int long_walls = 0;
  for (const auto& w : walls["walls"]) long_walls += w["length"].get<double>() > 0.3;
  EXPECT_EQ(long_walls, 6);
  const auto rooms = nlohmann::json::parse(file_text(path("rooms.json")));
  EXPECT_GE(rooms["rooms"].size(), 1u);
  EXPECT_TRUE(fs::exists(path("rooms.png")));
  EXPECT_TRUE(fs::exists(path("map.pgm")));
}

TEST_F(WallsCli, WallsReadsGzipLogsAlike) {
  const std::string text = simulated_log();
  write_text(path("run.log"), text);
  gzFile gz = gzopen(path("run.log.gz").c_str(), "wb");
  ASSERT_NE(gz, nullptr);
  gzwrite(gz, text.data(), static_cast<unsigned>(text.size()));
  gzclose(gz);
  const CliResult plain = run("walls '" + path("run.log") + "' --out-walls '" + path("a.json") + "'");
  const CliResult packed = run("walls '" + path("run.log.gz") + "' --out-walls '" + path("b.json") + "'");
  ASSERT_EQ(plain.code, 0) << plain.err;
  ASSERT_EQ(packed.code, 0) << packed.err;
  EXPECT_EQ(file_text(path("a.json")), file_text(path("b.json")));
}

TEST_F(WallsCli, WallsRefusesBadLogs) {
  const CliResult missing = run("walls '" + path("nope.log") + "'");
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("no such file"), std::string::npos) << missing.err;

  write_text(path("empty.log"), "");
  const CliResult empty = run("walls '" + path("empty.log") + "'");
  EXPECT_EQ(empty.code, 1);
  EXPECT_NE(empty.err.find("no usable FLASER"), std::string::npos) << empty.err;

  write_text(path("odom.log"), "ODOM 1 2 3 0 0 0 1 h 1\nODOM 1 2 3 0 0 0 2 h 2\n");
  const CliResult odom = run("walls '" + path("odom.log") + "'");
  EXPECT_EQ(odom.code, 1);
  EXPECT_NE(odom.err.find("ODOM x2"), std::string::npos) << odom.err;

  write_text(path("bad.log"), "ODOM 1 2 3\nODOM 1 2 3\nFLASER 3 1 2 oops 0 0 0 0 0 0 1 h 1\n");
  const CliResult bad = run("walls '" + path("bad.log") + "'");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("bad.log:3:"), std::string::npos) << bad.err;

  // Only non-finite poses: a warning, then the error that nothing is left.
  write_text(path("nan.log"), "FLASER 3 1 2 3 nan 0 0 0 0 0 1 h 1\n");
  const CliResult nan = run("walls '" + path("nan.log") + "'");
  EXPECT_EQ(nan.code, 1);
  EXPECT_NE(nan.err.find("non-finite pose"), std::string::npos) << nan.err;

  const CliResult method = run("walls '" + path("bad.log") + "' --method magic");
  EXPECT_EQ(method.code, 2);

  // An output that cannot be written is refused before any work.
  write_text(path("run.log"), simulated_log());
  const CliResult unwritable = run("walls '" + path("run.log") + "' --out-map '" + path("no/such/dir/map.yaml") + "'");
  EXPECT_EQ(unwritable.code, 1);
  EXPECT_EQ(unwritable.out, "");
}

}  // namespace

namespace {

TEST_F(WallsCli, IncrementalReplaysTheLogAndWritesFrames) {
  write_text(path("run.log"), simulated_log());
  const CliResult o = run("walls '" + path("run.log") + "' --incremental --compare-batch --frames '" + path("frames") +
                        "' --frame-every 3 --out-rooms '" + path("rooms.json") + "'");
  ASSERT_EQ(o.code, 0) << o.err;
  for (const char* line : {"8 scans", "updates: ", "incremental per update: median", "batch per update:",
                           "speed-up on the same updates", "stability: churn median", "ids used", "final rooms: incremental",
                           "batch stability (ids carried by overlap): churn median", "against batch: churn p95"})
    EXPECT_NE(o.out.find(line), std::string::npos) << line << "\n" << o.out;
  // Updates 1, 4, 7 and the last one (the last scan changes the map: it looks at a new wall).
  const std::size_t updates = std::stoul(o.out.substr(o.out.find("updates: ") + 9));
  ASSERT_GE(updates, 2u);
  ASSERT_LE(updates, 8u);
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(path("frames"))) frames += entry.path().extension() == ".png";
  EXPECT_EQ(frames, static_cast<int>((updates - 1) / 3 + 1 + ((updates - 1) % 3 != 0 ? 1 : 0)));
  EXPECT_TRUE(fs::exists(path("frames/frame_00001.png")));
  EXPECT_GE(nlohmann::json::parse(file_text(path("rooms.json")))["rooms"].size(), 1u);
}

TEST_F(WallsCli, IncrementalOptionsNeedIncremental) {
  write_text(path("run.log"), simulated_log());
  const CliResult frames = run("walls '" + path("run.log") + "' --frames '" + path("frames") + "'");
  EXPECT_EQ(frames.code, 2);
  EXPECT_NE(frames.err.find("need --incremental"), std::string::npos) << frames.err;
  const CliResult walls = run("walls '" + path("run.log") + "' --incremental --out-walls '" + path("w.json") + "'");
  EXPECT_EQ(walls.code, 2);
  EXPECT_FALSE(fs::exists(path("w.json")));
  const CliResult every = run("walls '" + path("run.log") + "' --incremental --batch-every 0");
  EXPECT_EQ(every.code, 2);
}

}  // namespace
