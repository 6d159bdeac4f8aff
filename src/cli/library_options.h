#pragma once
// The library's option tables (topocut/core/option_table.h) as program_options: a command adds the
// rows it takes, with the defaults it uses shown in its help, and reads back what the command line
// or its --config file gave. The names, help lines and checks are the library's, defined once.
#include <optional>
#include <span>
#include <typeinfo>
#include <vector>

#include "cli/command.h"
#include "topocut/core/option_choice.h"
#include "topocut/core/option_table.h"
#include "topocut/core/option_text.h"
#include "topocut/io/map_load_flags.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segment_switches.h"

namespace topocut::cli {

// A double option bound to field, its default field's value shown in its shortest form ("(=0.05)",
// not "(=0.050000000000000003)").
inline po::typed_value<double>* number_value(double& field) {
  return po::value<double>(&field)->default_value(field, shortest_number(field));
}

// Whether row is a switch its struct has on (--windowed): given as --name false, since a bare --name
// could not turn it off; in every command alike, whatever that command's default.
// The struct's own defaults are made once: a SegmentSettings holds the shipped merge model, whose
// copy per row cost more instructions than the rest of a small map's start-up.
template <typename Target>
bool switch_on_by_default(const OptionRow<Target>& row) {
  static const Target struct_defaults{};
  return row.is_switch() && row.get(struct_defaults) != 0.0;
}

// Adds rows to options: a switch as a bool_switch (one on by default takes true or false, as --config
// and the ROS node do), a number as text (read by parse_option_number(), the parser of every front
// end) whose help shows its value in defaults in its shortest form ("--resolution M (=0.05)").
template <typename Target>
void add_option_rows(po::options_description& options, std::span<const OptionRow<Target>> rows, const Target& defaults) {
  for (const OptionRow<Target>& row : rows) {
    if (switch_on_by_default(row)) {
      options.add_options()(row.name.c_str(),
                            po::value<std::string>()->default_value(row.get(defaults) != 0.0 ? "true" : "false")->value_name("true|false"),
                            row.help.c_str());
    } else if (row.is_switch()) {
      options.add_options()(row.name.c_str(), po::bool_switch(), row.help.c_str());
    } else {
      options.add_options()(row.name.c_str(),
                            po::value<std::string>()->default_value(shortest_number(row.get(defaults)))->value_name(row.value_name),
                            row.help.c_str());
    }
  }
}

// The same for a whole table.
template <typename Target>
void add_option_rows(po::options_description& options, const std::vector<OptionRow<Target>>& rows,
                     const Target& defaults) {
  add_option_rows(options, std::span<const OptionRow<Target>>(rows), defaults);
}

// Sets in target every row that vm holds a given (not defaulted) value for, read and checked as every
// front end reads and checks it (option_table.h); a bad value is a UsageError.
template <typename Target>
void read_option_rows(const po::variables_map& vm, const std::vector<OptionRow<Target>>& rows, Target& target) {
  for (const OptionRow<Target>& row : rows) {
    if (!vm.count(row.name) || vm[row.name].defaulted()) continue;
    const std::string shown = "--" + row.name;
    if (row.is_switch() && vm[row.name].value().type() == typeid(std::string)) {  // on by default: true or false
      const std::string text = vm[row.name].template as<std::string>();
      const std::optional<bool> on = parse_switch_value(text);
      if (!on) throw UsageError(switch_value_error(shown, text));
      row.set(target, *on ? 1.0 : 0.0);
      continue;
    }
    if (row.is_switch() && !vm[row.name].template as<bool>()) continue;
    check_usage([&] {
      const double value = row.is_switch() ? 1.0 : parse_option_number(vm[row.name].template as<std::string>(), shown);
      set_option(row, target, value, shown);
    });
  }
}

// Adds rows chosen by name to options: "--selection greedy|reference (=greedy)", the default being
// the name of defaults' value.
template <typename Target>
void add_choice_rows(po::options_description& options, const std::vector<ChoiceRow<Target>>& rows, const Target& defaults) {
  for (const ChoiceRow<Target>& row : rows)
    options.add_options()(row.name.c_str(),
                          po::value<std::string>()->default_value(row.get(defaults))->value_name(row.value_name()),
                          row.help.c_str());
}

// Sets in target every choice that vm holds a given value for; a name not allowed is a UsageError.
template <typename Target>
void read_choice_rows(const po::variables_map& vm, const std::vector<ChoiceRow<Target>>& rows, Target& target) {
  for (const ChoiceRow<Target>& row : rows) {
    if (!vm.count(row.name) || vm[row.name].defaulted()) continue;
    check_usage([&] { set_choice(row, target, vm[row.name].template as<std::string>(), "--" + row.name); });
  }
}

// Adds text rows to options: "--out-json FILE", a required one (an operand) marked required, a
// repeatable one taking every value given.
template <typename Target>
void add_text_rows(po::options_description& options, const std::vector<TextRow<Target>>& rows) {
  for (const TextRow<Target>& row : rows) {
    const std::string name = row.letter.empty() ? row.name : row.name + "," + row.letter;
    if (row.repeatable) {
      options.add_options()(name.c_str(), po::value<std::vector<std::string>>()->composing()->value_name(row.value_name),
                            row.help.c_str());
    } else {
      po::typed_value<std::string>* value = po::value<std::string>()->value_name(row.value_name);
      options.add_options()(name.c_str(), row.required ? value->required() : value, row.help.c_str());
    }
  }
}

// Sets in target every text row vm holds a value for, checked as set_text_option() checks it; a bad
// value (an empty file name, a point that is none) is a UsageError.
template <typename Target>
void read_text_rows(const po::variables_map& vm, const std::vector<TextRow<Target>>& rows, Target& target) {
  for (const TextRow<Target>& row : rows) {
    if (!vm.count(row.name)) continue;
    const std::string shown = "--" + row.name;
    check_usage([&] {
      if (row.repeatable) {
        for (const std::string& text : vm[row.name].template as<std::vector<std::string>>())
          set_text_option(row, target, text, shown);
      } else {
        set_text_option(row, target, vm[row.name].template as<std::string>(), shown);
      }
    });
  }
}

// The segmentation options (segment_option_rows()), with defaults' values shown.
void add_segment_options(po::options_description& options, const SegmentSettings& defaults);

// defaults with what vm gave; the switches are not applied yet (to_segment_options()).
SegmentSettings read_segment_settings(const po::variables_map& vm, SegmentSettings defaults);

// to_segment_options(read_segment_settings(vm, defaults)); a bad combination is a UsageError.
SegmentOptions read_segment_options(const po::variables_map& vm, const SegmentSettings& defaults);

// The incremental segmenter's own options (incremental_option_rows()), with defaults' values shown,
// and defaults with what vm gave (the segment options are read apart: read_segment_options()).
void add_incremental_options(po::options_description& options, const IncrementalOptions& defaults);
IncrementalOptions read_incremental_options(const po::variables_map& vm, IncrementalOptions defaults);

// The map-loading options (map_load_option_rows()), with defaults' values shown.
void add_map_load_options(po::options_description& options, const MapLoadOptions& defaults);

// defaults with what vm gave, validated (a bad combination is a UsageError).
MapLoadOptions read_map_load_options(const po::variables_map& vm, MapLoadOptions defaults);

}  // namespace topocut::cli
