#include "topocut/io/rooms_geojson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "topocut/core/error.h"

namespace topocut {
namespace {

using nlohmann::json;

double ring_area(const json& ring) {
  double twice = 0.0;
  for (std::size_t i = 0; i + 1 < ring.size(); ++i)
    twice += ring[i][0].get<double>() * ring[i + 1][1].get<double>() - ring[i + 1][0].get<double>() * ring[i][1].get<double>();
  return twice / 2.0;
}

// Two rooms: a 4 x 4 square with a 1 x 1 hole given clockwise-outside / counter-clockwise-hole (the
// wrong way round, so the writer must orient), and a 2 x 4 room beside it; one door between them.
Segmentation two_rooms() {
  Segmentation s;
  s.labels = cv::Mat(4, 6, CV_32SC1, cv::Scalar(1));
  Room a;
  a.id = 1;
  a.polygon.outer = {{0, 0}, {0, 4}, {4, 4}, {4, 0}};
  a.polygon.holes = {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}};
  a.area = 15.0;
  a.labelled_area = 14.5;
  a.centroid = {2.0, 2.1};
  Room b;
  b.id = 2;
  b.polygon.outer = {{4, 0}, {6, 0}, {6, 4}, {4, 4}};
  b.area = 8.0;
  b.centroid = {5.0, 2.0};
  s.rooms = {a, b};
  Passage door;
  door.room_a = 1;
  door.room_b = 2;
  door.cut = {{4, 1}, {4, 2}};
  door.width = 1.0;
  door.door = true;
  door.rule = CutRule::kDoor;
  Passage opening = door;
  opening.cut = {{4, 2.5}, {4, 4}};
  opening.width = 1.5;
  opening.door = false;
  opening.rule = CutRule::kWallLine;
  s.passages = {door, opening};
  return s;
}

TEST(RoomsGeoJson, Rfc7946RingsAndProperties) {
  const Segmentation s = two_rooms();
  const std::vector<RoomPlacement> placements = {{{0.5, 0.5}, {0, 0}, {4, 4}}, {{5, 2}, {4, 0}, {6, 4}}};
  const json g = json::parse(rooms_to_geojson(s, placements));
  ASSERT_EQ(g["type"], "FeatureCollection");
  const json& features = g["features"];
  ASSERT_EQ(features.size(), 4u);
  const json& room = features[0];
  EXPECT_EQ(room["geometry"]["type"], "Polygon");
  const json& rings = room["geometry"]["coordinates"];
  ASSERT_EQ(rings.size(), 2u);
  for (const json& ring : rings) {
    ASSERT_GE(ring.size(), 4u);
    EXPECT_EQ(ring.front(), ring.back()) << "ring not closed";
  }
  EXPECT_DOUBLE_EQ(ring_area(rings[0]), 16.0);  // exterior counter-clockwise
  EXPECT_DOUBLE_EQ(ring_area(rings[1]), -1.0);  // hole clockwise
  EXPECT_EQ(room["properties"]["id"], 1);
  EXPECT_EQ(room["properties"]["kind"], "room");
  EXPECT_DOUBLE_EQ(room["properties"]["area"].get<double>(), 15.0);
  EXPECT_DOUBLE_EQ(room["properties"]["labelled_area"].get<double>(), 14.5);
  EXPECT_EQ(room["properties"]["inside"], json::array({0.5, 0.5}));
  const json& door = features[2];
  EXPECT_EQ(door["geometry"]["type"], "LineString");
  EXPECT_EQ(door["geometry"]["coordinates"], json::parse("[[4, 1], [4, 2]]"));
  EXPECT_EQ(door["properties"]["kind"], "door");
  EXPECT_EQ(door["properties"]["rooms"], json::array({1, 2}));
  EXPECT_EQ(door["properties"]["rule"], "door");
  EXPECT_EQ(features[3]["properties"]["kind"], "opening");
  EXPECT_EQ(features[3]["properties"]["rule"], "wall-line");
  EXPECT_DOUBLE_EQ(features[3]["properties"]["width"].get<double>(), 1.5);
}

TEST(RoomsGeoJson, WithoutPlacementsHasNoInsideAndMismatchIsAnError) {
  const Segmentation s = two_rooms();
  const json g = json::parse(rooms_to_geojson(s));
  EXPECT_FALSE(g["features"][0]["properties"].contains("inside"));
  EXPECT_THROW(rooms_to_geojson(s, {RoomPlacement{}}), Error);
}

}  // namespace
}  // namespace topocut
