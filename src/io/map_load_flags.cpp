#include "topocut/io/map_load_flags.h"

#include "topocut/core/error.h"
#include "topocut/io/image_input.h"

namespace topocut {

const std::vector<OptionRow<MapLoadOptions>>& map_load_option_rows() {
  using L = MapLoadOptions;
  static const std::vector<OptionRow<L>> rows = {
      {"resolution", "M", "metres per cell of a plain image (a YAML's own resolution always wins)", OptionRange::kResolution,
       [](const L& l) { return l.resolution; }, [](L& l, double v) { l.resolution = v; }},
      {"fixed-thresholds", "",
       "plain images: use --free-threshold and --occupied-threshold instead of reading the palette from the image",
       OptionRange::kSwitch, [](const L& l) { return l.detect_palette ? 0.0 : 1.0; },
       [](L& l, double on) { l.detect_palette = on == 0.0; }},
      {"free-threshold", "GREY",
       "plain images with --fixed-thresholds (or no readable palette): grey values above this are free",
       OptionRange::kGreyLevel, [](const L& l) { return l.free_min; },
       [](L& l, double v) {
         l.free_min = static_cast<int>(v);
         l.detect_palette = false;
       }},
      {"occupied-threshold", "GREY",
       "plain images with --fixed-thresholds: grey values below this are occupied (between the two: unknown)",
       OptionRange::kGreyLevel, [](const L& l) { return l.occupied_max; },
       [](L& l, double v) {
         l.occupied_max = static_cast<int>(v);
         l.detect_palette = false;
       }},
      {kMaxMegapixelsOption, "MP", max_megapixels_help(), OptionRange::kAny,
       [](const L& l) { return l.limits.max_megapixels; },
       [](L& l, double v) {
         l.limits.max_megapixels = v;
         validate(l.limits);
       }},
  };
  return rows;
}

void validate(const MapLoadOptions& options) {
  for (const OptionRow<MapLoadOptions>& row : map_load_option_rows())
    if (!row.is_switch()) check_option_value(row.range, row.get(options), "--" + row.name);
  if (options.occupied_max > options.free_min) throw Error("--occupied-threshold must not exceed --free-threshold");
  validate(options.limits);
}

}  // namespace topocut
