#pragma once
// The command-line options of a dataset run, shared by `topocut evaluate` and the dataset benchmark
// so that both accept the same flags: one table of options, one function that applies a value.
// Adding a segmenter option means adding one row to the table and one case to
// apply_dataset_option(); both programs then accept it.
#include <string>
#include <vector>

#include "topocut/evaluation/dataset.h"

namespace topocut {

struct DatasetArguments {
  std::string dataset = "../shared/datasets/bormann";  // relative to the current directory
  std::string csv;                                     // CSV output path; empty: none
  bool variant_given = false;                          // --variant was given (else: the folder's variants)
  DatasetRunOptions run;
};

struct DatasetOption {
  std::string name;        // long name without the leading dashes
  std::string value_name;  // shown in the help, e.g. "DIR"; empty for a flag (takes no value)
  std::string help;        // one line, with the default
  bool repeatable = false; // takes one or more values (--map a b c), may be given several times
};

// The options, in the order the help lists them.
const std::vector<DatasetOption>& dataset_options();

// Applies one option to arguments (value "" for a flag; a repeatable option is applied once per
// value). Throws Error with one clear sentence on an unknown option or a bad value.
void apply_dataset_option(DatasetArguments& arguments, const std::string& name, const std::string& value);

// Parses "--name value", "--name=value", flags and repeatable options for programs that do not use
// Boost.Program_options (the benchmarks). Throws Error on anything it does not understand.
DatasetArguments parse_dataset_arguments(const std::vector<std::string>& args);

// The options as help text, one per line: "  --name VALUE   help".
std::string dataset_options_help();

// A short name for the segmenter configuration, for the summary's method column.
std::string method_name(const SegmentOptions& options);

}  // namespace topocut
