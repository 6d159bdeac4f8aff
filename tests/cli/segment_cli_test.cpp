// Smoke and bad-input tests of `topocut segment`, run as a separate process.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <algorithm>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "cli/cli_maps.h"
#include "cli/cli_runner.h"
#include "io/temp_dir.h"
#include "io/test_images.h"

namespace {

using topocut::testing::bundled;
using topocut::testing::TempDir;

using Result = topocut::testing::CliResult;
using topocut::testing::file_text;

// `topocut segment ARGS...` (the shared runner, with the suite's time limit).
Result run(const TempDir& dir, const std::vector<std::string>& args) { return topocut::testing::run_cli(dir, "segment", args, 600); }

// A failed run: non-zero exit, one line on stderr that says error and names the problem.
void expect_error(const Result& r, const std::string& fragment, int code = 1) {
  EXPECT_EQ(r.code, code) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("topocut segment: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << "expected '" << fragment << "' in: " << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

std::size_t files_in(const TempDir& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++n;
  return n;
}

TEST(SegmentCli, FloorplanWritesEveryOutput) {
  TempDir dir;
  const Result r = run(dir, {bundled("floorplan.yaml"), "--out-labels", dir.file("labels.png"), "--out-color",
                             dir.file("rooms.png"), "--out-json", dir.file("rooms.json"), "--out-svg", dir.file("rooms.svg")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("400 x 300 cells at 0.05 m"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrote labels:  " + dir.file("labels.png")), std::string::npos) << r.out;
  const cv::Mat labels = topocut::testing::read_test_image(dir.file("labels.png"));
  ASSERT_EQ(labels.type(), CV_16UC1);
  const nlohmann::json rooms = nlohmann::json::parse(file_text(dir.file("rooms.json")));
  double low = 0, high = 0;
  cv::minMaxLoc(labels, &low, &high);
  EXPECT_EQ(static_cast<std::size_t>(high), rooms["rooms"].size());
  EXPECT_NE(r.out.find(std::to_string(rooms["rooms"].size()) + " room"), std::string::npos) << r.out;
  // Every free cell of the map is in a room, and only those.
  const cv::Mat map = topocut::testing::read_test_image(bundled("floorplan.png"), topocut::testing::Pixels::kGrey);
  EXPECT_EQ(cv::countNonZero((labels > 0) != (map == 254)), 0);
  const cv::Mat overlay = topocut::testing::read_test_image(dir.file("rooms.png"), topocut::testing::Pixels::kColour);
  EXPECT_EQ(overlay.size(), cv::Size(800, 600));  // scaled 2x so the ids stay legible
  const std::string svg = file_text(dir.file("rooms.svg"));
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(files_in(dir), 4u);  // and no temporary files left over
}

TEST(SegmentCli, MergedCorridorIsOneRoomAndParityKeepsDuDesPieces) {
  TempDir dir;
  const Result rooms = run(dir, {bundled("corridor_l.yaml"), "--out-json", dir.file("rooms.json")});
  ASSERT_EQ(rooms.code, 0) << rooms.err;
  EXPECT_NE(rooms.out.find("1 room, 0 passages"), std::string::npos) << rooms.out;
  // The merged room's polygon is the whole L (no internal passage, area of all its cells).
  const nlohmann::json json = nlohmann::json::parse(file_text(dir.file("rooms.json")));
  ASSERT_EQ(json["rooms"].size(), 1u);
  EXPECT_TRUE(json["passages"].empty());
  const Result parity = run(dir, {bundled("corridor_l.yaml"), "--parity"});
  ASSERT_EQ(parity.code, 0) << parity.err;
  EXPECT_NE(parity.out.find("2 rooms, 1 passage"), std::string::npos) << parity.out;
  EXPECT_NE(parity.out.find("parity"), std::string::npos) << parity.out;
  const Result unmerged = run(dir, {bundled("corridor_l.yaml"), "--no-merge"});
  ASSERT_EQ(unmerged.code, 0) << unmerged.err;
  EXPECT_NE(unmerged.out.find("2 rooms, 1 passage"), std::string::npos) << unmerged.out;
  expect_error(run(dir, {bundled("corridor_l.yaml"), "--parity", "--no-merge"}), "--parity", 2);
  expect_error(run(dir, {bundled("corridor_l.yaml"), "--door-width", "0"}), "--door-width", 2);
}

TEST(SegmentCli, TrivialModeGivesOneRoomPerComponent) {
  TempDir dir;
  const Result r = run(dir, {bundled("floorplan.yaml"), "--trivial", "--out-json", dir.file("r.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1 room, 0 passages"), std::string::npos) << r.out;
  EXPECT_EQ(nlohmann::json::parse(file_text(dir.file("r.json")))["rooms"].size(), 1u);
}

TEST(SegmentCli, PlainImageTakesTheResolutionOption) {
  TempDir dir;
  const Result r = run(dir, {bundled("furnished.png"), "--resolution", "0.1", "--trivial", "--out-json", dir.file("r.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(file_text(dir.file("r.json")));
  EXPECT_DOUBLE_EQ(doc["resolution"].get<double>(), 0.1);
  // The same map at twice the cell size covers four times the area.
  const Result yaml = run(dir, {bundled("furnished.yaml"), "--trivial", "--out-json", dir.file("y.json")});
  ASSERT_EQ(yaml.code, 0) << yaml.err;
  const nlohmann::json at_005 = nlohmann::json::parse(file_text(dir.file("y.json")));
  EXPECT_NEAR(doc["rooms"][0]["area"].get<double>(), 4.0 * at_005["rooms"][0]["area"].get<double>(), 1e-6);
  const Result note = run(dir, {bundled("furnished.yaml"), "--trivial", "--resolution", "0.1"});
  EXPECT_NE(note.out.find("--resolution is ignored"), std::string::npos) << note.out;
}

TEST(SegmentCli, HelpExplainsTheCommand) {
  TempDir dir;
  const Result r = run(dir, {"--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("Usage: topocut segment MAP"), std::string::npos);
  for (const char* option : {"--concavity", "--resolution", "--out-labels", "--out-color", "--out-json", "--out-svg",
                             "--trivial", "--robot-radius"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

TEST(SegmentCli, BadMapFiles) {
  TempDir dir;
  expect_error(run(dir, {dir.file("missing.png")}), "does not exist");
  std::ofstream(dir.file("notes.png")) << "not an image";
  expect_error(run(dir, {dir.file("notes.png")}), "as an image");
  std::ofstream(dir.file("empty.png")).close();
  expect_error(run(dir, {dir.file("empty.png")}), "empty");
  ASSERT_TRUE(topocut::testing::write_test_image(dir.file("walls.png"), cv::Mat(20, 20, CV_8UC1, cv::Scalar(0))));
  expect_error(run(dir, {dir.file("walls.png")}), "no free space");
  expect_error(run(dir, {}), "no MAP given: topocut segment MAP [options]", 2);
}

TEST(SegmentCli, BadYamlFiles) {
  TempDir dir;
  ASSERT_TRUE(topocut::testing::write_test_image(dir.file("m.png"), cv::Mat(20, 20, CV_8UC1, cv::Scalar(255))));
  auto yaml = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir.file(name)) << text;
    return dir.file(name);
  };
  expect_error(run(dir, {yaml("a.yaml", "resolution: 0.05\norigin: [0, 0, 0]\n")}), "'image'");
  expect_error(run(dir, {yaml("b.yaml", "image: m.png\norigin: [0, 0, 0]\n")}), "'resolution'");
  expect_error(run(dir, {yaml("c.yaml", "image: m.png\nresolution: 0.05\norigin: [0, 0, 0]\nmode: fuzzy\n")}), "'mode'");
  expect_error(run(dir, {yaml("d.yaml", "image: m.png\nresolution: 0.05\norigin: [0, 0, 0]\noccupied_thresh: 2\n")}),
               "'occupied_thresh'");
  expect_error(run(dir, {yaml("e.yaml", "image: gone.png\nresolution: 0.05\norigin: [0, 0, 0]\n")}), "gone.png");
  expect_error(run(dir, {yaml("f.yaml", "image: m.png\nresolution: -0.05\norigin: [0, 0, 0]\n")}), "'resolution'");
  expect_error(run(dir, {yaml("g.yaml", "{{{")}), "YAML");
  // The well-formed version of the same map works.
  EXPECT_EQ(run(dir, {yaml("ok.yaml", "image: m.png\nresolution: 0.05\norigin: [0, 0, 0]\n")}).code, 0);
}

TEST(SegmentCli, BadOptions) {
  TempDir dir;
  const std::string map = bundled("floorplan.yaml");
  expect_error(run(dir, {map, "--resolution", "0"}), "--resolution", 2);
  expect_error(run(dir, {map, "--resolution", "-1"}), "--resolution", 2);
  expect_error(run(dir, {map, "--resolution", "nan"}), "--resolution", 2);
  expect_error(run(dir, {map, "--resolution", "fine"}), "resolution", 2);
  expect_error(run(dir, {map, "--concavity", "0"}), "--concavity", 2);
  expect_error(run(dir, {map, "--robot-radius", "-1"}), "--robot-radius", 2);
  expect_error(run(dir, {map, "--colour-me-surprised"}), "colour-me-surprised", 2);
  expect_error(run(dir, {map, "--out-labels"}), "out-labels", 2);
}

TEST(SegmentCli, UnwritableOutputsFailBeforeAnyWork) {
  TempDir dir;
  const std::string map = bundled("floorplan.yaml");
  expect_error(run(dir, {map, "--out-json", dir.file("good.json"), "--out-labels", dir.file("no/such/dir/l.png")}),
               "no/such/dir");
  expect_error(run(dir, {map, "--out-svg", dir.path().string()}), "directory");
  expect_error(run(dir, {map, "--out-labels", dir.file("l.jpg")}), ".png");
  expect_error(run(dir, {map, "--out-color", dir.file("c.unknown")}), "format");
  expect_error(run(dir, {map, "--out-json", dir.file("x.json"), "--out-svg", dir.file("x.json")}), "two outputs");
  EXPECT_EQ(files_in(dir), 0u);  // nothing written, not even the good output
}

}  // namespace

namespace {

TEST(SegmentCli, OutCleanShowsTheMapAsTheSegmenterSawIt) {
  TempDir dir;
  // A SLAM-style image: light-grey unknown (230), grey walls (127), a 5 m room with a window in its
  // top wall and laser rays fanning out of it.
  cv::Mat map(200, 200, CV_8UC1, cv::Scalar(230));
  cv::rectangle(map, cv::Rect(48, 78, 104, 104), cv::Scalar(127), cv::FILLED);
  map(cv::Rect(50, 80, 100, 100)).setTo(255);
  map(cv::Rect(90, 78, 20, 2)).setTo(255);
  for (int k = -2; k <= 2; ++k)
    for (int t = 1; t <= 60; ++t) map.at<unsigned char>(78 - t, 100 + k * t / 4) = 255;
  ASSERT_TRUE(topocut::testing::write_test_image(dir.file("slam.png"), map));
  const Result r = run(dir, {dir.file("slam.png"), "--out-clean", dir.file("clean.png"), "--out-labels", dir.file("l.png")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("map cells: free 255, unknown 230, occupied 127 (detected)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrote cleaned map: " + dir.file("clean.png")), std::string::npos) << r.out;
  const cv::Mat clean = topocut::testing::read_test_image(dir.file("clean.png"), topocut::testing::Pixels::kColour);
  ASSERT_EQ(clean.size(), map.size());
  EXPECT_EQ(clean.at<cv::Vec3b>(100, 100), cv::Vec3b(255, 255, 255));  // floor
  EXPECT_EQ(clean.at<cv::Vec3b>(80, 48), cv::Vec3b(0, 0, 0));          // wall
  EXPECT_EQ(clean.at<cv::Vec3b>(5, 5), cv::Vec3b(160, 160, 160));      // unknown
  EXPECT_EQ(clean.at<cv::Vec3b>(78 - 50, 100), cv::Vec3b(40, 40, 220)); // a ray, outside
  const cv::Mat labels = topocut::testing::read_test_image(dir.file("l.png"));
  EXPECT_EQ(labels.at<unsigned short>(78 - 50, 100), 0);
  // Without the cleaning the rays are room space, and --out-clean draws the grid alone.
  const Result raw = run(dir, {dir.file("slam.png"), "--no-clean", "--out-clean", dir.file("raw.png"), "--out-labels", dir.file("r.png")});
  ASSERT_EQ(raw.code, 0) << raw.err;
  EXPECT_NE(topocut::testing::read_test_image(dir.file("r.png")).at<unsigned short>(78 - 50, 100), 0);
  EXPECT_EQ(topocut::testing::read_test_image(dir.file("raw.png"), topocut::testing::Pixels::kColour).at<cv::Vec3b>(78 - 50, 100), cv::Vec3b(255, 255, 255));
  // A non-PNG cleaned map is refused before any work.
  const Result bad = run(dir, {dir.file("slam.png"), "--out-clean", dir.file("clean.jpg")});
  EXPECT_NE(bad.code, 0);
}

}  // namespace

namespace {

TEST(SegmentCli, AnOptionWhereAValueBelongsIsAMissingValue) {
  TempDir dir;
  const Result r = run(dir, {bundled("floorplan.yaml"), "--out-json", "--trivial"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("--out-json needs a value, not the option '--trivial'"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("--trivial")));
  EXPECT_FALSE(std::filesystem::exists("--trivial"));
  // A value that only looks like an option (no such option) is a value.
  EXPECT_EQ(run(dir, {bundled("floorplan.yaml"), "--out-json", dir.file("--rooms.json")}).code, 0);
}

}  // namespace

// --config: a robot's options from a YAML file give what the same options on the command line
// give; the command line wins; a key that is no option is one clear error.
TEST(SegmentCli, ConfigFileGivesTheSameRoomsAsTheCommandLine) {
  TempDir dir;
  {
    std::ofstream config(dir.file("robot.yaml"));
    config << "# the robot's parameters\nconcavity: 1.5\nno-merge: true\nno-doors: false\nout-json: " << dir.file("config.json") << "\n";
  }
  Result r = run(dir, {bundled("floorplan.yaml"), "--config", dir.file("robot.yaml")});
  ASSERT_EQ(r.code, 0) << r.err;
  r = run(dir, {bundled("floorplan.yaml"), "--concavity", "1.5", "--no-merge", "--out-json", dir.file("flags.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json from_config = nlohmann::json::parse(file_text(dir.file("config.json")));
  EXPECT_EQ(from_config, nlohmann::json::parse(file_text(dir.file("flags.json"))));
  // The command line's concavity wins over the file's.
  r = run(dir, {bundled("floorplan.yaml"), "--config", dir.file("robot.yaml"), "--concavity", "2.5", "--out-json", dir.file("mixed.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  r = run(dir, {bundled("floorplan.yaml"), "--concavity", "2.5", "--no-merge", "--out-json", dir.file("expected.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(file_text(dir.file("mixed.json"))), nlohmann::json::parse(file_text(dir.file("expected.json"))));

  std::ofstream(dir.file("typo.yaml")) << "concavty: 1.5\n";
  expect_error(run(dir, {bundled("floorplan.yaml"), "--config", dir.file("typo.yaml")}),
               "is not an option of this command (did you mean 'concavity'?)", 2);
  std::ofstream(dir.file("bad.yaml")) << "concavity: [1.5\n";
  expect_error(run(dir, {bundled("floorplan.yaml"), "--config", dir.file("bad.yaml")}), "is not valid YAML");
  std::ofstream(dir.file("switch.yaml")) << "no-merge: maybe\n";
  expect_error(run(dir, {bundled("floorplan.yaml"), "--config", dir.file("switch.yaml")}), "give true or false", 2);
  expect_error(run(dir, {bundled("floorplan.yaml"), "--config", dir.file("missing.yaml")}), "missing.yaml");
}

// One vocabulary (docs/options.md, "Segmentation options"): robot_radius and robot-radius are one option on the
// command line and in --config, and a typo is answered with the name meant.
TEST(SegmentCli, UnderscoresAndDashesNameTheSameOptionAndTyposGetTheNameMeant) {
  TempDir dir;
  std::ofstream(dir.file("underscored.yaml")) << "robot_radius: 0.3\nno_merge: true\n";
  Result r = run(dir, {bundled("floorplan.yaml"), "--config", dir.file("underscored.yaml"), "--out_json", dir.file("a.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  r = run(dir, {bundled("floorplan.yaml"), "--robot-radius", "0.3", "--no-merge", "--out-json", dir.file("b.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(file_text(dir.file("a.json"))), nlohmann::json::parse(file_text(dir.file("b.json"))));
  r = run(dir, {bundled("floorplan.yaml"), "--robot_radius=0.3", "--no_merge", "--out-json", dir.file("c.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(file_text(dir.file("c.json"))), nlohmann::json::parse(file_text(dir.file("b.json"))));
  expect_error(run(dir, {bundled("floorplan.yaml"), "--robot-radios", "0.3"}), "'--robot-radios' (did you mean '--robot-radius'?)", 2);
  expect_error(run(dir, {bundled("floorplan.yaml"), "--xyz"}), "unrecognised option '--xyz' (see", 2);  // nothing close: no guess
}

TEST(SegmentCli, GeoJsonHasOneFeaturePerRoomAndPassage) {
  TempDir dir;
  const Result r = run(dir, {bundled("floorplan.yaml"), "--out-json", dir.file("rooms.json"), "--out-geojson", dir.file("rooms.geojson")});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json rooms = nlohmann::json::parse(file_text(dir.file("rooms.json")));
  const nlohmann::json geo = nlohmann::json::parse(file_text(dir.file("rooms.geojson")));
  ASSERT_EQ(geo["features"].size(), rooms["rooms"].size() + rooms["passages"].size());
  for (std::size_t k = 0; k < rooms["rooms"].size(); ++k) {
    const nlohmann::json& feature = geo["features"][k];
    EXPECT_EQ(feature["properties"]["id"], rooms["rooms"][k]["id"]);
    // The exterior is the rooms JSON's outer ring, closed.
    nlohmann::json ring = rooms["rooms"][k]["outer"];
    ring.push_back(ring.front());
    EXPECT_EQ(feature["geometry"]["coordinates"][0], ring);
  }
}

namespace {

using topocut::testing::run_cli;

// segment, evaluate, explore and walls share one definition of the segmentation options: the same
// flags in every --help, defaults in their shortest form, the same --parity rule.
TEST(SegmentationOptions, EveryCommandTakesTheSameFlags) {
  TempDir dir;
  for (const std::string command : {"segment", "evaluate", "explore", "walls"}) {
    SCOPED_TRACE(command);
    const Result help = run_cli(dir, command, {"--help"});
    ASSERT_EQ(help.code, 0) << help.err;
    for (const std::string flag : {"--concavity M (=", "--parity", "--door-width M (=", "--no-merge", "--opening M (=",
                                   "--min-room-area M2 (=", "--no-furniture-rule", "--no-wall-lines", "--wall-line-side M (=1)", "--no-island-cuts", "--oversegment F (=0.5)"})
      EXPECT_NE(help.out.find(flag), std::string::npos) << flag << " in\n" << help.out;
    EXPECT_EQ(help.out.find("00000000"), std::string::npos) << help.out;  // no 0.050000000000000003
    if (command != "walls") {
      EXPECT_NE(help.out.find("--resolution M (=0.05)"), std::string::npos) << help.out;
    }
  }
}

TEST(SegmentationOptions, ParityWithASwitchItSetsIsAUsageErrorInEveryCommand) {
  TempDir dir;
  const std::string map = bundled("corridor_l.yaml");
  for (const auto& [command, input] : {std::pair<std::string, std::string>{"segment", map}, {"explore", map},
                                       {"walls", dir.file("absent.log")}}) {
    SCOPED_TRACE(command);
    topocut::testing::expect_clean_error(run_cli(dir, command, {input, "--parity", "--no-merge"}), command, "--parity", 2);
  }
  topocut::testing::expect_clean_error(
      run_cli(dir, "evaluate", {"--dataset", dir.path().string(), "--parity", "--cover-obstacles"}), "evaluate", "--parity", 2);
}

}  // namespace

namespace {

double ring_area(const nlohmann::json& ring) {
  double twice = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const nlohmann::json& a = ring[i];
    const nlohmann::json& b = ring[(i + 1) % ring.size()];
    twice += a[0].get<double>() * b[1].get<double>() - b[0].get<double>() * a[1].get<double>();
  }
  return std::abs(twice) / 2.0;
}

// The rooms JSON, the GeoJSON and the label image say the same of every room: the JSON carries the
// GeoJSON's properties (kind, inside point), "area" is the polygon's and "labelled_area" the cells'.
// On the furnished map they differ (absorbed furniture), so the test tells them apart.
TEST(SegmentCli, JsonGeoJsonAndLabelsAgree) {
  TempDir dir;
  const Result r = run(dir, {bundled("furnished.yaml"), "--out-json", dir.file("r.json"), "--out-geojson", dir.file("r.geojson"),
                             "--out-labels", dir.file("l.png")});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(file_text(dir.file("r.json")));
  const nlohmann::json geo = nlohmann::json::parse(file_text(dir.file("r.geojson")));
  const cv::Mat labels = topocut::testing::read_test_image(dir.file("l.png"));
  const double cell = doc["resolution"].get<double>() * doc["resolution"].get<double>();
  ASSERT_GE(doc["rooms"].size(), 2u);
  double largest_difference = 0.0;
  for (std::size_t i = 0; i < doc["rooms"].size(); ++i) {
    const nlohmann::json& room = doc["rooms"][i];
    double polygon = ring_area(room["outer"]);
    for (const nlohmann::json& hole : room["holes"]) polygon -= ring_area(hole);
    EXPECT_NEAR(room["area"].get<double>(), polygon, 1e-4) << "room " << room["id"];
    const int id = room["id"].get<int>();
    EXPECT_NEAR(room["labelled_area"].get<double>(), cv::countNonZero(labels == id) * cell, 1e-6) << "room " << id;
    largest_difference = std::max(largest_difference, std::abs(room["area"].get<double>() - room["labelled_area"].get<double>()));
    nlohmann::json properties = geo["features"][i]["properties"];
    properties.erase("kind");
    nlohmann::json expected = room;
    expected.erase("outer");
    expected.erase("holes");
    EXPECT_EQ(expected, properties);
    ASSERT_TRUE(room.contains("inside"));
  }
  EXPECT_GT(largest_difference, 0.01) << "the furnished map's polygons should cover furniture that no room's cells do";
  ASSERT_EQ(doc["passages"].size() + doc["rooms"].size(), geo["features"].size());
  for (std::size_t i = 0; i < doc["passages"].size(); ++i) {
    nlohmann::json passage = doc["passages"][i];
    passage.erase("cut");
    EXPECT_EQ(passage, geo["features"][doc["rooms"].size() + i]["properties"]);
    EXPECT_TRUE(passage["kind"] == "door" || passage["kind"] == "opening") << passage;
  }
}

// --at X,Y names the room whose cell holds the point: each room's inside point is in that room; a
// wall and a point off the map are in none; a malformed point is a usage error.
TEST(SegmentCli, AtNamesTheRoomAtAPoint) {
  TempDir dir;
  const Result json_run = run(dir, {bundled("floorplan.yaml"), "--out-json", dir.file("r.json")});
  ASSERT_EQ(json_run.code, 0) << json_run.err;
  const nlohmann::json doc = nlohmann::json::parse(file_text(dir.file("r.json")));
  std::vector<std::string> args = {bundled("floorplan.yaml")};
  std::string expected;
  for (const nlohmann::json& room : doc["rooms"]) {
    std::ostringstream point;
    point.precision(17);
    point << room["inside"][0].get<double>() << "," << room["inside"][1].get<double>();
    args.insert(args.end(), {"--at", point.str()});
    expected += "at " + point.str() + ": room " + std::to_string(room["id"].get<int>()) + "\n";
  }
  args.insert(args.end(), {"--at", "0.01,0.01", "--at=-5,3"});  // the map's corner wall; off the map
  expected += "at 0.01,0.01: none\nat -5,3: none\n";
  const Result r = run(dir, args);
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_GE(r.out.size(), expected.size());
  EXPECT_EQ(r.out.substr(r.out.size() - expected.size()), expected) << r.out;
  expect_error(run(dir, {bundled("floorplan.yaml"), "--at", "3"}), "--at needs a point X,Y", 2);
  expect_error(run(dir, {bundled("floorplan.yaml"), "--at", "3,x"}), "needs a number", 2);
  expect_error(run(dir, {bundled("floorplan.yaml"), "--at", "inf,1"}), "finite", 2);
}

}  // namespace
