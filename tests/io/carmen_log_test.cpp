#include "topocut/io/carmen_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <zlib.h>

#include "topocut/core/error.h"

namespace topocut {
namespace {

namespace fs = std::filesystem;

const char* const kSmallLog =
    "# message formats defined: PARAM SYNC ODOM FLASER\n"
    "PARAM robot_frontlaser_offset 0.0 nohost 0\n"
    "ODOM 0.1 0.2 0.3 0 0 0 1.0 host 1.0\n"
    "FLASER 3 1.5 2.0 2.5 1.0 -2.0 0.5 1.1 -2.1 0.6 12.5 host 12.6\n"
    "\n"
    "ODOM 0.1 0.2 0.3 0 0 0 1.0 host 1.0\r\n"
    "FLASER 5 1 nan 3 4 5 -0.5 0.25 -3.0 0 0 0 13.5 host 13.6\r\n";

std::string error_of(const std::string& text) {
  try {
    parse_carmen_log(text, "small.log");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

class CarmenLogFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("topocut_carmen_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

void write_plain(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

void write_gzip(const std::string& path, const std::string& text) {
  gzFile file = gzopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  ASSERT_EQ(gzwrite(file, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
  ASSERT_EQ(gzclose(file), Z_OK);
}

TEST(CarmenLog, ParsesFlaserMessagesAndSkipsTheRest) {
  const CarmenLog log = parse_carmen_log(kSmallLog, "small.log");
  ASSERT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.lines, 7u);
  EXPECT_EQ(log.skipped_messages.at("ODOM"), 2u);
  EXPECT_EQ(log.skipped_messages.at("PARAM"), 1u);
  EXPECT_EQ(log.skipped_messages.size(), 2u);
  EXPECT_FALSE(log.truncated_last_line);

  const CarmenLaserScan& a = log.scans[0];
  EXPECT_EQ(a.ranges, (std::vector<double>{1.5, 2.0, 2.5}));
  EXPECT_DOUBLE_EQ(a.pose.x, 1.0);
  EXPECT_DOUBLE_EQ(a.pose.y, -2.0);
  EXPECT_DOUBLE_EQ(a.pose.theta, 0.5);
  EXPECT_DOUBLE_EQ(a.odometry.x, 1.1);
  EXPECT_DOUBLE_EQ(a.odometry.theta, 0.6);
  EXPECT_DOUBLE_EQ(a.timestamp, 12.5);
  EXPECT_EQ(a.line, 4u);
  // Three beams over 180°: −90°, 0°, +90°.
  EXPECT_DOUBLE_EQ(a.start_angle, -M_PI / 2);
  EXPECT_DOUBLE_EQ(a.angle_step, M_PI / 2);

  const CarmenLaserScan& b = log.scans[1];
  ASSERT_EQ(b.ranges.size(), 5u);
  EXPECT_TRUE(std::isnan(b.ranges[1]));  // NaN ranges stay in place as invalid readings
  EXPECT_DOUBLE_EQ(b.ranges[4], 5.0);
  EXPECT_DOUBLE_EQ(b.angle_step, M_PI / 4);
  EXPECT_DOUBLE_EQ(b.pose.theta, -3.0);
  EXPECT_EQ(b.line, 7u);
}

TEST(CarmenLog, MalformedLinesNameTheLine) {
  const std::string head = "PARAM a b\nODOM 1 2 3\n";
  EXPECT_NE(error_of(head + "FLASER 3 1 2 x 0 0 0 0 0 0 1 h 1\n").find("small.log:3:"), std::string::npos);
  EXPECT_NE(error_of(head + "FLASER 3 1 2 x 0 0 0 0 0 0 1 h 1\n").find("range 3 'x'"), std::string::npos);
  EXPECT_NE(error_of(head + "FLASER 3 1 2 3 0 0 0 0 0\n").find("small.log:3:"), std::string::npos);
  EXPECT_NE(error_of("FLASER three 1 2 3 0 0 0 0 0 0\n").find("not an integer"), std::string::npos);
  EXPECT_NE(error_of("FLASER 1 1 0 0 0 0 0 0\n").find("outside"), std::string::npos);
  EXPECT_NE(error_of("FLASER -4 1 0 0 0 0 0 0\n").find("outside"), std::string::npos);
  EXPECT_NE(error_of("FLASER 999999999999 1 2\n").find("outside"), std::string::npos);
  EXPECT_NE(error_of("FLASER 2 1 2 0 0 zero 0 0 0 1 h 1\n").find("pose value 'zero'"), std::string::npos);
  EXPECT_NE(error_of("FLASER 2 1 2 0 0 0 0 0 0 later h 1\n").find("timestamp"), std::string::npos);
  EXPECT_NE(error_of("FLASER\n").find("small.log:1:"), std::string::npos);
  // A well-formed log has no error at all.
  EXPECT_EQ(error_of(kSmallLog), "");
}

TEST(CarmenLog, IncompleteLastLineIsDroppedAndFlagged) {
  const std::string good = "FLASER 2 1 2 0 0 0 0 0 0 1 h 1\n";
  // Cut in the middle of the pose: without the newline the line cannot be trusted.
  const CarmenLog cut = parse_carmen_log(good + "FLASER 2 1 2 0 0 0.2", "x");
  EXPECT_EQ(cut.scans.size(), 1u);
  EXPECT_TRUE(cut.truncated_last_line);
  // Cut after the pose but before the trailing fields: still dropped (the pose may be cut).
  const CarmenLog cut2 = parse_carmen_log(good + "FLASER 2 1 2 0 0 0 0 0 0", "x");
  EXPECT_EQ(cut2.scans.size(), 1u);
  EXPECT_TRUE(cut2.truncated_last_line);
  // A complete last line that merely lacks its newline is kept.
  const CarmenLog whole = parse_carmen_log(good + "FLASER 2 1 2 0 0 0 0 0 0 1 h 1", "x");
  EXPECT_EQ(whole.scans.size(), 2u);
  EXPECT_FALSE(whole.truncated_last_line);
  // The same cut line in the middle of the log is an error.
  EXPECT_THROW(parse_carmen_log("FLASER 2 1 2 0 0 0.2\n" + good, "x"), Error);
}

TEST(CarmenLog, NonFinitePosesAreDroppedWithTheirLines) {
  const CarmenLog log = parse_carmen_log(
      "FLASER 2 1 2 nan 0 0 0 0 0 1 h 1\n"
      "FLASER 2 1 2 0 inf 0 0 0 0 1 h 1\n"
      "FLASER 2 1 2 0 0 -inf 0 0 0 1 h 1\n"
      "FLASER 2 1 2 5 6 0.1 nan nan nan 1 h 1\n",
      "x");
  ASSERT_EQ(log.scans.size(), 1u);  // a non-finite odometry does not matter
  EXPECT_DOUBLE_EQ(log.scans[0].pose.x, 5.0);
  EXPECT_EQ(log.dropped_lines, (std::vector<std::size_t>{1, 2, 3}));
}

TEST(CarmenLog, EmptyLogsAndLogsWithoutLaser) {
  const CarmenLog empty = parse_carmen_log("", "x");
  EXPECT_TRUE(empty.scans.empty());
  EXPECT_EQ(empty.lines, 0u);
  const CarmenLog odom = parse_carmen_log("ODOM 1 2 3 0 0 0 1 h 1\nODOM 1 2 3 0 0 0 1 h 1\n\x01\x02 binary\n", "x");
  EXPECT_TRUE(odom.scans.empty());
  EXPECT_EQ(odom.skipped_messages.at("ODOM"), 2u);
  EXPECT_EQ(odom.skipped_messages.at("(unreadable)"), 1u);
}

TEST(CarmenLog, MaximumRangeRule) {
  // Three readings at 50 m (the largest value): the laser saturates there.
  const std::string saturated = "FLASER 4 50 1 50 2 0 0 0 0 0 0 1 h 1\nFLASER 2 50 49.5 0 0 0 0 0 0 1 h 1\n";
  const CarmenLog a = parse_carmen_log(saturated, "x");
  EXPECT_TRUE(a.max_range_detected);
  EXPECT_DOUBLE_EQ(a.max_range, 50.0 - 0.1);
  // Only one reading at the largest value: a real hit, so the hard limit applies.
  const CarmenLog b = parse_carmen_log("FLASER 4 30 1 20 2 0 0 0 0 0 0 1 h 1\n", "x");
  EXPECT_FALSE(b.max_range_detected);
  EXPECT_DOUBLE_EQ(b.max_range, 80.0);
  // Saturation beyond the hard limit (SICK mm mode, 81.83 m): the hard limit applies.
  const CarmenLog c = parse_carmen_log("FLASER 4 81.83 1 81.83 81.83 0 0 0 0 0 0 1 h 1\n", "x");
  EXPECT_DOUBLE_EQ(c.max_range, 80.0);
  // A fixed threshold wins.
  CarmenReadOptions fixed;
  fixed.max_range = 10.0;
  EXPECT_DOUBLE_EQ(parse_carmen_log(saturated, "x", fixed).max_range, 10.0);
  fixed.max_range = -1.0;
  EXPECT_THROW(parse_carmen_log(saturated, "x", fixed), Error);
}

TEST(CarmenLog, MutatedLogsParseOrFailCleanly) {
  // Random edits of a valid log: every outcome is a parsed log or an Error, never a crash or any
  // other exception; parsed scans always have their announced beam count and a finite pose.
  std::mt19937 rng(29);
  const std::string alphabet = "0123456789 .-+eEnaifFLASERODM\n\t#x";
  const std::string base = std::string(kSmallLog) + "FLASER 4 1 2 3 4 0 0 0 0 0 0 1 h 1\n";
  int parsed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = base;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0: text[at] = alphabet[rng() % alphabet.size()]; break;
        case 1: text.erase(at, 1 + rng() % 8); break;
        default: text.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
      }
      if (text.empty()) text = "x";
    }
    try {
      const CarmenLog log = parse_carmen_log(text, "m");
      ++parsed;
      for (const auto& scan : log.scans) {
        ASSERT_GE(scan.ranges.size(), 2u);
        ASSERT_TRUE(std::isfinite(scan.pose.x) && std::isfinite(scan.pose.y) && std::isfinite(scan.pose.theta));
      }
      ASSERT_GT(log.max_range, 0.0);
    } catch (const Error&) {
    }
  }
  EXPECT_GT(parsed, 100);  // many edits leave a readable log
}

TEST_F(CarmenLogFile, ReadsPlainAndGzipFilesAlike) {
  write_plain(path("plain.log"), kSmallLog);
  write_gzip(path("packed.log.gz"), kSmallLog);
  const CarmenLog plain = read_carmen_log(path("plain.log"));
  const CarmenLog packed = read_carmen_log(path("packed.log.gz"));
  ASSERT_EQ(plain.scans.size(), 2u);
  ASSERT_EQ(packed.scans.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(plain.scans[i].line, packed.scans[i].line);
    EXPECT_DOUBLE_EQ(plain.scans[i].pose.x, packed.scans[i].pose.x);
    EXPECT_EQ(plain.scans[i].ranges.size(), packed.scans[i].ranges.size());
  }
}

TEST_F(CarmenLogFile, FileErrorsNameThePath) {
  try {
    read_carmen_log(path("missing.log"));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.log"), std::string::npos);
  }
  EXPECT_THROW(read_carmen_log(dir_.string()), Error);
  write_plain(path("bad.log"), "ODOM 1 2 3\nFLASER 2 1 oops 0 0 0 0 0 0 1 h 1\n");
  try {
    read_carmen_log(path("bad.log"));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.log:2:"), std::string::npos) << e.what();
  }
  // A gzip stream cut in half.
  std::string big;
  for (int i = 0; i < 2000; ++i) big += "FLASER 2 1 2 " + std::to_string(i) + " 0 0 0 0 0 1 h 1\n";
  write_gzip(path("whole.gz"), big);
  std::ifstream in(path("whole.gz"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  write_plain(path("cut.gz"), bytes.substr(0, bytes.size() / 2));
  EXPECT_THROW(read_carmen_log(path("cut.gz")), Error);
  EXPECT_EQ(read_carmen_log(path("whole.gz")).scans.size(), 2000u);
}

TEST(CarmenLog, SharedIntelLog) {
  const std::string path = std::string(TOPOCUT_SHARED_DIR "/datasets/carmen/intel-corrected.log.gz");
  if (!fs::exists(path)) GTEST_SKIP() << "shared dataset not found: " << path;
  const CarmenLog log = read_carmen_log(path);
  ASSERT_EQ(log.scans.size(), 910u);
  for (const auto& scan : log.scans) ASSERT_EQ(scan.ranges.size(), 180u);
  // Intel saturates at 81.83 m, beyond the SICK's 80 m: the hard limit applies.
  EXPECT_TRUE(log.max_range_detected);
  EXPECT_DOUBLE_EQ(log.max_range, 80.0);
  EXPECT_DOUBLE_EQ(log.scans[0].pose.x, 0.600266);
  EXPECT_EQ(log.skipped_messages.at("ODOM"), 14541u);
}

}  // namespace
}  // namespace topocut
