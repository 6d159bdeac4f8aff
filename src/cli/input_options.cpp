#include "cli/input_options.h"

#include "topocut/core/error.h"

namespace topocut::cli {

void add_image_limit_option(po::options_description& options, ImageLimits& limits) {
  options.add_options()(kMaxMegapixelsOption,
                        po::value<double>(&limits.max_megapixels)->default_value(limits.max_megapixels)->value_name("MP"),
                        max_megapixels_help().c_str());
}

void check_image_limit_option(const ImageLimits& limits) {
  check_usage([&] { validate(limits); });
}

}  // namespace topocut::cli
