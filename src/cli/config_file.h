#pragma once
// --config FILE.yaml: a command's options from a YAML file, so that a robot's parameters live in one
// place. Keys are the long option names; the command line wins over the file.
#include <string>

#include "cli/command.h"

namespace topocut::cli {

// The options in the YAML mapping at path, as if given on the command line: a scalar is the option's
// value, true turns a switch on (false leaves it off), a list gives several values. Throws
// UsageError naming the file and the key on an unknown key or a value of the wrong shape, Error if
// the file cannot be read or is not YAML.
po::parsed_options config_file_options(const std::string& path, const po::options_description& options);

}  // namespace topocut::cli
