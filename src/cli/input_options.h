#pragma once
// Options about inputs shared by every command that reads images, so each is defined once.
#include "cli/command.h"
#include "topocut/io/image_input.h"

namespace topocut::cli {

// Adds --max-megapixels (image_input.h's name and help), writing into limits.
void add_image_limit_option(po::options_description& options, ImageLimits& limits);

// Validates limits after parsing; a bad value is a UsageError naming the range.
void check_image_limit_option(const ImageLimits& limits);

}  // namespace topocut::cli
