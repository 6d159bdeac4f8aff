// Rooms JSON, SVG and the colour overlay, on a hand-built two-room segmentation.
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/json_coordinates.h"
#include "io/temp_dir.h"
#include "topocut/core/error.h"
#include "topocut/io/overlay.h"
#include "topocut/io/rooms_geojson.h"
#include "topocut/io/rooms_json.h"
#include "topocut/io/rooms_svg.h"

namespace topocut {
namespace {

// A 10 x 6 map at 0.5 m, origin (1, 2): a wall frame, rooms 1 (columns 1..4) and 2 (columns 5..8)
// separated at x = 1 + 5 * 0.5 = 3.5 m.
struct TwoRooms {
  OccupancyGrid grid;
  Segmentation seg;
  TwoRooms() {
    grid.cells = cv::Mat(6, 10, CV_8UC1, cv::Scalar(kOccupied));
    grid.cells(cv::Rect(1, 1, 8, 4)).setTo(kFree);
    grid.resolution = 0.5;
    grid.origin = {1.0, 2.0};
    seg.labels = cv::Mat::zeros(6, 10, CV_32SC1);
    seg.labels(cv::Rect(1, 1, 4, 4)).setTo(1);
    seg.labels(cv::Rect(5, 1, 4, 4)).setTo(2);
    seg.resolution = 0.5;
    seg.origin = grid.origin;
    // Room 1 spans x 1.5..3.5, y 2.5..4.5 in metres; room 2 x 3.5..5.5.
    seg.rooms.push_back({1, {{{1.5, 2.5}, {3.5, 2.5}, {3.5, 4.5}, {1.5, 4.5}}, {}}, 4.0, {2.5, 3.5}});
    seg.rooms.push_back({2, {{{3.5, 2.5}, {5.5, 2.5}, {5.5, 4.5}, {3.5, 4.5}}, {{{4, 3}, {4, 4}, {5, 4}, {5, 3}}}}, 4.0, {4.5, 3.5}});
    seg.rooms[1].area = 3.0;  // the polygon's: 4 m² less its 1 m² hole
    seg.rooms[0].labelled_area = seg.rooms[1].labelled_area = 4.0;
    seg.passages.push_back({1, 2, {{3.5, 3.0}, {3.5, 4.0}}, 1.0, true});
    placements = {{{2.0, 3.0}, {1.5, 2.5}, {3.5, 4.5}}, {{4.5, 4.25}, {3.5, 2.5}, {5.5, 4.5}}};
  }
  std::vector<RoomPlacement> placements;
};

TEST(RoomsJson, CarriesRoomsAndPassagesInMetres) {
  const TwoRooms t;
  const nlohmann::json doc = nlohmann::json::parse(rooms_to_json(t.seg));
  EXPECT_EQ(doc["units"], "metres");
  EXPECT_DOUBLE_EQ(doc["resolution"].get<double>(), 0.5);
  EXPECT_EQ(doc["size"], nlohmann::json::array({10, 6}));
  ASSERT_EQ(doc["rooms"].size(), 2u);
  EXPECT_EQ(doc["rooms"][1]["id"], 2);
  EXPECT_DOUBLE_EQ(doc["rooms"][1]["area"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(doc["rooms"][1]["labelled_area"].get<double>(), 4.0);
  EXPECT_FALSE(doc["rooms"][1].contains("inside")) << "no placements given";
  EXPECT_DOUBLE_EQ(doc["rooms"][1]["centroid"][0].get<double>(), 4.5);
  EXPECT_EQ(doc["rooms"][1]["outer"].size(), 4u);
  ASSERT_EQ(doc["rooms"][1]["holes"].size(), 1u);
  EXPECT_DOUBLE_EQ(doc["rooms"][1]["holes"][0][2][1].get<double>(), 4.0);
  ASSERT_EQ(doc["passages"].size(), 1u);
  EXPECT_EQ(doc["passages"][0]["rooms"], nlohmann::json::array({1, 2}));
  EXPECT_DOUBLE_EQ(doc["passages"][0]["cut"][1][1].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(doc["passages"][0]["width"].get<double>(), 1.0);
  EXPECT_EQ(doc["passages"][0]["kind"], "door");
  EXPECT_EQ(doc["passages"][0]["rule"], "decomposition");  // the rule a passage has when none is set
  EXPECT_EQ(doc["frame"], "map");
}

// What GeoJSON and Python carry (kind, inside point), the rooms JSON carries too, with the same values.
TEST(RoomsJson, CarriesWhatTheGeoJsonCarries) {
  TwoRooms t;
  t.seg.rooms[1].kind = RoomKind::kCorridor;
  const nlohmann::json doc = nlohmann::json::parse(rooms_to_json(t.seg, t.placements));
  const nlohmann::json geo = nlohmann::json::parse(rooms_to_geojson(t.seg, t.placements));
  ASSERT_EQ(geo["features"].size(), doc["rooms"].size() + doc["passages"].size());
  for (std::size_t i = 0; i < doc["rooms"].size(); ++i) {
    nlohmann::json properties = geo["features"][i]["properties"];
    EXPECT_EQ(properties["kind"], i == 1 ? "corridor" : "room");
    nlohmann::json room = doc["rooms"][i];
    room.erase("outer");
    room.erase("holes");
    EXPECT_EQ(room, properties);
  }
  EXPECT_EQ(doc["rooms"][1]["inside"], nlohmann::json::array({4.5, 4.25}));
  nlohmann::json passage = doc["passages"][0];
  passage.erase("cut");
  EXPECT_EQ(passage, geo["features"][2]["properties"]);
  EXPECT_THROW(rooms_to_json(t.seg, {t.placements[0]}), Error);
}

// Rooms are printed without building their rings as JSON trees: each room's line is still the
// library's dump of the room's object, rings and all, for coordinates of every size and sign (some
// rounding to 0 or -0, some beyond the fixed notation), with holes and without.
TEST(RoomsJson, EachRoomLineIsTheLibrarysDumpOfTheRoom) {
  std::mt19937 random(36);
  auto coordinate = [&random] {
    const double magnitude = std::pow(10.0, static_cast<double>(random() % 24) - 9.0);
    return (random() % 2 ? -1.0 : 1.0) * magnitude * static_cast<double>(random() % 100000) / 1000.0;
  };
  auto ring = [&](std::size_t n) {
    Ring r;
    for (std::size_t k = 0; k < n; ++k) r.push_back({coordinate(), coordinate()});
    return r;
  };
  Segmentation seg;
  seg.labels = cv::Mat::zeros(4, 4, CV_32SC1);
  seg.resolution = 0.05;
  std::vector<RoomPlacement> placements;
  for (int id = 1; id <= 40; ++id) {
    Room room;
    room.id = id;
    room.polygon.outer = ring(3 + random() % 30);
    for (std::size_t h = 0; h < random() % 3; ++h) room.polygon.holes.push_back(ring(3 + random() % 5));
    room.area = coordinate();
    room.labelled_area = coordinate();
    room.centroid = {coordinate(), coordinate()};
    seg.rooms.push_back(room);
    placements.push_back({{coordinate(), coordinate()}, {}, {}});
  }
  std::istringstream lines(rooms_to_json(seg, placements));
  std::string line;
  while (std::getline(lines, line) && line != "\"rooms\": [") {}
  for (std::size_t i = 0; i < seg.rooms.size(); ++i) {
    ASSERT_TRUE(std::getline(lines, line));
    const Room& room = seg.rooms[i];
    nlohmann::json holes = nlohmann::json::array();
    for (const Ring& hole : room.polygon.holes) holes.push_back(json_coordinates::ring(hole));
    nlohmann::json entry = json_coordinates::room_properties(room, &placements[i]);
    entry["outer"] = json_coordinates::ring(room.polygon.outer);
    entry["holes"] = holes;
    EXPECT_EQ(line, " " + entry.dump() + (i + 1 < seg.rooms.size() ? "," : "")) << "room " << room.id;
  }
}

TEST(RoomsJson, WritesAtomicallyAndReportsBadPaths) {
  const testing::TempDir dir;
  const TwoRooms t;
  write_rooms_json(dir.file("r.json"), t.seg);
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(dir.file("r.json")))["rooms"].size(), 2u);
  EXPECT_THROW(write_rooms_json(dir.file("no/r.json"), t.seg), Error);
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(RoomsSvg, OnePathPerRoomAndFlippedY) {
  const TwoRooms t;
  SvgOptions options;
  options.embed_map = false;
  const std::string svg = rooms_to_svg(t.grid, t.seg, options);
  EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
  EXPECT_EQ(count(svg, "<path "), 2u);
  EXPECT_EQ(count(svg, "<line "), 1u);
  EXPECT_NE(svg.find("viewBox=\"0 0 5 3\""), std::string::npos);
  // Room 1's first vertex (1.5, 2.5) m: x = 0.5, y = 3 - (2.5 - 2) = 2.5 from the top.
  EXPECT_NE(svg.find("M0.5 2.5 L2.5 2.5"), std::string::npos);
  EXPECT_NE(rooms_to_svg(t.grid, t.seg).find("data:image/png;base64,"), std::string::npos);
}

TEST(Overlay, RoomsTintedObstaclesDarkSizeScaled) {
  const TwoRooms t;
  OverlayOptions options;
  options.scale = 3;
  options.draw_ids = false;
  options.draw_passages = false;
  const cv::Mat image = render_overlay(t.grid, t.seg, options);
  ASSERT_EQ(image.size(), cv::Size(30, 18));
  ASSERT_EQ(image.type(), CV_8UC3);
  const cv::Vec3b wall = image.at<cv::Vec3b>(1, 1);
  EXPECT_LT(wall[0] + wall[1] + wall[2], 3 * 80);
  // An interior cell of room 1 (column 2, row 2) is the pastel of room 1's colour.
  const cv::Vec3b c1 = room_colour(1);
  const cv::Vec3b cell = image.at<cv::Vec3b>(2 * 3 + 1, 2 * 3 + 1);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(cell[k], 0.55 * c1[k] + 0.45 * 255, 1.0);
  // With the default scale, the longer side reaches 40 pixels (4 per cell, the cap).
  EXPECT_EQ(render_overlay(t.grid, t.seg).cols, 40);
}

TEST(Overlay, ConsecutiveIdsGetDistinctColours) {
  for (int id = 1; id < 40; ++id) {
    const cv::Vec3b a = room_colour(id), b = room_colour(id + 1);
    const double d = std::sqrt(std::pow(a[0] - b[0], 2) + std::pow(a[1] - b[1], 2) + std::pow(a[2] - b[2], 2));
    EXPECT_GT(d, 60.0) << "ids " << id << " and " << id + 1;
  }
}

// A cut is drawn in its rule's colour, and a wide overlay lists the rules present in a legend.
TEST(Overlay, CutsInTheirRulesColoursWithALegend) {
  TwoRooms t;
  t.seg.passages[0].cut = {{3.5, 2.5}, {3.5, 4.5}};  // the whole wall's height: clear of the anchor marker
  t.seg.passages[0].rule = CutRule::kWallLine;
  OverlayOptions options;
  options.scale = 8;
  options.draw_ids = false;
  // x = 3.5 m is column 5, pixel 5 * 8 - 0.5; y = 2.7 m is row 6 - 1.4 = 4.6, pixel 36.3.
  EXPECT_EQ(render_overlay(t.grid, t.seg, options).at<cv::Vec3b>(36, 39), cut_rule_colour(CutRule::kWallLine));
  for (int a = 0; a <= static_cast<int>(CutRule::kDecomposition); ++a)
    for (int b = a + 1; b <= static_cast<int>(CutRule::kDecomposition); ++b)
      EXPECT_NE(cut_rule_colour(static_cast<CutRule>(a)), cut_rule_colour(static_cast<CutRule>(b)));
  options.scale = 8;  // 80 pixels wide: no legend over the map
  EXPECT_EQ(render_overlay(t.grid, t.seg, options).at<cv::Vec3b>(14, 20),
            render_overlay(t.grid, TwoRooms().seg, options).at<cv::Vec3b>(14, 20));
  // 40 cells at scale 8, 320 pixels wide: a legend, one line per rule present, in the rules' order.
  OccupancyGrid wide;
  wide.cells = cv::Mat(10, 40, CV_8UC1, cv::Scalar(kFree));
  wide.resolution = 0.5;
  Segmentation two_cuts;
  two_cuts.labels = cv::Mat(10, 40, CV_32SC1, cv::Scalar(1));
  two_cuts.resolution = 0.5;
  two_cuts.passages = {t.seg.passages[0], t.seg.passages[0]};
  two_cuts.passages[1].rule = CutRule::kDoor;
  const cv::Mat legend = render_overlay(wide, two_cuts, options);
  EXPECT_EQ(legend.at<cv::Vec3b>(6 + 8, 20), cut_rule_colour(CutRule::kDoor));
  EXPECT_EQ(legend.at<cv::Vec3b>(6 + 16 + 8, 20), cut_rule_colour(CutRule::kWallLine));
}

TEST(Overlay, AnchorsLieInsideTheirRooms) {
  // An L-shaped room whose centroid falls outside it: the anchor must move inside.
  Segmentation s;
  s.resolution = 1.0;
  s.labels = cv::Mat::zeros(20, 20, CV_32SC1);
  s.labels(cv::Rect(0, 0, 4, 20)).setTo(1);
  s.labels(cv::Rect(0, 16, 20, 4)).setTo(1);
  // Centroid of the L in world metres (origin 0, y up): computed by hand from its two rectangles.
  // Vertical bar 4x20 (centre 2, 10), horizontal bar 16x4 without the overlap (centre 12, 2).
  const double ax = (80 * 2.0 + 64 * 12.0) / 144, ay = (80 * 10.0 + 64 * 2.0) / 144;
  s.rooms.push_back({1, {}, 144.0, {ax, ay}});
  const Point2 anchor = room_anchor_points(s)[0];
  const int c = static_cast<int>(std::floor(anchor.x)), r = 19 - static_cast<int>(std::floor(anchor.y));
  EXPECT_EQ(s.labels.at<int>(r, c), 1);
}

TEST(Overlay, SizeMismatchIsAnError) {
  TwoRooms t;
  t.seg.labels = cv::Mat::zeros(5, 5, CV_32SC1);
  EXPECT_THROW(render_overlay(t.grid, t.seg), Error);
  EXPECT_THROW(rooms_to_svg(t.grid, t.seg), Error);
}

}  // namespace
}  // namespace topocut
