// topocut rules: the segmentation pipeline as the library runs it, read from its rule list
// (segmentation_rules.h), so that the pipeline's description is the list itself and never a table
// kept beside it.
#include <iostream>

#include "cli/command.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace topocut::cli {
namespace {

const char* const kDescription =
    "Prints the pipeline that segment (and the incremental update of explore, walls --incremental and\n"
    "evaluate --mode incremental) runs, one row a line in the order the rows run: the row's name, its\n"
    "stage, its switch (--no-NAME on the command line and in --config, no_NAME=True in Python; 'no switch':\n"
    "on with its stage) and what it does. Merge criteria are asked in their order within merge; the\n"
    "first that does not abstain decides.";

int run(const std::vector<std::string>& args) {
  const auto vm = parse_options("topocut rules", kDescription, po::options_description(), po::positional_options_description(), args);
  if (!vm) return 0;
  std::cout << rule_list_text(segmentation_rules()) << std::flush;
  return 0;
}

const bool registered = register_command({"rules", "list the segmentation pipeline's rows in order (name, stage, switch, what it does)", &run});

}  // namespace
}  // namespace topocut::cli
