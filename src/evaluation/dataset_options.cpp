#include "topocut/evaluation/dataset_options.h"

#include <cstdio>

#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/core/option_table.h"
#include "topocut/io/map_load_flags.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace topocut {

namespace {

// As method names have always printed numbers (%g).
std::string number(double value) { return format("%g", value); }

// How an option is given on a command line.
enum class Takes { kNothing, kValue, kValues, kUnknown };

Takes takes(const std::string& name) {
  for (const DatasetOption& option : dataset_options()) {
    if (option.name == name) return option.value_name.empty() ? Takes::kNothing : option.repeatable ? Takes::kValues : Takes::kValue;
  }
  if (const auto* row = find_option(segment_option_rows(), name)) return row->is_switch() ? Takes::kNothing : Takes::kValue;
  if (const auto* row = find_option(map_load_option_rows(), name)) return row->is_switch() ? Takes::kNothing : Takes::kValue;
  return Takes::kUnknown;
}

// Sets row in target from value (a switch: ""); true if row is not null.
template <typename Target>
bool apply_row(const OptionRow<Target>* row, Target& target, const std::string& value) {
  if (row == nullptr) return false;
  const std::string shown = "--" + row->name;
  set_option(*row, target, row->is_switch() ? 1.0 : parse_option_number(value, shown), shown);
  return true;
}

template <typename Target>
std::string rows_help(const std::vector<OptionRow<Target>>& rows, const Target& defaults) {
  std::string help;
  for (const OptionRow<Target>& row : rows) {
    const std::string shown_default = row.is_switch() ? "" : " (default " + shortest_number(row.get(defaults)) + ")";
    help += option_help_line(row.name, row.value_name, row.help + shown_default);
  }
  return help;
}

}  // namespace

const std::vector<DatasetOption>& dataset_options() {
  static const std::vector<DatasetOption> options = [] {
    const DatasetArguments defaults;
    return std::vector<DatasetOption>{
        {"dataset", "DIR", "Bormann-format dataset folder (default " + defaults.dataset + ")", false},
        {"variant", "V", "plain, furnished or all (default: those the folder has)", false},
        {"map", "NAME", "run only the named maps (one or more; default all)", true},
        {"csv", "FILE", "also write the per-image results to FILE as CSV", false},
    };
  }();
  return options;
}

void apply_dataset_option(DatasetArguments& arguments, const std::string& name, const std::string& value) {
  if (name == "dataset") {
    if (value.empty()) throw Error("--dataset needs a folder");
    arguments.dataset = value;
  } else if (name == "variant") {
    arguments.variant_given = true;
    if (value == "all") {
      arguments.run.variants = {Variant::kPlain, Variant::kFurnished};
    } else if (value == "plain" || value == "furnished") {
      arguments.run.variants = {parse_variant(value)};
    } else {
      throw Error("unknown variant '" + value + "' (expected plain, furnished or all)");
    }
  } else if (name == "map") {
    if (value.empty()) throw Error("--map needs a map name");
    arguments.run.maps.push_back(value);
  } else if (name == "csv") {
    if (value.empty()) throw Error("--csv needs a file name");
    arguments.csv = value;
  } else if (apply_row(find_option(segment_option_rows(), name), arguments.segment, value)) {
    arguments.run.segment = to_segment_options(arguments.segment);
  } else if (!apply_row(find_option(map_load_option_rows(), name), arguments.run.load, value)) {
    throw Error("unknown option '--" + name + "'");
  }
}

DatasetArguments parse_dataset_arguments(const std::vector<std::string>& args) {
  DatasetArguments arguments;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) throw Error("unexpected argument '" + arg + "'");
    std::string name = arg.substr(2);
    std::string inline_value;
    bool has_inline_value = false;
    if (const std::size_t eq = name.find('='); eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name = name.substr(0, eq);
      has_inline_value = true;
    }
    const Takes kind = takes(name);
    if (kind == Takes::kUnknown) throw Error("unknown option '--" + name + "'");
    if (kind == Takes::kNothing) {
      if (has_inline_value) throw Error("--" + name + " takes no value");
      apply_dataset_option(arguments, name, "");
    } else if (has_inline_value) {
      apply_dataset_option(arguments, name, inline_value);
    } else {
      if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0) {
        throw Error("--" + name + " needs a value");
      }
      apply_dataset_option(arguments, name, args[++i]);
      while (kind == Takes::kValues && i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) {
        apply_dataset_option(arguments, name, args[++i]);
      }
    }
  }
  validate(arguments.run.load);  // the thresholds together
  return arguments;
}

std::string dataset_options_help() {
  std::string help;
  for (const DatasetOption& option : dataset_options()) help += option_help_line(option.name, option.value_name, option.help);
  const DatasetArguments defaults;
  return help + rows_help(segment_option_rows(), defaults.segment) + rows_help(map_load_option_rows(), defaults.run.load);
}

std::string method_name(const SegmentOptions& options) {
  if (!options.decompose) return "trivial (one room per component)";
  std::string name = "topocut (tau " + number(options.concavity) + " m";
  const std::vector<std::string> off = rules_off(options);
  if (off == rules_off(parity_segment_options(options.concavity)) && !options.labels.cover_absorbed_obstacles) {
    name += ", parity";
  } else {
    for (const std::string& rule : off) name += ", no " + rule;
    if (options.labels.cover_absorbed_obstacles) name += ", obstacles covered";
    if (options.merge.enabled && options.oversegment != SegmentOptions{}.oversegment)
      name += ", DuDe at " + number(options.oversegment) + " tau";
  }
  return name + ")";
}

}  // namespace topocut
