// Determinism (DESIGN.md: same input, same output, bit for bit): each command runs twice as separate
// processes on the same input and every output file must be byte-identical.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_runner.h"
#include "io/temp_dir.h"

namespace {

using topocut::testing::TempDir;

using topocut::testing::CliResult;
using topocut::testing::file_text;
using topocut::testing::run_cli;

// The first two outputs of a run are equal, byte for byte, to the same outputs of a second run.
void expect_identical(const std::string& first, const std::string& second) {
  const std::string a = file_text(first), b = file_text(second);
  EXPECT_FALSE(a.empty()) << first << " is empty";
  EXPECT_TRUE(a == b) << first << " and " << second << " differ (" << a.size() << " vs " << b.size() << " bytes)";
}

TEST(Determinism, SegmentWritesIdenticalLabelsOverlayJsonAndSvg) {
  TempDir dir;
  for (const std::string map : {"maps/furnished.yaml", "maps/corridor_l.yaml"}) {
    SCOPED_TRACE(map);
    for (const std::string run : {"a", "b"}) {
      const CliResult r = run_cli(dir, "segment",
                                  {std::string(TOPOCUT_SOURCE_DIR "/") + map, "--out-labels", dir.file(run + "_labels.png"),
                                   "--out-color", dir.file(run + "_color.png"), "--out-json", dir.file(run + ".json"),
                                   "--out-svg", dir.file(run + ".svg")},
                                  600);
      ASSERT_EQ(r.code, 0) << r.err;
    }
    for (const std::string name : {"_labels.png", "_color.png", ".json", ".svg"}) {
      expect_identical(dir.file("a" + name), dir.file("b" + name));
    }
  }
}

TEST(Determinism, DecomposeWritesIdenticalJson) {
  TempDir dir;
  // A floor plan with two rooms, a corridor and a pillar: several cuts and an absorbed hole.
  const std::string polygon = dir.write(
      "plan.json",
      R"({"outer": [[0,0],[40,0],[40,20],[22,20],[22,21],[40,21],[40,40],[0,40],[0,21],[18,21],[18,20],[0,20]],
          "holes": [[[30,8],[30,10],[32,10],[32,8]], [[5,30],[5,35],[12,35],[12,30]]]})");
  for (const std::string selection : {"greedy", "reference"}) {
    SCOPED_TRACE(selection);
    for (const std::string run : {"a", "b"}) {
      const CliResult r = run_cli(dir, "decompose", {polygon, "--tau", "2", "--selection", selection, "-o", dir.file(run + ".json")}, 600);
      ASSERT_EQ(r.code, 0) << r.err;
    }
    expect_identical(dir.file("a.json"), dir.file("b.json"));
  }
}

TEST(Determinism, LinesWritesIdenticalJsonForEveryMethod) {
  TempDir dir;
  // A scan of a 6 m x 4 m room from (1.5, 1), 0.5° steps over 270°, with a deterministic ripple as noise.
  std::ostringstream csv;
  csv.precision(17);
  csv << "angle,range\n";
  const double pi = 3.14159265358979323846;
  for (int i = 0; i <= 540; ++i) {
    const double angle = -0.75 * pi + i * pi / 360.0;
    const double dx = std::cos(angle), dy = std::sin(angle);
    double range = 1e9;
    if (dx > 1e-12) range = std::min(range, 4.5 / dx);
    if (dx < -1e-12) range = std::min(range, -1.5 / dx);
    if (dy > 1e-12) range = std::min(range, 3.0 / dy);
    if (dy < -1e-12) range = std::min(range, -1.0 / dy);
    csv << angle << "," << range + 0.01 * std::sin(i * 1.7) << "\n";
  }
  const std::string scan = dir.write("scan.csv", csv.str());
  for (const std::string method : {"sef", "lt", "iepf", "smf", "ale"}) {
    SCOPED_TRACE(method);
    for (const std::string run : {"a", "b"}) {
      const CliResult r = run_cli(dir, "lines", {scan, "--method", method, "-o", dir.file(run + ".json")}, 600);
      ASSERT_EQ(r.code, 0) << r.err;
    }
    expect_identical(dir.file("a.json"), dir.file("b.json"));
  }
}

}  // namespace
