#include "topocut/evaluation/dataset_options.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "topocut/core/error.h"
#include "topocut/io/image_input.h"

namespace topocut {

namespace {

std::string number(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

// The whole of value as a number satisfying ok; otherwise Error "--name needs <what>, not 'value'".
template <typename Ok>
double parse_number(const std::string& name, const std::string& value, const std::string& what, Ok ok) {
  std::size_t used = 0;
  double parsed = 0.0;
  try {
    parsed = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != value.size() || !ok(parsed)) throw Error("--" + name + " needs " + what + ", not '" + value + "'");
  return parsed;
}

double parse_positive_metres(const std::string& name, const std::string& value) {
  return parse_number(name, value, "a positive number of metres", [](double v) { return std::isfinite(v) && v > 0.0; });
}

const DatasetOption* find_option(const std::string& name) {
  for (const DatasetOption& option : dataset_options()) {
    if (option.name == name) return &option;
  }
  return nullptr;
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
        {"concavity", "M", "maximum concavity tau in metres (default " + number(defaults.run.segment.concavity) + ")",
         false},
        {"trivial", "", "baseline: every free-space component is one room (no decomposition)", false},
        {"parity", "", "the reference: DuDe's pieces are the rooms (no doors, merging or simplification)", false},
        {"no-doors", "", "no door cuts before the decomposition", false},
        {"no-wall-openings", "", "door cuts without the wall openings", false},
        {"no-merge", "", "no merging of pieces into rooms", false},
        {"no-simplify", "", "decompose the exact pixel-edge polygons", false},
        {"cover-obstacles", "", "rooms also label the obstacles they absorbed (furniture)", false},
        {"no-clean", "", "decompose the free space as it is (no removal of ray fans, slivers and specks)", false},
        {"fixed-thresholds", "", "plain images: grey > 250 free, < 50 occupied (no palette detection)", false},
        {"no-width-steps", "", "merge a room into a much wider space it opens onto (no width-step rule)", false},
        {"no-furniture-rule", "", "cuts that end on furniture-sized obstacles may separate rooms", false},
        {"resolution", "M", "metres per cell of images without a YAML (default " + number(defaults.run.load.resolution) + ")",
         false},
        {kMaxMegapixelsOption, "MP", max_megapixels_help(), false},
        {"oversegment", "F", "with merging, DuDe cuts at F x tau, 0 < F <= 1 (default " +
                                  number(defaults.run.segment.oversegment) + ")", false},
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
  } else if (name == "concavity") {
    arguments.run.segment.concavity = parse_positive_metres(name, value);
  } else if (name == "trivial") {
    arguments.run.segment.decompose = false;
  } else if (name == "parity") {
    const bool decompose = arguments.run.segment.decompose;
    arguments.run.segment = parity_segment_options(arguments.run.segment.concavity);
    arguments.run.segment.decompose = decompose;
  } else if (name == "no-doors") {
    arguments.run.segment.doors.enabled = false;
  } else if (name == "no-wall-openings") {
    arguments.run.segment.doors.extend_walls = false;
  } else if (name == "no-merge") {
    arguments.run.segment.merge.enabled = false;
  } else if (name == "no-simplify") {
    arguments.run.segment.simplify = 0.0;
  } else if (name == "cover-obstacles") {
    arguments.run.segment.labels.cover_absorbed_obstacles = true;
  } else if (name == "no-clean") {
    arguments.run.segment.clean = false;
  } else if (name == "fixed-thresholds") {
    arguments.run.load.detect_palette = false;
  } else if (name == "no-width-steps") {
    arguments.run.segment.merge.step_ratio = 0.0;
  } else if (name == "no-furniture-rule") {
    arguments.run.segment.merge.furniture_size = 0.0;
  } else if (name == "resolution") {
    arguments.run.load.resolution = parse_positive_metres(name, value);
  } else if (name == kMaxMegapixelsOption) {
    arguments.run.load.limits.max_megapixels = parse_number(name, value, "a number of megapixels", [](double) { return true; });
    validate(arguments.run.load.limits);
  } else if (name == "oversegment") {
    arguments.run.segment.oversegment =
        parse_number(name, value, "a factor in (0, 1]", [](double v) { return v > 0.0 && v <= 1.0; });
  } else {
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
    const DatasetOption* option = find_option(name);
    if (option == nullptr) throw Error("unknown option '--" + name + "'");
    if (option->value_name.empty()) {
      if (has_inline_value) throw Error("--" + name + " takes no value");
      apply_dataset_option(arguments, name, "");
    } else if (has_inline_value) {
      apply_dataset_option(arguments, name, inline_value);
    } else {
      if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0) {
        throw Error("--" + name + " needs a value (" + option->value_name + ")");
      }
      apply_dataset_option(arguments, name, args[++i]);
      while (option->repeatable && i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) {
        apply_dataset_option(arguments, name, args[++i]);
      }
    }
  }
  return arguments;
}

std::string dataset_options_help() {
  std::string help;
  for (const DatasetOption& option : dataset_options()) {
    std::string left = "  --" + option.name + (option.value_name.empty() ? "" : " " + option.value_name);
    if (left.size() < 24) left += std::string(24 - left.size(), ' ');
    help += left + " " + option.help + "\n";
  }
  return help;
}

std::string method_name(const SegmentOptions& options) {
  if (!options.decompose) return "trivial (one room per component)";
  std::string name = "topocut (tau " + number(options.concavity) + " m";
  if (!options.doors.enabled && !options.merge.enabled && options.simplify == 0.0 &&
      !options.labels.cover_absorbed_obstacles && !options.clean) {
    name += ", parity";
  } else {
    if (!options.doors.enabled) name += ", no doors";
    if (options.doors.enabled && !options.doors.extend_walls) name += ", no wall openings";
    if (!options.merge.enabled) name += ", no merge";
    if (options.simplify == 0.0) name += ", no simplify";
    if (options.labels.cover_absorbed_obstacles) name += ", obstacles covered";
    if (!options.clean) name += ", no cleaning";
    if (options.merge.enabled && options.merge.step_ratio == 0.0) name += ", no width steps";
    if (options.merge.enabled && options.merge.furniture_size == 0.0) name += ", no furniture rule";
    if (options.merge.enabled && options.oversegment != SegmentOptions{}.oversegment)
      name += ", DuDe at " + number(options.oversegment) + " tau";
  }
  return name + ")";
}

}  // namespace topocut
