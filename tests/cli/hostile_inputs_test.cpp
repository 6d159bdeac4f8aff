// Hostile inputs through the topocut binary (issue 12, inputs and numbers): devices, FIFOs, images
// declaring huge sizes or in formats no map comes in, gzip bombs, and numbers far from any map's
// scale. Every case must end within seconds as one clean error line (or a correct result).
#include <sys/stat.h>

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <zlib.h>

#include "cli/cli_maps.h"
#include "cli/cli_runner.h"
#include "io/test_images.h"

namespace {

using topocut::testing::bundled;
using topocut::testing::small_map;
using topocut::testing::CliResult;
using topocut::testing::expect_clean_error;
using topocut::testing::run_cli;
using topocut::testing::TempDir;

// The bytes of a real PNG whose IHDR now declares width x height (the CRC no longer matches, which
// does not matter: the size must be refused before any decoder reads on).
std::string png_declaring(const TempDir& dir, std::uint32_t width, std::uint32_t height) {
  std::string bytes = topocut::testing::file_text(small_map(dir));
  for (int i = 0; i < 4; ++i) {
    bytes[16 + i] = static_cast<char>(width >> (24 - 8 * i));
    bytes[20 + i] = static_cast<char>(height >> (24 - 8 * i));
  }
  return dir.write("huge.png", bytes);
}

std::string gzip(const TempDir& dir, const std::string& name, const std::string& unit, std::size_t repeats) {
  const std::string path = dir.file(name);
  gzFile file = gzopen(path.c_str(), "wb9");
  for (std::size_t i = 0; i < repeats; ++i) gzwrite(file, unit.data(), static_cast<unsigned>(unit.size()));
  gzclose(file);
  return path;
}

std::string number(double value) { return nlohmann::json(value).dump(); }

std::string pentagon_json(double scale) {
  const double points[5][2] = {{0, 0}, {10, 0}, {10, 10}, {5, 3}, {0, 10}};  // concave at (5, 3)
  nlohmann::json outer = nlohmann::json::array();
  for (const auto& p : points) outer.push_back({p[0] * scale, p[1] * scale});
  return nlohmann::json{{"outer", outer}}.dump();
}

TEST(HostileInputs, FifoAsMapIsRefusedWithoutWaiting) {
  const TempDir dir;
  ASSERT_EQ(::mkfifo(dir.file("map.png").c_str(), 0600), 0);
  expect_clean_error(run_cli(dir, "segment", {dir.file("map.png")}), "segment", "not a regular file");
  ASSERT_EQ(::mkfifo(dir.file("log").c_str(), 0600), 0);
  expect_clean_error(run_cli(dir, "walls", {dir.file("log")}), "walls", "not a regular file");
}

TEST(HostileInputs, FifoOrDeviceAsConfigFileIsRefusedWithoutWaiting) {
  const TempDir dir;
  ASSERT_EQ(::mkfifo(dir.file("robot.yaml").c_str(), 0600), 0);
  expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.png"), "--config", dir.file("robot.yaml")}), "segment",
                     "not a regular file");
  expect_clean_error(run_cli(dir, "segment", {bundled("floorplan.png"), "--config", "/dev/zero"}), "segment",
                     "not a regular file");
}

TEST(HostileInputs, DevZeroAsMapYamlImageOrPolygonIsRefused) {
  const TempDir dir;
  expect_clean_error(run_cli(dir, "segment", {"/dev/zero"}), "segment", "not a regular file");
  const std::string yaml = dir.write("m.yaml", "image: /dev/zero\nresolution: 0.05\norigin: [0, 0, 0]\n");
  expect_clean_error(run_cli(dir, "segment", {yaml}), "segment", "not a regular file");
  expect_clean_error(run_cli(dir, "decompose", {"/dev/zero", "--tau", "1"}), "decompose", "not a regular file");
  expect_clean_error(run_cli(dir, "lines", {"/dev/zero"}), "lines", "not a regular file");
  expect_clean_error(run_cli(dir, "walls", {"/dev/zero"}), "walls", "not a regular file");
}

TEST(HostileInputs, StandardInputIsBoundedToo) {
  const TempDir dir;
  const std::string polygon = dir.write("p.json", pentagon_json(1.0));
  const CliResult ok = run_cli(dir, "decompose", {"-", "--tau", "1"}, 10, polygon);
  ASSERT_EQ(ok.code, 0) << ok.err;
  EXPECT_GE(nlohmann::json::parse(ok.out)["pieces"].size(), 2u);  // cut at the notch
  // /dev/zero on standard input: refused at the limit, not read until memory runs out.
  expect_clean_error(run_cli(dir, "decompose", {"-", "--tau", "1"}, 10, "/dev/zero"), "decompose", "4 MiB");
}

TEST(HostileInputs, ImageDeclaringTooManyPixelsIsRefusedBeforeDecoding) {
  const TempDir dir;
  const std::string huge = png_declaring(dir, 30000, 30000);
  expect_clean_error(run_cli(dir, "segment", {huge}), "segment", "--max-megapixels");
  // Raising the limit lets the header pass; the (patched) file then fails as corrupt, still cleanly.
  expect_clean_error(run_cli(dir, "segment", {huge, "--max-megapixels", "1000"}), "segment", "huge.png");
  expect_clean_error(run_cli(dir, "segment", {small_map(dir), "--max-megapixels", "0"}), "segment", "(0, 1000]", 2);
  // The limit is the user's: a 2400-pixel map is refused at 0.001 megapixels, accepted by default.
  expect_clean_error(run_cli(dir, "segment", {small_map(dir), "--max-megapixels", "0.001"}), "segment", "0.001 megapixels");
  EXPECT_EQ(run_cli(dir, "segment", {small_map(dir), "--trivial"}).code, 0);
}

TEST(HostileInputs, FormatsNoMapComesInNeverReachADecoder) {
  const TempDir dir;
  // A DICOM preamble (128 bytes, then "DICM"): OpenCV would hand it to its DICOM decoder.
  std::string dicom(128, '\0');
  dicom += "DICM";
  dicom += std::string(15, '\x7f');
  expect_clean_error(run_cli(dir, "segment", {dir.write("scan.png", dicom)}), "segment", "not PNG, PGM/PPM, JPEG, BMP or TIFF");
  expect_clean_error(run_cli(dir, "segment", {dir.write("x.hdr", "#?RADIANCE\n")}), "segment", "not PNG");
}

TEST(HostileInputs, GzipBombsInWallsEndAtTheirBounds) {
  const TempDir dir;
  // 256 MiB of zeros in about 256 KB: one endless line, refused at 4 MiB of it.
  const std::string zeros = gzip(dir, "zeros.log.gz", std::string(1 << 20, '\0'), 256);
  expect_clean_error(run_cli(dir, "walls", {zeros}), "walls", "longer than 4 MiB");
  // Valid lines beyond the reading limit (5 million readings): refused with the limit named.
  std::string line = "FLASER 1000";
  for (int i = 0; i < 1000; ++i) line += " 1";
  line += " 0 0 0 0 0 0 1 h 1\n";
  const std::string many = gzip(dir, "many.log.gz", line, 5001);
  expect_clean_error(run_cli(dir, "walls", {many}), "walls", "max_total_beams");
}

TEST(HostileInputs, FlaserWithMoreValuesThanAnnouncedIsRefusedNamingTheLine) {
  const TempDir dir;
  std::string log;
  for (int i = 0; i < 3; ++i) log += "FLASER 3 1 1 1 0 0 0 0 0 0 1 h 1\n";
  log += "FLASER 3 1 1 1 1 1 0 0 0 0 0 0 1 h 1\n";  // five ranges announced as three
  expect_clean_error(run_cli(dir, "walls", {dir.write("bad.log", log)}), "walls", "bad.log:4: FLASER announces 3 ranges");
}

TEST(HostileInputs, ResolutionsOutsideTheRangeAreRefusedWithTheRange) {
  const TempDir dir;
  const std::string map = small_map(dir);
  for (const char* r : {"1e308", "1e-12"})  // a bad option (the table's range): a usage error, as --concavity
    expect_clean_error(run_cli(dir, "segment", {map, "--resolution", r}), "segment", "[0.0001, 1000] metres per cell", 2);
  const std::string yaml = dir.write("m.yaml", "image: map.png\nresolution: 1e308\norigin: [0, 0, 0]\n");
  expect_clean_error(run_cli(dir, "segment", {yaml}), "segment", "[0.0001, 1000] metres per cell");
  const std::string far = dir.write("f.yaml", "image: map.png\nresolution: 0.05\norigin: [1e300, 0, 0]\n");
  expect_clean_error(run_cli(dir, "segment", {far}), "segment", "[-1e+09, 1e+09] metres");
  expect_clean_error(run_cli(dir, "segment", {map, "--concavity", "1e308"}), "segment", "(0, 100000] metres", 2);
  expect_clean_error(run_cli(dir, "walls", {bundled("../fuzz/corpus/fuzz_carmen_log/small.log"), "--resolution", "1e308"}),
                     "walls", "[0.0001, 1000] metres per cell", 2);  // a bad option: usage error, before the log is read
  // The edges of the range work and give finite numbers.
  for (const char* r : {"0.0001", "1000"}) {
    const CliResult ok =
        run_cli(dir, "segment", {map, "--resolution", r, "--trivial", "--no-clean", "--min-room-area", "0", "--out-json", dir.file("r.json")});
    ASSERT_EQ(ok.code, 0) << ok.err;
    const nlohmann::json rooms = nlohmann::json::parse(topocut::testing::file_text(dir.file("r.json")))["rooms"];
    ASSERT_EQ(rooms.size(), 1u);
    EXPECT_TRUE(rooms[0]["area"].is_number() && rooms[0]["area"].get<double>() > 0.0) << rooms[0]["area"];
  }
}

// At the finest resolution allowed the cleaning's 0.6 m disc and its closing square are thousands
// of cells wide, wider than the map: they must be answered without an erosion of that size (it ran
// for minutes). The bundled 400 x 300 floor plan at 0.1 mm per cell is one room 4 cm wide.
TEST(HostileInputs, FinestResolutionWithCleaningEndsInOneRoom) {
  const TempDir dir;
  const CliResult r = run_cli(dir, "segment", {bundled("floorplan.png"), "--resolution", "0.0001", "--out-json", dir.file("r.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json rooms = nlohmann::json::parse(topocut::testing::file_text(dir.file("r.json")))["rooms"];
  EXPECT_EQ(rooms.size(), 1u);
}

TEST(HostileInputs, DecomposeFarFromUnitScaleIsRefusedNotEmptied) {
  const TempDir dir;
  for (double scale : {1e160, 1e307, 1e-200}) {  // 1e307: the pentagon reaches 1e308
    const std::string path = dir.write("p.json", pentagon_json(scale));
    const CliResult r = run_cli(dir, "decompose", {path, "--tau", number(scale)});
    expect_clean_error(r, "decompose", "rescale the polygon");
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  const std::string square = dir.write("s.json", R"({"outer": [[0,0],[1e308,0],[1e308,1e308],[0,1e308]]})");
  expect_clean_error(run_cli(dir, "decompose", {square, "--tau", "1"}), "decompose", "[-1e+12, 1e+12]");
  // Within the range the pentagon is cut at its notch, with finite areas.
  for (double scale : {1e-5, 1e10}) {
    const CliResult ok = run_cli(dir, "decompose", {dir.write("q.json", pentagon_json(scale)), "--tau", number(scale)});
    ASSERT_EQ(ok.code, 0) << ok.err;
    const nlohmann::json pieces = nlohmann::json::parse(ok.out)["pieces"];
    ASSERT_GE(pieces.size(), 2u) << ok.out;
    double total = 0.0;
    for (const auto& piece : pieces) total += piece["area"].get<double>();
    EXPECT_NEAR(total, 65.0 * scale * scale, 1e-9 * 65.0 * scale * scale);
  }
}

// A bad option of a later stage is reported before the log is read (here the log does not even
// exist, so any other order would report the missing file instead).
TEST(HostileInputs, WallsRefusesBadOptionsBeforeReadingTheLog) {
  TempDir dir;
  // The row's range, checked where options enter, names the flag.
  expect_clean_error(run_cli(dir, "walls", {dir.file("missing.log"), "--thickness", "-1"}), "walls",
                     "--thickness must lie in [0, 100000] metres", 2);
}

}  // namespace

namespace {

// A memory limit (ulimit -v) below what an 8000 x 8000 map needs: OpenCV's failed allocation is
// reported as running out of memory, not as an internal failure. ASan reserves terabytes of
// address space, so the limit cannot apply to a sanitizer build.
TEST(HostileInputs, OutOfMemoryIsNamedAsSuch) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "a virtual memory limit does not work with AddressSanitizer";
#else
  const TempDir dir;
  cv::Mat map(8000, 8000, CV_8UC1, cv::Scalar(255));
  for (int i = 0; i < map.rows; i += 200) map.row(i).setTo(0), map.col(i).setTo(0);
  ASSERT_TRUE(topocut::testing::write_test_image(dir.file("big.png"), map));
  const std::string line = "segment " + topocut::testing::shell_quoted(dir.file("big.png")) + " --trivial";
  const CliResult r = topocut::testing::run_cli_line(dir.path(), line, 60, "ulimit -v 300000;");
  expect_clean_error(r, "segment", "out of memory");
  EXPECT_EQ(r.err.find("internal failure"), std::string::npos) << r.err;
#endif
}

// A config file whose YAML is well formed but not a mapping of option names: one line naming the
// file and the line, a usage error (it was "internal failure: yaml-cpp: ... bad conversion").
TEST(HostileInputs, ConfigKeysThatAreNotNamesAreNamed) {
  const TempDir dir;
  const std::string map = small_map(dir);
  for (const char* text : {"? [a, b]\n: 1\n", "{[1]: 2}\n", "trivial: true\n? {x: 1}\n: 2\n"}) {
    const std::string config = dir.write("c.yaml", text);
    expect_clean_error(run_cli(dir, "segment", {map, "--config", config}), "segment",
                       "c.yaml', line ", 2);
    expect_clean_error(run_cli(dir, "segment", {map, "--config", config}), "segment", "a key must be an option name", 2);
  }
}

}  // namespace
