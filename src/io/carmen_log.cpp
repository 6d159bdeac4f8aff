#include "topocut/io/carmen_log.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <system_error>

#include <zlib.h>

#include "topocut/core/error.h"

namespace topocut {

namespace {

constexpr std::size_t kMaxBeams = 100000;
constexpr std::size_t kPoseValues = 6;  // x y theta odom_x odom_y odom_theta

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

void split(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
}

// Parses a whole token as a double (nan and inf allowed, a leading '+' too).
bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

// A malformed line: the reason, to be prefixed with source and line.
struct Malformed {
  std::string reason;
};

constexpr std::size_t kTrailingValues = 3;  // timestamp host logger_timestamp

CarmenLaserScan parse_flaser(const std::vector<std::string_view>& tokens, double step, bool complete,
                             Malformed& error) {
  CarmenLaserScan scan;
  if (tokens.size() < 2) {
    error.reason = "FLASER message without a beam count";
    return scan;
  }
  long long n = 0;
  const auto [end, ec] = std::from_chars(tokens[1].data(), tokens[1].data() + tokens[1].size(), n);
  if (ec != std::errc() || end != tokens[1].data() + tokens[1].size()) {
    error.reason = "FLASER beam count '" + std::string(tokens[1]) + "' is not an integer";
    return scan;
  }
  if (n < 2 || static_cast<std::size_t>(n) > kMaxBeams) {
    error.reason = "FLASER beam count " + std::to_string(n) + " is outside 2.." + std::to_string(kMaxBeams);
    return scan;
  }
  const auto beams = static_cast<std::size_t>(n);
  if (tokens.size() < 2 + beams + kPoseValues) {
    error.reason = "FLASER announces " + std::to_string(beams) + " ranges and a 6-value pose but the line has " +
                   std::to_string(tokens.size() - 2) + " values";
    return scan;
  }
  // A last line without its newline may have been cut anywhere, even inside the pose: it is trusted
  // only if every field up to the logger timestamp is there.
  if (!complete && tokens.size() < 2 + beams + kPoseValues + kTrailingValues) {
    error.reason = "incomplete last line";
    return scan;
  }
  scan.ranges.resize(beams);
  for (std::size_t i = 0; i < beams; ++i) {
    if (!parse_double(tokens[2 + i], scan.ranges[i])) {
      error.reason = "FLASER range " + std::to_string(i + 1) + " '" + std::string(tokens[2 + i]) + "' is not a number";
      return scan;
    }
  }
  double pose[kPoseValues];
  for (std::size_t i = 0; i < kPoseValues; ++i) {
    if (!parse_double(tokens[2 + beams + i], pose[i])) {
      error.reason = "FLASER pose value '" + std::string(tokens[2 + beams + i]) + "' is not a number";
      return scan;
    }
  }
  scan.pose = {pose[0], pose[1], pose[2]};
  scan.odometry = {pose[3], pose[4], pose[5]};
  scan.timestamp = std::numeric_limits<double>::quiet_NaN();
  if (tokens.size() > 2 + beams + kPoseValues && !parse_double(tokens[2 + beams + kPoseValues], scan.timestamp)) {
    error.reason = "FLASER timestamp '" + std::string(tokens[2 + beams + kPoseValues]) + "' is not a number";
    return scan;
  }
  scan.angle_step = step / static_cast<double>(beams - 1);
  scan.start_angle = -step / 2.0;
  return scan;
}

void validate(const CarmenReadOptions& options) {
  if (!std::isfinite(options.max_range) || options.max_range < 0.0)
    throw Error("the maximum laser range must be a non-negative number of metres (0: detect), got " +
                std::to_string(options.max_range));
  if (!(options.hard_max_range > 0.0))
    throw Error("the hard maximum laser range must be positive, got " + std::to_string(options.hard_max_range));
  if (!std::isfinite(options.saturation_tolerance) || options.saturation_tolerance < 0.0)
    throw Error("the saturation tolerance must be a non-negative number of metres");
  if (!std::isfinite(options.field_of_view) || options.field_of_view <= 0.0 || options.field_of_view > 2.0 * M_PI)
    throw Error("the laser field of view must lie in (0, 2π] radians, got " + std::to_string(options.field_of_view));
}

// The no-return threshold, by the rule documented on CarmenReadOptions.
void choose_max_range(CarmenLog& log, const CarmenReadOptions& options) {
  if (options.max_range > 0.0) {
    log.max_range = options.max_range;
    return;
  }
  double largest = 0.0;
  for (const auto& scan : log.scans)
    for (double r : scan.ranges)
      if (std::isfinite(r)) largest = std::max(largest, r);
  std::size_t near_largest = 0;
  for (const auto& scan : log.scans)
    for (double r : scan.ranges)
      if (std::isfinite(r) && r >= largest - options.saturation_tolerance) ++near_largest;
  log.max_range = options.hard_max_range;
  if (largest > 0.0 && near_largest >= std::max<std::size_t>(options.saturation_count, 1)) {
    const double saturation = largest - options.saturation_tolerance;
    if (saturation > 0.0 && saturation < log.max_range) {
      log.max_range = saturation;
      log.max_range_detected = true;
    } else if (saturation >= log.max_range) {
      log.max_range_detected = true;  // saturates beyond the hard limit: the hard limit applies
    }
  }
}

}  // namespace

CarmenLog parse_carmen_log(std::string_view text, const std::string& source, const CarmenReadOptions& options) {
  validate(options);
  CarmenLog log;
  std::vector<std::string_view> tokens;
  std::size_t position = 0;
  std::size_t line_number = 0;
  while (position < text.size()) {
    const std::size_t newline = text.find('\n', position);
    const bool complete = newline != std::string_view::npos;
    const std::string_view line = text.substr(position, complete ? newline - position : std::string_view::npos);
    position = complete ? newline + 1 : text.size();
    ++line_number;
    split(line, tokens);
    if (tokens.empty() || tokens.front().front() == '#') continue;
    if (tokens.front() != "FLASER") {
      // Message names are short identifiers; anything else is counted as unreadable text.
      const bool name = tokens.front().size() <= 32 &&
                        std::all_of(tokens.front().begin(), tokens.front().end(),
                                    [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
      ++log.skipped_messages[name ? std::string(tokens.front()) : std::string("(unreadable)")];
      continue;
    }
    Malformed error;
    CarmenLaserScan scan = parse_flaser(tokens, options.field_of_view, complete, error);
    if (!error.reason.empty()) {
      if (!complete) {
        log.truncated_last_line = true;
        break;
      }
      throw Error(source + ":" + std::to_string(line_number) + ": " + error.reason);
    }
    scan.line = line_number;
    if (!std::isfinite(scan.pose.x) || !std::isfinite(scan.pose.y) || !std::isfinite(scan.pose.theta)) {
      log.dropped_lines.push_back(line_number);
      continue;
    }
    log.scans.push_back(std::move(scan));
  }
  log.lines = line_number;
  choose_max_range(log, options);
  return log;
}

CarmenLog read_carmen_log(const std::string& path, const CarmenReadOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error("cannot read log '" + path + "': no such file");
  if (fs::is_directory(path, ec)) throw Error("cannot read log '" + path + "': it is a directory");
  gzFile file = gzopen(path.c_str(), "rb");
  if (file == nullptr) throw Error("cannot open log '" + path + "'");
  gzbuffer(file, 1 << 17);
  std::string text;
  std::vector<char> chunk(1 << 17);
  while (true) {
    const int got = gzread(file, chunk.data(), static_cast<unsigned>(chunk.size()));
    if (got < 0) {
      int code = 0;
      const std::string message = gzerror(file, &code);
      gzclose(file);
      throw Error("cannot read log '" + path + "': " + message);
    }
    if (got == 0) break;
    text.append(chunk.data(), static_cast<std::size_t>(got));
  }
  // A gzip stream cut short reads as end of file; zlib reports it on close.
  const int closed = gzclose(file);
  if (closed == Z_BUF_ERROR) throw Error("cannot read log '" + path + "': the gzip data is truncated");
  if (closed != Z_OK) throw Error("cannot read log '" + path + "': the gzip data is corrupt");
  return parse_carmen_log(text, path, options);
}

}  // namespace topocut
