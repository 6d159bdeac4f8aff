#include "topocut/scan/scan_csv.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <system_error>
#include <vector>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"

namespace topocut {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// std::from_chars is locale-independent (unlike strtod) and accepts nan/inf; it rejects a leading
// '+', which people do write, so that is allowed here by hand.
bool parse_double(std::string_view field, double& value) {
  field = trim(field);
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  if (field.empty()) return false;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  return error == std::errc() && end == field.data() + field.size();
}

std::string where(const std::string& source, std::size_t line) {
  return source + ":" + std::to_string(line) + ": ";
}

}  // namespace

Scan parse_scan_csv(const std::string& text, const std::string& source) {
  std::vector<std::string_view> lines;
  {
    std::string_view rest(text);
    while (!rest.empty()) {
      const std::size_t newline = rest.find('\n');
      lines.push_back(rest.substr(0, newline));
      if (newline == std::string_view::npos) break;
      rest.remove_prefix(newline + 1);
    }
  }
  // Trailing blank lines are harmless; blank lines between beams would shift beam indices.
  while (!lines.empty() && trim(lines.back()).empty()) lines.pop_back();
  if (lines.empty()) throw Error(where(source, 1) + "the scan file is empty; expected the header 'angle,range'");

  std::string_view header = trim(lines[0]);
  if (header.size() >= 3 && static_cast<unsigned char>(header[0]) == 0xEF &&
      static_cast<unsigned char>(header[1]) == 0xBB && static_cast<unsigned char>(header[2]) == 0xBF)
    header.remove_prefix(3);  // UTF-8 byte order mark written by some spreadsheet programs
  const std::size_t comma = header.find(',');
  if (comma == std::string_view::npos || trim(header.substr(0, comma)) != "angle" ||
      trim(header.substr(comma + 1)) != "range")
    throw Error(where(source, 1) + "expected the header 'angle,range', got '" + std::string(header) + "'");

  Scan scan;
  scan.angles.reserve(lines.size() - 1);
  scan.ranges.reserve(lines.size() - 1);
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const std::size_t line_number = k + 1;
    const std::string_view line = trim(lines[k]);
    if (line.empty())
      throw Error(where(source, line_number) + "empty line inside the scan (every row is one beam)");
    const std::size_t c = line.find(',');
    if (c == std::string_view::npos || line.find(',', c + 1) != std::string_view::npos)
      throw Error(where(source, line_number) + "expected two fields 'angle,range', got '" + std::string(line) + "'");
    double angle = 0.0, range = 0.0;
    if (!parse_double(line.substr(0, c), angle))
      throw Error(where(source, line_number) + "the angle '" + std::string(trim(line.substr(0, c))) +
                  "' is not a number");
    if (!parse_double(line.substr(c + 1), range))
      throw Error(where(source, line_number) + "the range '" + std::string(trim(line.substr(c + 1))) +
                  "' is not a number");
    if (!std::isfinite(angle))
      throw Error(where(source, line_number) + "the angle must be finite, got '" +
                  std::string(trim(line.substr(0, c))) + "'");
    if (!scan.angles.empty() && !(angle > scan.angles.back()))
      throw Error(where(source, line_number) + "angles must be strictly increasing, but " + std::to_string(angle) +
                  " follows " + std::to_string(scan.angles.back()));
    scan.angles.push_back(angle);
    scan.ranges.push_back(range);
  }
  return scan;
}

Scan read_scan_csv(const std::string& path) {
  return parse_scan_csv(read_input_file(path, "scan file", kMaxScanCsvBytes, /*allow_stdin=*/true), path);
}

std::string format_scan_csv(const Scan& scan) {
  validate(scan);
  std::string out = "angle,range\n";
  char buffer[64];
  for (std::size_t i = 0; i < scan.size(); ++i) {
    auto r = std::to_chars(buffer, buffer + sizeof buffer, scan.angles[i]);
    out.append(buffer, r.ptr);
    out.push_back(',');
    r = std::to_chars(buffer, buffer + sizeof buffer, scan.ranges[i]);
    out.append(buffer, r.ptr);
    out.push_back('\n');
  }
  return out;
}

}  // namespace topocut
