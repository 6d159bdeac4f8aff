#include "topocut/io/carmen_log.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>
#include <utility>

#include <zlib.h>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"

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

// Whether the values after the count are n ranges, the pose and nothing, a timestamp, or all three
// trailing fields with a host name (not a number). Why so strict: a line with more ranges than it
// announces would otherwise be read with its pose taken from range values.
bool value_count_matches(const std::vector<std::string_view>& tokens, std::size_t beams, bool complete) {
  const std::size_t values = tokens.size() - 2, base = beams + kPoseValues;
  if (values < base) return false;
  if (values <= base + 1) return true;
  if (!complete && values < base + kTrailingValues) return true;  // cut short: judged as incomplete
  double ignored = 0.0;
  return values == base + kTrailingValues && !parse_double(tokens[2 + base + 1], ignored);
}

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
  if (!value_count_matches(tokens, beams, complete)) {
    error.reason = "FLASER announces " + std::to_string(beams) + " ranges but the line has " +
                   std::to_string(tokens.size() - 2) + " values (expected " + std::to_string(beams + kPoseValues) +
                   " to " + std::to_string(beams + kPoseValues + kTrailingValues) + ": ranges, pose, timestamp host logger_timestamp)";
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

namespace {

// Parses a log line by line, so that read_carmen_log can feed it from a stream of any length.
class LogParser {
 public:
  LogParser(const std::string& source, const CarmenReadOptions& options) : source_(source), options_(options) {
    validate(options);
  }

  // Parses one line (without its newline); complete is false for a last line without a newline.
  void add(std::string_view line, bool complete) {
    ++log_.lines;
    split(line, tokens_);
    if (tokens_.empty() || tokens_.front().front() == '#') return;
    if (tokens_.front() != "FLASER") {
      // Message names are short identifiers; anything else is counted as unreadable text.
      const bool name = tokens_.front().size() <= 32 &&
                        std::all_of(tokens_.front().begin(), tokens_.front().end(),
                                    [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
      ++log_.skipped_messages[name ? std::string(tokens_.front()) : std::string("(unreadable)")];
      return;
    }
    Malformed error;
    CarmenLaserScan scan = parse_flaser(tokens_, options_.field_of_view, complete, error);
    if (!error.reason.empty()) {
      if (complete) throw Error(where() + error.reason);
      log_.truncated_last_line = true;
      return;
    }
    scan.line = log_.lines;
    if (!std::isfinite(scan.pose.x) || !std::isfinite(scan.pose.y) || !std::isfinite(scan.pose.theta)) {
      log_.dropped_lines.push_back(log_.lines);
      return;
    }
    beams_ += scan.ranges.size();
    if (beams_ > options_.max_total_beams)
      throw Error(where() + "the log holds more than " + std::to_string(options_.max_total_beams) +
                  " laser readings, the limit (CarmenReadOptions::max_total_beams)");
    log_.scans.push_back(std::move(scan));
  }

  // "source:line: " of the line last added, or (next) of the line about to be.
  std::string where(bool next = false) const {
    return source_ + ":" + std::to_string(log_.lines + (next ? 1 : 0)) + ": ";
  }

  CarmenLog finish() {
    choose_max_range(log_, options_);
    return std::move(log_);
  }

 private:
  const std::string& source_;
  const CarmenReadOptions& options_;
  CarmenLog log_;
  std::vector<std::string_view> tokens_;
  std::size_t beams_ = 0;
};

void check_line_length(std::size_t length, const LogParser& parser) {
  if (length > kMaxCarmenLineBytes)
    throw Error(parser.where(/*next=*/true) + "a line longer than " + byte_size_text(kMaxCarmenLineBytes) +
                " (a FLASER message of 100000 readings needs less): not a CARMEN log");
}

}  // namespace

CarmenLog parse_carmen_log(std::string_view text, const std::string& source, const CarmenReadOptions& options) {
  LogParser parser(source, options);
  std::size_t position = 0;
  while (position < text.size()) {
    const std::size_t newline = text.find('\n', position);
    const bool complete = newline != std::string_view::npos;
    const std::size_t length = complete ? newline - position : text.size() - position;
    check_line_length(length, parser);
    parser.add(text.substr(position, length), complete);
    position += length + (complete ? 1 : 0);
  }
  return parser.finish();
}

namespace {

// Passes the complete lines of a chunk to the parser; the unfinished rest stays in pending.
void feed(std::string_view chunk, std::string& pending, LogParser& parser) {
  while (!chunk.empty()) {
    const std::size_t newline = chunk.find('\n');
    const std::size_t length = newline == std::string_view::npos ? chunk.size() : newline;
    check_line_length(pending.size() + length, parser);
    if (newline == std::string_view::npos) {
      pending.append(chunk);
      return;
    }
    if (pending.empty()) {
      parser.add(chunk.substr(0, length), true);
    } else {
      pending.append(chunk.substr(0, length));
      parser.add(pending, true);
      pending.clear();
    }
    chunk.remove_prefix(length + 1);
  }
}

}  // namespace

CarmenLog read_carmen_log(const std::string& path, const CarmenReadOptions& options) {
  // Regular files only: a FIFO would block, /dev/zero never end.
  require_regular_file(path, "log");
  LogParser parser(path, options);
  gzFile file = gzopen(path.c_str(), "rb");
  if (file == nullptr) throw Error("cannot open log '" + path + "'");
  gzbuffer(file, 1 << 17);
  std::string pending;  // the current line so far, bounded by kMaxCarmenLineBytes
  std::vector<char> chunk(1 << 17);
  std::uint64_t total = 0;
  try {
    while (true) {
      const int got = gzread(file, chunk.data(), static_cast<unsigned>(chunk.size()));
      if (got < 0) {
        int code = 0;
        throw Error("cannot read log '" + path + "': " + gzerror(file, &code));
      }
      if (got == 0) break;
      total += static_cast<std::uint64_t>(got);
      if (total > options.max_text_bytes)
        throw Error("cannot read log '" + path + "': more than " + byte_size_text(options.max_text_bytes) +
                    " of text (inflated), the limit (CarmenReadOptions::max_text_bytes)");
      feed(std::string_view(chunk.data(), static_cast<std::size_t>(got)), pending, parser);
    }
  } catch (...) {
    gzclose(file);
    throw;
  }
  // A gzip stream cut short reads as end of file; zlib reports it on close.
  const int closed = gzclose(file);
  if (closed == Z_BUF_ERROR) throw Error("cannot read log '" + path + "': the gzip data is truncated");
  if (closed != Z_OK) throw Error("cannot read log '" + path + "': the gzip data is corrupt");
  if (!pending.empty()) parser.add(pending, false);
  return parser.finish();
}

const std::vector<OptionRow<CarmenReadOptions>>& carmen_read_option_rows() {
  static const std::vector<OptionRow<CarmenReadOptions>> rows = {
      field_row("max-range", "M", OptionRange::kNonNegative, &CarmenReadOptions::max_range,
                "readings at or beyond this range (m) are no return; 0 detects the laser's saturation value"),
  };
  return rows;
}

}  // namespace topocut
