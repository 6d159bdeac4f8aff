#include "topocut/core/option_table.h"

#include <charconv>
#include <cmath>

#include "topocut/core/error.h"
#include "topocut/core/value_ranges.h"

namespace topocut {

void check_option_value(OptionRange range, double value, const std::string& shown) {
  switch (range) {
    case OptionRange::kPositive:
      if (!std::isfinite(value) || value <= 0.0) throw Error(shown + " must be a positive number");
      break;
    case OptionRange::kNonNegative:
      if (!std::isfinite(value) || value < 0.0) throw Error(shown + " must be a non-negative number");
      break;
    case OptionRange::kFraction:
      if (!(value > 0.0 && value <= 1.0)) throw Error(shown + " must be a factor in (0, 1]");
      break;
    case OptionRange::kGreyLevel:
      if (!(value >= 0.0 && value <= 255.0) || value != std::floor(value))
        throw Error(shown + " must be a grey level, a whole number in 0..255");
      break;
    case OptionRange::kShare:
      if (!(value >= 0.0 && value <= 1.0)) throw Error(shown + " must be a share in [0, 1]");
      break;
    case OptionRange::kShareBelowOne:
      if (!(value >= 0.0 && value < 1.0)) throw Error(shown + " must be a share in [0, 1)");
      break;
    case OptionRange::kCount:
      if (!(value >= 1.0 && value <= 1e9) || value != std::floor(value)) throw Error(shown + " must be a whole number >= 1");
      break;
    case OptionRange::kWholeNumber:
      if (!(value >= 0.0 && value <= 1e9) || value != std::floor(value)) throw Error(shown + " must be a whole number >= 0");
      break;
    case OptionRange::kLength: check_length(value, shown, /*zero_allowed=*/false); break;
    case OptionRange::kLengthOrZero: check_length(value, shown); break;
    case OptionRange::kArea: check_area(value, shown); break;
    case OptionRange::kResolution: check_resolution(value, shown); break;
    case OptionRange::kSwitch:
    case OptionRange::kAny:
      break;
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
