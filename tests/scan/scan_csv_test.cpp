#include "topocut/scan/scan_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <cstdio>
#include <fstream>
#include <string>

#include "topocut/core/error.h"

namespace topocut {
namespace {

// The message of the Error thrown by parsing `text`, or "" if none.
std::string parse_error(const std::string& text) {
  try {
    parse_scan_csv(text, "s.csv");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ScanCsv, ParsesRowsAsBeams) {
  const Scan scan = parse_scan_csv("angle,range\n-0.5,1.25\n0,nan\n+0.5, inf \r\n0.75,0\n\n");
  ASSERT_EQ(scan.size(), 4u);
  EXPECT_EQ(scan.angles[0], -0.5);
  EXPECT_EQ(scan.ranges[0], 1.25);
  EXPECT_TRUE(std::isnan(scan.ranges[1]));
  EXPECT_EQ(scan.angles[2], 0.5);
  EXPECT_TRUE(std::isinf(scan.ranges[2]));
  EXPECT_EQ(scan.ranges[3], 0.0);
  EXPECT_TRUE(scan.is_valid(0));
  EXPECT_FALSE(scan.is_valid(1));
  EXPECT_FALSE(scan.is_valid(2));
  EXPECT_FALSE(scan.is_valid(3));
}

TEST(ScanCsv, HeaderOnlyIsAnEmptyScan) { EXPECT_EQ(parse_scan_csv("angle,range\n").size(), 0u); }

TEST(ScanCsv, RoundTripIsExact) {
  Scan scan;
  for (int i = 0; i < 50; ++i) {
    scan.angles.push_back(-1.0 + i * 0.0104719755119659774);
    scan.ranges.push_back(i == 7 ? std::numeric_limits<double>::infinity() : 1.0 / (i + 3));
  }
  const Scan back = parse_scan_csv(format_scan_csv(scan));
  EXPECT_EQ(back.angles, scan.angles);
  EXPECT_EQ(back.ranges, scan.ranges);
}

TEST(ScanCsv, ErrorsNameTheLine) {
  EXPECT_NE(parse_error("").find("s.csv:1:"), std::string::npos);
  EXPECT_NE(parse_error("0.1,2.0\n").find("header"), std::string::npos);
  EXPECT_NE(parse_error("range,angle\n0,1\n").find("s.csv:1:"), std::string::npos);
  EXPECT_NE(parse_error("angle,range\n0,1\n0.1,abc\n").find("s.csv:3:"), std::string::npos);
  EXPECT_NE(parse_error("angle,range\n0,1\n0.1,abc\n").find("not a number"), std::string::npos);
  EXPECT_NE(parse_error("angle,range\nx,1\n").find("s.csv:2:"), std::string::npos);
  EXPECT_NE(parse_error("angle,range\n0,1,2\n").find("s.csv:2:"), std::string::npos);
  EXPECT_NE(parse_error("angle,range\n0\n").find("s.csv:2:"), std::string::npos);
  EXPECT_NE(parse_error("angle,range\n0,1\n\n0.2,1\n").find("s.csv:3:"), std::string::npos);
  EXPECT_NE(parse_error("angle,range\n0.2,1\n0.1,1\n").find("s.csv:3: angles must be strictly increasing"),
            std::string::npos);
  EXPECT_NE(parse_error("angle,range\n0.2,1\n0.2,1\n").find("increasing"), std::string::npos);
  EXPECT_NE(parse_error("angle,range\nnan,1\n").find("s.csv:2:"), std::string::npos);
  EXPECT_NE(parse_error("angle,range\n,1\n").find("s.csv:2:"), std::string::npos);
}

TEST(ScanCsv, MissingFileIsAnError) { EXPECT_THROW(read_scan_csv("/nonexistent/dir/scan.csv"), Error); }

}  // namespace
}  // namespace topocut

namespace topocut {
namespace {

// Issue 28: a scan CSV is bounded by what the commands can do with it (64 MiB, about 4 million
// beams), no longer by the 1 MiB (45,000 beams) the quadratic merge of SMF needed.
TEST(ScanCsv, AScanOfSeveralMegabytesIsRead) {
  std::string text = "angle,range\n";
  const int beams = 200000;
  for (int i = 0; i < beams; ++i) text += std::to_string(-3.0 + 6.0 * i / beams) + ",4.25\n";
  ASSERT_GT(text.size(), 2u << 20);  // twice the old limit and more
  const std::string path = ::testing::TempDir() + "/topocut_large_scan.csv";
  { std::ofstream(path, std::ios::binary) << text; }
  EXPECT_EQ(read_scan_csv(path).size(), static_cast<std::size_t>(beams));
  std::remove(path.c_str());
}

}  // namespace
}  // namespace topocut
