#pragma once
// The options of map loading as people give them (the flags of every command that reads a map,
// --config keys, the benchmarks' arguments): defined once, next to segment_option_rows().
#include <vector>

#include "topocut/core/option_table.h"
#include "topocut/io/map_loader.h"

namespace topocut {

// resolution, fixed-thresholds, free-threshold, occupied-threshold, max-megapixels. Giving either
// threshold means fixed thresholds (detect_palette = false), as --fixed-thresholds does.
const std::vector<OptionRow<MapLoadOptions>>& map_load_option_rows();

// Throws Error unless the options are usable together: thresholds in 0..255 with occupied_max <=
// free_min, a positive finite resolution, the image limit in its range.
void validate(const MapLoadOptions& options);

}  // namespace topocut
