#include "topocut/lines/lines_format.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "topocut/core/error.h"
#include "topocut/lines/line.h"

namespace topocut {
namespace {

TEST(LinesFormat, JsonFollowsTheDesignFormatAndRoundTrips) {
  const Line a{1.0 / 3.0, -2.5, {0.1, -0.2}, {1e-17, 3.0}, {0, 1, 2, 7}};
  const Line b{0.0, 3.14159, {-1.0, 0.0}, {1.0, 0.0}, {9, 10}};
  const std::string text = format_lines_json({a, b});
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.rfind("[{\"rho\":", 0), 0u);  // keys in DESIGN.md's order
  const auto json = nlohmann::json::parse(text);
  ASSERT_EQ(json.size(), 2u);
  EXPECT_EQ(json[0]["rho"].get<double>(), a.rho);  // bit-exact numbers
  EXPECT_EQ(json[0]["alpha"].get<double>(), a.alpha);
  EXPECT_EQ(json[0]["start"], nlohmann::json({0.1, -0.2}));
  EXPECT_EQ(json[0]["end"][0].get<double>(), 1e-17);
  EXPECT_EQ(json[0]["support"], nlohmann::json({0, 1, 2, 7}));
  EXPECT_EQ(json[1]["support"], nlohmann::json({9, 10}));
  EXPECT_EQ(format_lines_json({}), "[]\n");
}

TEST(LinesFormat, CsvHasOneRowPerLine) {
  const Line a{2.0, 0.5, {1.0, 2.0}, {3.0, 4.0}, {4, 5, 6}};
  EXPECT_EQ(format_lines_csv({a}), "rho,alpha,start_x,start_y,end_x,end_y,support\n2,0.5,1,2,3,4,4 5 6\n");
  EXPECT_EQ(format_lines_csv({}), "rho,alpha,start_x,start_y,end_x,end_y,support\n");
}

TEST(MakeLine, FitsTheRowsAndChecksThem) {
  // Beams at -45, 0, +45 degrees hitting the wall x = 1.
  Scan scan{{-0.7853981633974483, 0.0, 0.7853981633974483, 1.0}, {1.4142135623730951, 1.0, 1.4142135623730951, NAN}};
  const Line line = make_line(scan, {2, 0, 1, 1});
  EXPECT_EQ(line.support, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_NEAR(line.rho, 1.0, 1e-12);
  EXPECT_NEAR(line.alpha, 0.0, 1e-12);
  EXPECT_NEAR(line.start.x, 1.0, 1e-12);
  EXPECT_NEAR(line.start.y, -1.0, 1e-12);  // the lowest row's end
  EXPECT_NEAR(line.end.y, 1.0, 1e-12);
  EXPECT_NEAR(length(line), 2.0, 1e-12);
  EXPECT_THROW(make_line(scan, {0, 3}), Error);  // NaN range
  EXPECT_THROW(make_line(scan, {0, 9}), Error);  // no such row
  EXPECT_THROW(make_line(scan, {}), Error);
}

}  // namespace
}  // namespace topocut
