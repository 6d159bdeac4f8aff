#include "cli/input_options.h"

#include "topocut/core/error.h"

namespace topocut::cli {

void add_image_limit_option(po::options_description& options, std::string& value) {
  options.add_options()(kMaxMegapixelsOption, po::value<std::string>(&value)->value_name("MP"), max_megapixels_help().c_str());
}

void apply_image_limit_option(const std::string& value, ImageLimits& limits) {
  if (value.empty()) return;
  try {
    apply_max_megapixels(limits, value);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

}  // namespace topocut::cli
