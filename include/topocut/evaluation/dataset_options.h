#pragma once
// The arguments of a dataset run for the benchmark programs, which take `topocut evaluate`'s flags
// without Boost.Program_options: the dataset's own options (--dataset, --variant, --map, --csv) are
// defined here; every segmentation and map-loading flag comes from the library's tables
// (segment_option_rows(), map_load_option_rows()), which `topocut evaluate` reads with
// program_options. A flag added to those tables reaches every command and benchmark at once.
#include <string>
#include <vector>

#include "topocut/evaluation/dataset.h"
#include "topocut/segmentation/segment_switches.h"

namespace topocut {

struct DatasetArguments {
  std::string dataset = "../shared/datasets/bormann";  // relative to the current directory
  std::string csv;                                     // CSV output path; empty: none
  bool variant_given = false;                          // --variant was given (else: the folder's variants)
  SegmentSettings segment;  // the segmentation flags as given; run.segment is to_segment_options() of them
  DatasetRunOptions run;
};

struct DatasetOption {
  std::string name;        // long name without the leading dashes
  std::string value_name;  // shown in the help, e.g. "DIR"; empty for a flag (takes no value)
  std::string help;        // one line, with the default
  bool repeatable = false; // takes one or more values (--map a b c), may be given several times
};

// The dataset's own options (--dataset, --variant, --map, --csv), in the order the help lists them.
const std::vector<DatasetOption>& dataset_options();

// Applies one option, the dataset's own or a segmentation or map-loading flag, to arguments (value
// "" for a flag; a repeatable option is applied once per value); run.segment is updated at once.
// Throws Error with one clear sentence on an unknown option or a bad value.
void apply_dataset_option(DatasetArguments& arguments, const std::string& name, const std::string& value);

// Parses "--name value", "--name=value", flags and repeatable options for programs that do not use
// Boost.Program_options (the benchmarks). Throws Error on anything it does not understand.
DatasetArguments parse_dataset_arguments(const std::vector<std::string>& args);

// Every option as help text, one per line: "  --name VALUE   help (default ...)".
std::string dataset_options_help();

// A short name for the segmenter configuration, for the summary's method column.
std::string method_name(const SegmentOptions& options);

}  // namespace topocut
