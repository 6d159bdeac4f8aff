// topocut label: sparse connected-component labeling of one laser scan, printed as JSON.
#include <iostream>

#include "cli/command.h"
#include "cli/library_options.h"
#include "topocut/core/error.h"
#include "topocut/labeling/labeling_json.h"
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/labeling/segment_centres.h"
#include "topocut/scan/scan_csv.h"

namespace topocut::cli {
namespace {

int run(const std::vector<std::string>& args) {
  std::string scan_path;
  LabelingOptions options;
  int clusters = 0;
  po::options_description described("Labeling");
  described.add_options()
      ("scan", po::value<std::string>(&scan_path)->required(), "scan CSV (header angle,range; radians, metres; - for standard input)");
  add_option_rows(described, labeling_option_rows(), options);
  add_choice_rows(described, labeling_choice_rows(), options);
  described.add_options()
      ("fcm", po::value<int>(&clusters)->default_value(0), "fuzzy c-means centres per segment (0: none)");
  po::positional_options_description positional;
  positional.add("scan", 1);
  const auto vm = parse_options(
      "topocut label SCAN.csv [options]",
      "Rasterizes the scan's points, dilates, labels connected components (Ravankar et al.) and prints\n"
      "the segments as JSON: for each segment the beam indices (rows of the CSV) and, with --fcm K,\n"
      "up to K fuzzy c-means centres in the sensor frame, ordered along the segment.",
      described, positional, args);
  if (!vm) return 0;
  read_option_rows(*vm, labeling_option_rows(), options);
  read_choice_rows(*vm, labeling_choice_rows(), options);
  if (clusters < 0) throw UsageError("--fcm must be 0 or a positive number of centres");

  const Scan scan = read_scan_csv(scan_path);
  const Labeling labeling = label_scan(scan, options);

  std::vector<std::vector<Point2>> centres;
  if (clusters > 0) {
    FuzzyCMeansOptions fcm;
    fcm.clusters = clusters;
    centres = segment_centres(scan, labeling, fcm);
  }
  std::cout << labeling_to_json(scan_path, scan, options, labeling, centres);
  return 0;
}

const bool registered = register_command({"label", "label a laser scan into segments (sparse connected components)", &run});

}  // namespace
}  // namespace topocut::cli
