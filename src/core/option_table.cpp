#include "topocut/core/option_table.h"

#include <charconv>
#include <cmath>

#include "topocut/core/error.h"
#include "topocut/core/value_ranges.h"

namespace topocut {

bool option_value_in_range(OptionRange range, double value) {
  // Written so that NaN lies in no range.
  switch (range) {
    case OptionRange::kPositive: return std::isfinite(value) && value > 0.0;
    case OptionRange::kNonNegative: return std::isfinite(value) && value >= 0.0;
    case OptionRange::kFraction: return value > 0.0 && value <= 1.0;
    case OptionRange::kGreyLevel: return value >= 0.0 && value <= 255.0 && value == std::floor(value);
    case OptionRange::kShare: return value >= 0.0 && value <= 1.0;
    case OptionRange::kShareBelowOne: return value >= 0.0 && value < 1.0;
    case OptionRange::kCount: return value >= 1.0 && value <= 1e9 && value == std::floor(value);
    case OptionRange::kWholeNumber: return value >= 0.0 && value <= 1e9 && value == std::floor(value);
    case OptionRange::kSeed: return value >= 0.0 && value <= 4294967295.0 && value == std::floor(value);
    case OptionRange::kLength: return value > 0.0 && value <= kMaxLength;
    case OptionRange::kLengthOrZero: return value >= 0.0 && value <= kMaxLength;
    case OptionRange::kArea: return value >= 0.0 && value <= kMaxLength * kMaxLength;
    case OptionRange::kResolution: return value >= kMinResolution && value <= kMaxResolution;
    case OptionRange::kSwitch:
    case OptionRange::kAny: return true;
  }
  return true;
}

void check_option_value(OptionRange range, double value, const std::string& shown) {
  if (option_value_in_range(range, value)) return;
  switch (range) {
    case OptionRange::kPositive: throw Error(shown + " must be a positive number");
    case OptionRange::kNonNegative: throw Error(shown + " must be a non-negative number");
    case OptionRange::kFraction: throw Error(shown + " must be a factor in (0, 1]");
    case OptionRange::kGreyLevel: throw Error(shown + " must be a grey level, a whole number in 0..255");
    case OptionRange::kShare: throw Error(shown + " must be a share in [0, 1]");
    case OptionRange::kShareBelowOne: throw Error(shown + " must be a share in [0, 1)");
    case OptionRange::kCount: throw Error(shown + " must be a whole number >= 1");
    case OptionRange::kWholeNumber: throw Error(shown + " must be a whole number >= 0");
    case OptionRange::kSeed: throw Error(shown + " must be a whole number in 0..4294967295");
    // The library's own checks, which give the interval and unit.
    case OptionRange::kLength: check_length(value, shown, /*zero_allowed=*/false); break;
    case OptionRange::kLengthOrZero: check_length(value, shown); break;
    case OptionRange::kArea: check_area(value, shown); break;
    case OptionRange::kResolution: check_resolution(value, shown); break;
    case OptionRange::kSwitch:
    case OptionRange::kAny: break;
  }
}

double parse_option_number(const std::string& text, const std::string& shown) {
  // Decimal only, as people write numbers: no hexadecimal ("0x10"), no blanks around it, one optional
  // sign. from_chars reads "inf" and "nan" too; the row's range then refuses them, naming the value.
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+' && last - first > 1 && first[1] != '-') ++first;
  double value = 0.0;
  const auto [end, error] = std::from_chars(first, last, value, std::chars_format::general);
  if (first == last || error != std::errc() || end != last) throw Error(shown + " needs a number, not '" + text + "'");
  return value;
}

std::optional<bool> parse_switch_value(const std::string& text) {
  for (const char* on : {"y", "Y", "yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON"})
    if (text == on) return true;
  for (const char* off : {"n", "N", "no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF"})
    if (text == off) return false;
  return std::nullopt;
}

std::string switch_value_error(const std::string& shown, const std::string& value) {
  return shown + " is a switch: give true or false, not '" + value + "'";
}

std::string given_twice_error(const std::string& shown) { return shown + " is given twice"; }

std::string shortest_number(double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

std::string option_help_line(const std::string& name, const std::string& value_name, const std::string& help) {
  std::string left = "  --" + name + (value_name.empty() ? "" : " " + value_name);
  if (left.size() < 24) left += std::string(24 - left.size(), ' ');
  return left + " " + help + "\n";
}

}  // namespace topocut
