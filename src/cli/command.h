#pragma once
// The topocut command line is a set of subcommands, one file each (cmd_*.cpp), that register
// themselves here. A command only parses its options and calls the library.
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "topocut/core/error.h"

namespace topocut::cli {

namespace po = boost::program_options;

// Wrong use of the command line (unknown option, missing argument): exit code 2.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

struct Command {
  std::string name;
  std::string summary;  // one line for `topocut --help`
  std::function<int(const std::vector<std::string>& args)> run;  // args exclude the command name
};

// Adds a command to the table; returns true so it can initialise a static in the command's file.
bool register_command(Command command);

// All registered commands, by name.
const std::map<std::string, Command>& commands();

// The long names of options ("robot-radius"), for "did you mean" hints.
std::vector<std::string> option_names(const po::options_description& options);

// Parses args for a command. Prints usage and returns nullopt on --help; throws UsageError on bad
// options (an unknown one with the name meant, if close). Option names take '_' for '-'
// (--robot_radius). `usage` is the synopsis line, e.g. "topocut segment MAP [options]".
std::optional<po::variables_map> parse_options(const std::string& usage, const std::string& description,
                                               const po::options_description& options,
                                               const po::positional_options_description& positional,
                                               const std::vector<std::string>& args);

// Runs a library check of the command's options (validate(...), apply(...)); the Error it throws
// becomes a UsageError, so a bad option exits 2 whichever layer found it.
template <typename Check>
void check_usage(Check&& check) {
  try {
    check();
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

// Prints progress on stderr ("\r" updates) unless stderr is not a terminal and quiet is set.
void progress(const std::string& message);

}  // namespace topocut::cli
