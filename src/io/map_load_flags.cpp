#include "topocut/io/map_load_flags.h"

#include <cmath>

#include "topocut/core/error.h"
#include "topocut/io/image_input.h"

namespace topocut {

const std::vector<OptionRow<MapLoadOptions>>& map_load_option_rows() {
  using L = MapLoadOptions;
  static const std::vector<OptionRow<L>> rows = {
      {"resolution", "M", "metres per cell of a plain image (a YAML's own resolution always wins)", OptionRange::kPositive,
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
  if (!std::isfinite(options.resolution) || options.resolution <= 0.0) throw Error("--resolution must be a positive number");
  if (options.free_min < 0 || options.free_min > 255 || options.occupied_max < 0 || options.occupied_max > 255)
    throw Error("--free-threshold and --occupied-threshold must lie in 0..255");
  if (options.occupied_max > options.free_min) throw Error("--occupied-threshold must not exceed --free-threshold");
  validate(options.limits);
}

}  // namespace topocut
