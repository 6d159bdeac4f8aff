#include "topocut/core/option_table.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

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
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) throw Error(shown + " needs a number, not '" + text + "'");
  return value;
}

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
