// topocut: segment 2-D robot maps into rooms. Dispatches to the registered subcommands and turns
// every failure into one line on stderr and a non-zero exit code.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "cli/allocator.h"
#include "cli/command.h"
#include "topocut/core/error.h"
#include "topocut/core/option_names.h"
#include "topocut/core/version.h"
#include "topocut/io/output_files.h"

namespace {

void print_help() {
  std::cout << "topocut " << TOPOCUT_VERSION
            << " - segment 2-D robot maps (occupancy grids, laser logs) into rooms\n\n"
               "Usage: topocut COMMAND [options]\n       topocut COMMAND --help\n\nCommands:\n";
  for (const auto& [name, command] : topocut::cli::commands()) {
    std::cout << "  " << name << std::string(name.size() < 12 ? 12 - name.size() : 1, ' ') << command.summary << "\n";
  }
  std::cout << "\nOptions:\n  --help      show this help\n  --version   print the version\n";
}

const char* const kOutOfMemory =
    "out of memory: the input needs more memory than this machine has (or is allowed), or declares an impossible size";

// One line on stderr, whatever the message holds (see one_line_message).
void report(const std::string& command, const std::string& message) {
  std::cerr << "topocut " << command << ": error: " << topocut::one_line_message(message) << "\n";
}

// Runs the command; exceptions become one line on stderr and an exit code.
int dispatch(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help();
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    std::cout << "topocut " << TOPOCUT_VERSION << "\n";
    return 0;
  }
  const auto& table = topocut::cli::commands();
  const auto found = table.find(args[0]);
  if (found == table.end()) {
    std::vector<std::string> names;
    for (const auto& entry : table) names.push_back(entry.first);
    const std::string meant = topocut::closest_option_name(args[0], names);
    std::cerr << "topocut: error: unknown command '" << args[0] << "'"
              << (meant.empty() ? "" : " (did you mean '" + meant + "'?)") << " (see 'topocut --help')\n";
    return 2;
  }
  try {
    // Outputs are put in place only when the command ran to its end: an exception discards them
    // all (see output_files.h). A command that returns a non-zero code on purpose (evaluate with a
    // failed map) has written complete outputs that report it.
    topocut::OutputRun outputs;
    const int code = found->second.run(std::vector<std::string>(args.begin() + 1, args.end()));
    outputs.commit();
    return code;
  } catch (const topocut::cli::UsageError& e) {
    report(args[0], std::string(e.what()) + " (see 'topocut " + args[0] + " --help')");
    return 2;
  } catch (const topocut::Error& e) {
    report(args[0], e.what());
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the user gave that the system refused (too long, no permission, a loop of links).
    report(args[0], "cannot use '" + e.path1().string() + "': " + e.code().message());
    return 1;
  } catch (const std::bad_alloc&) {
    report(args[0], kOutOfMemory);
    return 1;
  } catch (const std::length_error&) {
    report(args[0], "the input declares a size too large to hold in memory");
    return 1;
  } catch (const cv::Exception& e) {
    // OpenCV reports a failed allocation as its own exception, not std::bad_alloc.
    report(args[0], e.code == cv::Error::StsNoMem ? kOutOfMemory : std::string("internal failure: ") + e.what());
    return 1;
  } catch (const std::exception& e) {
    report(args[0], std::string("internal failure: ") + e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  topocut::keep_freed_memory_for_reuse();
  const int code = dispatch(std::vector<std::string>(argv + 1, argv + argc));
  // Results printed on stdout are an output like any file: a full disk, a closed pipe or a closed
  // stdout must not end in exit 0 with the results lost.
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::cerr << "topocut: error: cannot write to standard output\n";
    return code == 0 ? 1 : code;
  }
  return code;
}
