#include "cli/library_options.h"

namespace topocut::cli {

void add_segment_options(po::options_description& options, const SegmentSettings& defaults) {
  add_option_rows(options, segment_option_rows(), defaults);
}

SegmentSettings read_segment_settings(const po::variables_map& vm, SegmentSettings defaults) {
  read_option_rows(vm, segment_option_rows(), defaults);
  return defaults;
}

SegmentOptions read_segment_options(const po::variables_map& vm, const SegmentSettings& defaults) {
  const SegmentSettings settings = read_segment_settings(vm, defaults);
  SegmentOptions options;
  check_usage([&] { options = to_segment_options(settings); });
  return options;
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
