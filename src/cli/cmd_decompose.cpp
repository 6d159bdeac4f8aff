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

template <class E>
E pick(const std::string& option, const std::string& value, std::initializer_list<std::pair<const char*, E>> choices) {
  std::string names;
  for (const auto& [name, e] : choices) {
    if (value == name) return e;
    names += names.empty() ? std::string("'") + name + "'" : std::string(", '") + name + "'";
  }
  throw UsageError("--" + option + " must be one of " + names + ", got '" + value + "'");
}

int run(const std::vector<std::string>& args) {
  std::string input, output, selection = "greedy", concavity = "straight", candidates = "validated";
  std::string pockets = "split", skinny = "reference", hull_distance = "segment";
  DecompositionOptions options;
  double tau = 0.0;
  po::options_description described("Decomposition");
  described.add_options()
      ("polygon", po::value<std::string>(&input)->required(), "polygon JSON (- for standard input): {\"outer\": [[x,y],...], \"holes\": [[[x,y],...],...]}")
      ("tau", po::value<double>(&tau)->required(), "maximum concavity, in the polygon's units (> 0)")
      ("output,o", po::value<std::string>(&output), "write the JSON here instead of standard output")
      ("selection", po::value<std::string>(&selection)->default_value(selection), "cut selection: greedy or reference (the authors' DP)")
      ("concavity-measure", po::value<std::string>(&concavity)->default_value(concavity), "how a pocket's concavity is measured: straight (reference code) or hierarchical (paper); the concavity bound itself is --tau")
      ("candidates", po::value<std::string>(&candidates)->default_value(candidates), "candidate cuts: validated or reference (unchecked, repaired)")
      ("pocket-polygons", po::value<std::string>(&pockets)->default_value(pockets), "dual pass on pockets: split (at the bridge) or reference")
      ("hull-chain-distance", po::value<std::string>(&hull_distance)->default_value(hull_distance), "pocket hull-chain approximation: segment or line (reference)")
      ("skinny", po::value<std::string>(&skinny)->default_value(skinny), "skinny-cut filter: reference, all or off");
  add_option_rows(described, decomposition_option_rows(), options);
  po::positional_options_description positional;
  positional.add("polygon", 1);
  const auto vm = parse_options(
      "topocut decompose POLYGON.json --tau T [options]",
      "Decomposes a polygon with holes into nearly convex pieces with the dual-space decomposition\n"
      "(DuDe, Liu, Xi & Lien 2014): cuts between existing vertices wherever a pocket or hole is\n"
      "deeper than tau. Rings may have any orientation. Prints JSON: the pieces (outer ring\n"
      "counter-clockwise, holes clockwise, area), the cuts applied, and the holes smaller than tau\n"
      "that the pieces cover.",
      described, positional, args);
  if (!vm) return 0;
  if (!(tau > 0.0) || !std::isfinite(tau)) throw UsageError("--tau must be a positive number");
  options.tau = tau;
  options.selection = pick<CutSelection>("selection", selection, {{"greedy", CutSelection::kGreedy}, {"reference", CutSelection::kReference}});
  options.concavity = pick<ConcavityMeasure>("concavity-measure", concavity, {{"straight", ConcavityMeasure::kStraightLine}, {"hierarchical", ConcavityMeasure::kHierarchical}});
  options.candidates = pick<CandidateCuts>("candidates", candidates, {{"validated", CandidateCuts::kValidated}, {"reference", CandidateCuts::kReference}});
  options.pocket_polygon = pick<PocketPolygon>("pocket-polygons", pockets, {{"split", PocketPolygon::kSplitOnBridge}, {"reference", PocketPolygon::kReference}});
  options.hull_chain_distance = pick<HullChainDistance>("hull-chain-distance", hull_distance, {{"segment", HullChainDistance::kSegment}, {"line", HullChainDistance::kLine}});
  options.skinny_cuts = pick<SkinnyCutFilter>("skinny", skinny, {{"reference", SkinnyCutFilter::kReference}, {"all", SkinnyCutFilter::kAll}, {"off", SkinnyCutFilter::kOff}});
  read_option_rows(*vm, decomposition_option_rows(), options);
  if (!output.empty()) check_outputs({output}, {input});

  const PolygonWithHoles polygon = read_polygon_json(input);
  const Decomposition result = decompose(polygon, options);
  if (!result.complete) {
    std::cerr << "warning: stopped after " << result.rounds << " rounds (--max-rounds) with cuts still to make: "
              << "the pieces tile the polygon but some may be deeper than tau\n";
  }

  const std::string text = decomposition_to_json(result);
  if (output.empty()) {
    std::cout << text;
  } else {
    write_file_atomically(output, text);
  }
  return 0;
}

const bool registered = register_command(
    {"decompose", "split a polygon (JSON) into nearly convex pieces (dual-space decomposition)", &run});

}  // namespace
}  // namespace topocut::cli
