#pragma once
// Reading CARMEN laser logs (Radish data sets): FLASER messages with their corrected poses.
//   FLASER n r1 … rn x y theta odom_x odom_y odom_theta timestamp host logger_timestamp
// The n ranges spread evenly from −90° to +90° around the heading (beam i at −π/2 + i·π/(n−1)).
// Every other message type (ODOM, PARAM, NEFF, RLASER, ROBOTLASER1, comments, …) is skipped and
// counted. Files may be gzip-compressed or plain (zlib reads both).
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "topocut/core/option_table.h"

namespace topocut {

struct CarmenPose {
  double x = 0.0;      // metres
  double y = 0.0;      // metres
  double theta = 0.0;  // radians
};

struct CarmenLaserScan {
  // Metres, exactly as logged (NaN allowed). A beam is a hit when 0 < range < CarmenLog::max_range;
  // a range at or beyond max_range means "no return"; NaN or <= 0 is an invalid reading.
  std::vector<double> ranges;
  double start_angle = 0.0;  // radians, of beam 0 relative to the heading
  double angle_step = 0.0;   // radians between consecutive beams
  CarmenPose pose;           // corrected laser pose in the world (x y theta of the message)
  CarmenPose odometry;       // raw odometry pose
  double timestamp = 0.0;    // seconds; NaN when the message has no timestamp field
  std::size_t line = 0;      // 1-based line of the message in the log
};

struct CarmenLog {
  std::vector<CarmenLaserScan> scans;  // FLASER messages with finite poses, in log order
  // Readings >= max_range are "no return" (the laser's saturation value, see CarmenReadOptions).
  double max_range = 0.0;
  bool max_range_detected = false;     // true when max_range came from a saturation value in the log
  std::size_t lines = 0;               // lines read
  std::map<std::string, std::size_t> skipped_messages;  // other message types, by name, with counts
  std::vector<std::size_t> dropped_lines;  // FLASER lines dropped for a non-finite pose
  bool truncated_last_line = false;    // the last line had no newline and was incomplete: dropped
};

struct CarmenReadOptions {
  // > 0: readings at or beyond this many metres are "no return". 0: detect the saturation value.
  // Rule: let L be the largest finite range in the log; if at least `saturation_count` readings lie
  // within `saturation_tolerance` of L, the laser saturated there and max_range = L − tolerance;
  // otherwise no saturation is seen and max_range = hard_max_range. Either way max_range is at most
  // hard_max_range. (Intel and CSAIL saturate at 81.83/81.91 m, ACES at 50 m, FHW at 51.05–51.1 m.)
  double max_range = 0.0;
  double saturation_tolerance = 0.1;  // metres
  std::size_t saturation_count = 3;
  double hard_max_range = 80.0;       // metres: the SICK LMS 2xx's longest measurable range
  double field_of_view = 3.14159265358979323846;  // radians covered from the first to the last beam
  // Bounds on what a log may hold (docs/limits.md): the inflated text, and the laser readings kept
  // (the walls pipeline holds every one; the largest shared log has 164 k).
  std::uint64_t max_text_bytes = 1ull << 30;     // 1 GiB
  std::size_t max_total_beams = 5'000'000;
};

// The longest line a log may have: a FLASER message of 100000 readings of up to 40 characters.
inline constexpr std::size_t kMaxCarmenLineBytes = 4u << 20;

// Parses log text; `source` names it in errors ("source:line: problem"). Throws Error on a malformed
// FLASER message (beam count not an integer or < 2, a value count other than the announced ranges,
// the 6-value pose and optionally the timestamp or all of "timestamp host logger_timestamp", a
// non-numeric range, pose or timestamp) — except on an incomplete last line without a newline, which
// is dropped and flagged — on a line longer than kMaxCarmenLineBytes, more readings than
// options.max_total_beams, and on invalid options. Never throws for a log without FLASER messages: the result has no
// scans and says which messages it skipped.
CarmenLog parse_carmen_log(std::string_view text, const std::string& source = "log",
                           const CarmenReadOptions& options = {});

// Reads a log file, gzip-compressed or plain, inflating it as a stream (never whole in memory) and
// parsing it as parse_carmen_log. Throws Error naming the path if it is missing, not a regular file,
// unreadable, a corrupt gzip stream, or more than options.max_text_bytes of text.
CarmenLog read_carmen_log(const std::string& path, const CarmenReadOptions& options = {});

// The reading options as people give them (the walls command): max-range.
const std::vector<OptionRow<CarmenReadOptions>>& carmen_read_option_rows();

}  // namespace topocut
