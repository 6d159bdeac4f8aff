#pragma once
// Options as people give them (command-line flags, --config keys, benchmark arguments, Python
// keywords), one row per option: its name, help line, range and the field it sets. A module defines
// its table once, next to its options struct; every front end builds its parser from that table, so
// the same name means the same thing, with the same default and the same check, everywhere.
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace topocut {

// What a value must be; a switch takes no value. The lengths, areas and resolutions are those of
// core/value_ranges.h, so that an option and the library's own check agree on the range and message.
enum class OptionRange {
  kSwitch,
  kPositive,
  kNonNegative,
  kFraction,
  kGreyLevel,
  kLength,          // metres, (0, kMaxLength]
  kLengthOrZero,    // metres, [0, kMaxLength]
  kArea,            // square metres, [0, kMaxLength^2]
  kResolution,      // metres per cell, [kMinResolution, kMaxResolution]
  kShare,           // [0, 1]
  kShareBelowOne,   // [0, 1)
  kCount,           // a whole number >= 1 (rounds, updates in a row)
  kWholeNumber,     // a whole number >= 0
  kSeed,            // a random seed: a whole number in 0..2^32-1
  kAny,
};

// Whether a row of range holds a whole number (Python types it int).
inline bool is_whole_number(OptionRange range) {
  return range == OptionRange::kGreyLevel || range == OptionRange::kCount || range == OptionRange::kWholeNumber ||
         range == OptionRange::kSeed;
}

template <typename Target>
struct OptionRow {
  std::string name;        // long name without dashes, e.g. "door-width" (Python: door_width)
  std::string value_name;  // shown in the help, e.g. "M"; empty for a switch
  std::string help;        // one line; front ends add the default from get
  OptionRange range = OptionRange::kAny;
  std::function<double(const Target&)> get;  // the value in target (numbers; a switch: 0 or 1)
  std::function<void(Target&, double)> set;  // sets the value (a switch: 1 on, 0 off); may throw Error

  bool is_switch() const { return range == OptionRange::kSwitch; }
};

// Throws Error "<shown> must be ..." unless value lies in range (kAny: the set function checks).
void check_option_value(OptionRange range, double value, const std::string& shown);
// Whether value lies in range (check_option_value() would not throw).
bool option_value_in_range(OptionRange range, double value);

// The whole of text as a decimal number (a sign, digits, a point, an exponent; "inf" and "nan" are
// read, for the range to refuse by name): the one reader of numbers given as text, for the command
// line, --config, the ROS node and the benchmarks. Error "<shown> needs a number, not '<text>'"
// otherwise (hexadecimal, blanks, trailing characters, out of double's range).
double parse_option_number(const std::string& text, const std::string& shown);

// A switch's value given as text, as YAML 1.1 reads a boolean (true/false, yes/no, on/off, y/n in
// lower, Capitalised or UPPER case): what --config and the ROS node's service take; nullopt for any
// other text.
std::optional<bool> parse_switch_value(const std::string& text);

// The messages every front end gives for an option: a switch given a value that is not true or
// false, and an option given twice.
std::string switch_value_error(const std::string& shown, const std::string& value);
std::string given_twice_error(const std::string& shown);

// The shortest text that reads back as value ("0.05", not "0.050000000000000003"), for help lines.
std::string shortest_number(double value);

// One line of a help text: "  --name VALUE", padded to the help column, then help.
std::string option_help_line(const std::string& name, const std::string& value_name, const std::string& help);

// Checks value against row's range, then sets it; shown names the option in errors.
template <typename Target>
void set_option(const OptionRow<Target>& row, Target& target, double value, const std::string& shown) {
  check_option_value(row.range, value, shown);
  row.set(target, value);
}

// A row for a number or switch field of Target (double, int, bool; a bool is a switch).
template <typename Target, typename Value>
OptionRow<Target> field_row(std::string name, std::string value_name, OptionRange range, Value Target::*field,
                            std::string help) {
  return {std::move(name), std::move(value_name), std::move(help), range,
          [field](const Target& t) { return static_cast<double>(t.*field); },
          [field](Target& t, double v) {
            if constexpr (std::is_same_v<Value, bool>) {
              t.*field = v != 0.0;
            } else {
              t.*field = static_cast<Value>(v);
            }
          }};
}
// A switch for a bool field.
template <typename Target>
OptionRow<Target> switch_row(std::string name, bool Target::*field, std::string help) {
  return field_row(std::move(name), "", OptionRange::kSwitch, field, std::move(help));
}
// The row of a number inside a part of Target (t.*part.*field), such as a ratio held in a small
// struct that two option structs share.
template <typename Target, typename Part, typename Value>
OptionRow<Target> field_row(std::string name, std::string value_name, OptionRange range, Part Target::*part,
                            Value Part::*field, std::string help) {
  return {std::move(name), std::move(value_name), std::move(help), range,
          [part, field](const Target& t) { return static_cast<double>(t.*part.*field); },
          [part, field](Target& t, double v) { t.*part.*field = static_cast<Value>(v); }};
}
// A switch that sets the field false when on (--keep-small-holes for absorb_small_holes).
template <typename Target>
OptionRow<Target> inverted_switch_row(std::string name, bool Target::*field, std::string help) {
  return {std::move(name), "", std::move(help), OptionRange::kSwitch,
          [field](const Target& t) { return t.*field ? 0.0 : 1.0; },
          [field](Target& t, double on) { t.*field = on == 0.0; }};
}

// The rows of a part of Outer (a sub-struct's table as rows of the struct holding it): part(outer)
// is the part's reference, for a const and a non-const Outer (a generic lambda).
template <typename Outer, typename Inner, typename Part>
std::vector<OptionRow<Outer>> rows_within(const std::vector<OptionRow<Inner>>& rows, Part part) {
  std::vector<OptionRow<Outer>> out;
  for (const OptionRow<Inner>& row : rows)
    out.push_back({row.name, row.value_name, row.help, row.range,
                   [get = row.get, part](const Outer& o) { return get(part(o)); },
                   [set = row.set, part](Outer& o, double v) { set(part(o), v); }});
  return out;
}

// Throws Error "--NAME must be ..." for the first row whose value in target lies outside its range:
// an options struct's validate() through its table, so that each range is written once. The name is
// made only for the error (validate() runs on every call of a stage).
template <typename Target>
void check_option_rows(const std::vector<OptionRow<Target>>& rows, const Target& target) {
  for (const OptionRow<Target>& row : rows) {
    const double value = row.get(target);
    if (!option_value_in_range(row.range, value)) check_option_value(row.range, value, "--" + row.name);
  }
}

// The row named name, or nullptr.
template <typename Target>
const OptionRow<Target>* find_option(const std::vector<OptionRow<Target>>& rows, const std::string& name) {
  for (const OptionRow<Target>& row : rows)
    if (row.name == name) return &row;
  return nullptr;
}

}  // namespace topocut
