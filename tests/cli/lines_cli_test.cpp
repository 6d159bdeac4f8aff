// `topocut lines` as a user runs it: the built binary, its exit codes, its output and its files.
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

#include "topocut/lines/line_fit.h"
#include "topocut/scan/laser_simulator.h"
#include "topocut/scan/scan_csv.h"

#include "cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace topocut;
constexpr double kPi = std::numbers::pi;

using topocut::testing::CliResult;
using topocut::testing::file_text;
using topocut::testing::run_cli_line;

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// A 4-wall room (6 m x 4 m) seen by a 270 degree laser from near one corner, facing the room.
const std::vector<Segment2> kRoom{{{0, 0}, {6, 0}}, {{6, 0}, {6, 4}}, {{6, 4}, {0, 4}}, {{0, 4}, {0, 0}}};
const Pose2 kPose{1.0, 1.0, 0.6};

std::string room_csv() {
  LaserSpec spec;
  spec.field_of_view = 1.5 * kPi;
  spec.angular_resolution = kPi / 360.0;
  spec.range_max = 20.0;
  return format_scan_csv(simulate_scan(kRoom, kPose, spec).scan);
}

class LinesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    write_text(dir_ / "room.csv", room_csv());
  }

  CliResult run(const std::string& args) const { return run_cli_line(dir_, args); }
  std::string path(const std::string& name) const { return topocut::testing::shell_quoted((dir_ / name).string()); }

  topocut::testing::TempDir temp_;
  const fs::path dir_ = temp_.path();
};

TEST_F(LinesCli, EveryMethodFindsTheFourWallsAsJson) {
  for (const std::string method : {"sef", "lt", "iepf", "smf", "ale"}) {
    SCOPED_TRACE(method);
    const CliResult o = run("lines " + path("room.csv") + " --method " + method);
    ASSERT_EQ(o.code, 0) << o.err;
    const auto json = nlohmann::json::parse(o.out);
    ASSERT_TRUE(json.is_array());
    ASSERT_EQ(json.size(), kRoom.size());
    for (const auto& line : json) {
      ASSERT_TRUE(line.contains("rho") && line.contains("alpha") && line.contains("start") && line.contains("end") &&
                  line.contains("support"));
      EXPECT_EQ(line["start"].size(), 2u);
      EXPECT_EQ(line["end"].size(), 2u);
      EXPECT_GE(line["support"].size(), 5u);
      // Each line is one of the walls, in the sensor frame.
      bool matched = false;
      for (const Segment2& w : kRoom) {
        const Point2 a = to_local(kPose, w.a), b = to_local(kPose, w.b);
        const LineFit truth = polar_line(a, std::atan2(b.y - a.y, b.x - a.x) + kPi / 2);
        matched = matched || (std::abs(line["rho"].get<double>() - truth.rho) < 1e-6 &&
                              angle_difference(line["alpha"].get<double>(), truth.alpha) < 1e-6);
      }
      EXPECT_TRUE(matched) << line.dump();
    }
  }
}

TEST_F(LinesCli, CsvFormatAndOutputFile) {
  const CliResult o = run("lines " + path("room.csv") + " --method iepf --format csv -o " + path("lines.csv"));
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_TRUE(o.out.empty());
  const std::string csv = file_text(dir_ / "lines.csv");
  std::istringstream rows(csv);
  std::string header, row;
  std::getline(rows, header);
  EXPECT_EQ(header, "rho,alpha,start_x,start_y,end_x,end_y,support");
  int count = 0;
  while (std::getline(rows, row)) {
    ++count;
    EXPECT_EQ(std::count(row.begin(), row.end(), ','), 6) << row;
  }
  EXPECT_EQ(count, 4);
}

TEST_F(LinesCli, MethodOptionsAreChecked) {
  // A huge T_max makes IEPF keep whole breakpoint segments: fewer lines than walls.
  const CliResult loose = run("lines " + path("room.csv") + " --method iepf --t-max 50");
  ASSERT_EQ(loose.code, 0) << loose.err;
  EXPECT_LT(nlohmann::json::parse(loose.out).size(), 4u);
  const CliResult wrong = run("lines " + path("room.csv") + " --method lt --sigma-max 0.1");
  EXPECT_EQ(wrong.code, 2);
  EXPECT_NE(wrong.err.find("--sigma-max does not apply to --method lt"), std::string::npos) << wrong.err;
  // The row's range refuses it where options enter, before the scan is read: a usage error.
  const CliResult negative = run("lines " + path("room.csv") + " --method smf --sigma-max -1");
  EXPECT_EQ(negative.code, 2);
  EXPECT_NE(negative.err.find("--sigma-max must be a positive number"), std::string::npos) << negative.err;
  const CliResult unknown = run("lines " + path("room.csv") + " --method hough");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("hough"), std::string::npos);
  EXPECT_EQ(run("lines " + path("room.csv") + " --format xml").code, 2);
  EXPECT_EQ(run("lines " + path("room.csv") + " --min-points 2.5").code, 2);
  EXPECT_EQ(run("lines").code, 2);
  const CliResult help = run("lines --help");
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("--method"), std::string::npos);
}

TEST_F(LinesCli, BadScansGiveOneClearError) {
  write_text(dir_ / "header.csv", "0,1\n0.1,1\n");
  write_text(dir_ / "text.csv", "angle,range\n0,1\n0.1,far\n");
  write_text(dir_ / "order.csv", "angle,range\n0,1\n0.2,1\n0.1,1\n");
  const CliResult header = run("lines " + path("header.csv"));
  EXPECT_EQ(header.code, 1);
  EXPECT_NE(header.err.find("header.csv:1:"), std::string::npos) << header.err;
  const CliResult text = run("lines " + path("text.csv"));
  EXPECT_EQ(text.code, 1);
  EXPECT_NE(text.err.find("text.csv:3:"), std::string::npos) << text.err;
  const CliResult order = run("lines " + path("order.csv"));
  EXPECT_EQ(order.code, 1);
  EXPECT_NE(order.err.find("order.csv:4:"), std::string::npos) << order.err;
  const CliResult missing = run("lines " + path("nothing.csv"));
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("nothing.csv"), std::string::npos);
  // An unwritable output is refused before any work.
  const CliResult unwritable = run("lines " + path("room.csv") + " -o " + path("no/such/dir/out.json"));
  EXPECT_EQ(unwritable.code, 1);
}

TEST_F(LinesCli, ScansWithoutEnoughValidBeamsGiveAnEmptyList) {
  write_text(dir_ / "invalid.csv", "angle,range\n0,nan\n0.01,inf\n0.02,0\n0.03,-1\n");
  write_text(dir_ / "empty.csv", "angle,range\n");
  for (const std::string name : {"invalid.csv", "empty.csv"}) {
    for (const std::string method : {"sef", "lt", "iepf", "smf", "ale"}) {
      const CliResult o = run("lines " + path(name) + " --method " + method);
      ASSERT_EQ(o.code, 0) << o.err;
      EXPECT_EQ(nlohmann::json::parse(o.out), nlohmann::json::array());
    }
  }
}

}  // namespace
