// The decomposition's JSON on the worked example of docs/decompose.md: a 10 x 10 room around a 4 x 4 pillar,
// tau 4, is cut at the two diagonals from the pillar's corners to the room's, giving two pieces
// of area 42 (100 - 16 split in half).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "topocut/decomposition/decompose.h"
#include "topocut/decomposition/decomposition_json.h"

namespace topocut {
namespace {

TEST(DecompositionJson, WritesPiecesCutsAndAbsorbedHolesInTheDocumentedOrder) {
  PolygonWithHoles room;
  room.outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  room.holes = {{{3, 3}, {3, 7}, {7, 7}, {7, 3}}};
  DecompositionOptions options;
  options.tau = 4.0;
  const std::string text = decomposition_to_json(decompose(room, options));
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
  std::vector<std::string> keys;
  for (const auto& [key, value] : json.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"pieces", "cuts", "absorbed_holes"}));
  ASSERT_EQ(json["pieces"].size(), 2u);
  for (const auto& piece : json["pieces"]) {
    EXPECT_DOUBLE_EQ(piece["area"].get<double>(), 42.0);
    EXPECT_TRUE(piece["holes"].empty());
    EXPECT_EQ(piece["outer"].size(), 6u);
  }
  ASSERT_EQ(json["cuts"].size(), 2u);
  for (const auto& cut : json["cuts"]) {
    // Each cut joins a corner of the room to the nearest corner of the pillar: length 3 * sqrt(2).
    const double dx = cut[1][0].get<double>() - cut[0][0].get<double>();
    const double dy = cut[1][1].get<double>() - cut[0][1].get<double>();
    EXPECT_NEAR(std::hypot(dx, dy), 3.0 * std::sqrt(2.0), 1e-12);
  }
  EXPECT_TRUE(json["absorbed_holes"].empty());
}

}  // namespace
}  // namespace topocut
