#include "topocut/io/map_load_flags.h"

#include "topocut/core/error.h"
#include "topocut/core/grid_array_options.h"
#include "topocut/io/image_input.h"

namespace topocut {

const std::vector<OptionRow<MapLoadOptions>>& map_load_option_rows() {
  using L = MapLoadOptions;
  static const std::vector<OptionRow<L>> rows = [] {
    std::vector<OptionRow<L>> all = {
        {"resolution", "M", "metres per cell of a plain image (a YAML's own resolution always wins)", OptionRange::kResolution,
         [](const L& l) { return l.resolution; }, [](L& l, double v) { l.resolution = v; }},
    };
    for (OptionRow<L>& row : grey_threshold_rows<L>()) all.push_back(std::move(row));  // GridArray's rule and names
    all.push_back({kMaxMegapixelsOption, "MP", max_megapixels_help(), OptionRange::kAny,
                   [](const L& l) { return l.limits.max_megapixels; },
                   [](L& l, double v) {
                     l.limits.max_megapixels = v;
                     validate(l.limits);
                   }});
    return all;
  }();
  return rows;
}

void validate(const MapLoadOptions& options) {
  for (const OptionRow<MapLoadOptions>& row : map_load_option_rows())
    if (!row.is_switch()) check_option_value(row.range, row.get(options), "--" + row.name);
  if (options.occupied_max > options.free_min) throw Error("--occupied-threshold must not exceed --free-threshold");
  validate(options.limits);
}

}  // namespace topocut
