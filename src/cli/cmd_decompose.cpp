// topocut decompose: dual-space decomposition of one polygon with holes given as JSON.
#include <cmath>
#include <iostream>
#include <string>

#include "cli/command.h"
#include "cli/library_options.h"
#include "topocut/core/error.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/decomposition/decomposition_json.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/output_files.h"
#include "topocut/io/polygon_json.h"

namespace topocut::cli {
namespace {

// The polygon read and the JSON written.
struct Files {
  std::string input, output;
};

const std::vector<TextRow<Files>>& file_rows() {
  static const std::vector<TextRow<Files>> rows = {
      path_row("polygon", "POLYGON", TextKind::kInput, &Files::input,
               "polygon JSON (- for standard input): {\"outer\": [[x,y],...], \"holes\": [[[x,y],...],...]}", true),
      path_row("output", "FILE", TextKind::kOutput, &Files::output, "write the JSON here instead of standard output", false, "o")};
  return rows;
}

int run(const std::vector<std::string>& args) {
  Files files;
  DecompositionOptions options;
  po::options_description described("Decomposition");
  add_text_rows(described, file_rows());
  add_option_rows(described, decomposition_tau_rows(), options);
  add_choice_rows(described, decomposition_choice_rows(), options);
  add_option_rows(described, decomposition_option_rows(), options);
  po::positional_options_description positional;
  positional.add("polygon", 1);
  const auto vm = parse_options(
      "topocut decompose POLYGON.json [--tau T] [options]",
      "Decomposes a polygon with holes into nearly convex pieces with the dual-space decomposition\n"
      "(DuDe, Liu, Xi & Lien 2014): cuts between existing vertices wherever a pocket or hole is\n"
      "deeper than tau. Rings may have any orientation. Prints JSON: the pieces (outer ring\n"
      "counter-clockwise, holes clockwise, area), the cuts applied, and the holes smaller than tau\n"
      "that the pieces cover.",
      described, positional, args);
  if (!vm) return 0;
  read_text_rows(*vm, file_rows(), files);
  read_option_rows(*vm, decomposition_tau_rows(), options);
  read_choice_rows(*vm, decomposition_choice_rows(), options);
  read_option_rows(*vm, decomposition_option_rows(), options);
  if (!files.output.empty()) check_outputs({files.output}, {files.input});

  const PolygonWithHoles polygon = read_polygon_json(files.input);
  const Decomposition result = decompose(polygon, options);
  if (!result.complete) {
    std::cerr << "warning: stopped after " << result.rounds << " rounds (--max-rounds) with cuts still to make: "
              << "the pieces tile the polygon but some may be deeper than tau\n";
  }

  const std::string text = decomposition_to_json(result);
  if (files.output.empty()) {
    std::cout << text;
  } else {
    write_file_atomically(files.output, text);
  }
  return 0;
}

const bool registered = register_command(
    {"decompose", "split a polygon (JSON) into nearly convex pieces (dual-space decomposition)", &run});

}  // namespace
}  // namespace topocut::cli
