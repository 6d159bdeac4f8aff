#include "cli/library_options.h"

#include <cstddef>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"
#include "topocut/segmentation/merge_model.h"

namespace topocut::cli {

void add_segment_options(po::options_description& options, const SegmentSettings& defaults) {
  const std::span<const OptionRow<SegmentSettings>> rows(segment_option_rows());
  std::size_t first = 0;
  for (const OptionGroup& group : segment_option_groups()) {
    po::options_description part(group.heading);
    add_option_rows(part, rows.subspan(first, group.rows), defaults);
    if (group.heading == kMergingHeading)
      part.add_options()(kMergeModelOption.name, po::value<std::string>()->value_name(kMergeModelOption.value_name),
                         kMergeModelOption.help);
    options.add(part);
    first += group.rows;
  }
}

SegmentSettings read_segment_settings(const po::variables_map& vm, SegmentSettings defaults) {
  read_option_rows(vm, segment_option_rows(), defaults);
  if (vm.count(kMergeModelOption.name)) {
    const std::string path = vm[kMergeModelOption.name].as<std::string>();
    const std::string text = read_input_file(path, "merge model", kMaxMergeModelBytes);
    try {
      defaults.options.merge.model = parse_merge_model(text);
      defaults.switches.merge_model_given = true;
    } catch (const Error& e) {
      throw Error(path + ": " + e.what());
    }
  }
  return defaults;
}

SegmentOptions read_segment_options(const po::variables_map& vm, const SegmentSettings& defaults) {
  const SegmentSettings settings = read_segment_settings(vm, defaults);
  SegmentOptions options;
  check_usage([&] { options = to_segment_options(settings); });
  return options;
}

void add_incremental_options(po::options_description& options, const IncrementalOptions& defaults) {
  add_option_rows(options, incremental_option_rows(), defaults);
}

IncrementalOptions read_incremental_options(const po::variables_map& vm, IncrementalOptions defaults) {
  read_option_rows(vm, incremental_option_rows(), defaults);
  return defaults;
}

void add_map_load_options(po::options_description& options, const MapLoadOptions& defaults) {
  add_option_rows(options, map_load_option_rows(), defaults);
}

MapLoadOptions read_map_load_options(const po::variables_map& vm, MapLoadOptions defaults) {
  read_option_rows(vm, map_load_option_rows(), defaults);
  check_usage([&] { validate(defaults); });
  return defaults;
}

}  // namespace topocut::cli
