#pragma once
// Options about inputs shared by every command that reads images, so each is defined once.
#include "cli/command.h"
#include "topocut/io/image_input.h"

namespace topocut::cli {

// Adds --max-megapixels (image_input.h's name and help) writing its text value to *value.
void add_image_limit_option(po::options_description& options, std::string& value);

// Applies the option's value (if given) to limits; a bad value is a UsageError naming the range.
void apply_image_limit_option(const std::string& value, ImageLimits& limits);

}  // namespace topocut::cli
