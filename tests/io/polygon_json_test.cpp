// Polygon JSON (the input of `topocut decompose`): what parses, and one clear Error for the rest.
#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/io/polygon_json.h"

namespace topocut {
namespace {

TEST(PolygonJson, ParsesOuterRingAndHolesAsWritten) {
  const PolygonWithHoles p = parse_polygon_json(
      R"({"outer": [[0,0],[10,0],[10,10],[0,10]], "holes": [[[2,2],[2,3],[3.5,3]]]})");
  ASSERT_EQ(p.outer.size(), 4u);
  EXPECT_EQ(p.outer[1], (Point2{10, 0}));
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_EQ(p.holes[0][2], (Point2{3.5, 3}));
}

TEST(PolygonJson, HolesAreOptional) {
  EXPECT_TRUE(parse_polygon_json(R"({"outer": [[0,0],[1,0],[0,1]]})").holes.empty());
}

void expect_error(const std::string& text, const std::string& fragment) {
  try {
    parse_polygon_json(text, "plan.json");
    ADD_FAILURE() << "no error for " << text;
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("plan.json"), std::string::npos) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

TEST(PolygonJson, BadInputIsOneErrorNamingTheSource) {
  expect_error(R"({"outer": [[0,0],[1,0],)", "not valid JSON");
  expect_error(R"([[0,0],[1,0],[0,1]])", "\"outer\"");
  expect_error(R"({"outer": [[0,0],["1",0],[0,1]]})", "two numbers");
  expect_error(R"({"outer": [[0,0],[1,0,2],[0,1]]})", "two numbers");
  expect_error(R"({"outer": {"x": 1}})", "array");
  expect_error(R"({"outer": [[0,0],[1,0],[0,1]], "holes": 3})", "holes");
  expect_error(R"({"outer": [[0,0],[1,0],[0,1]], "holes": [[[0,0]], 7]})", "hole 1");
  expect_error(R"({"outer": [[0,0],[1e999,0],[0,1]]})", "JSON");  // overflow is rejected by the parser
}

}  // namespace
}  // namespace topocut
