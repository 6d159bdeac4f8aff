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

// The scan labelled and the centres asked for.
struct LabelRequest {
  std::string scan;
  int clusters = 0;  // fuzzy c-means centres per segment; 0: none
};

const std::vector<TextRow<LabelRequest>>& scan_rows() {
  static const std::vector<TextRow<LabelRequest>> rows = {path_row(
      "scan", "SCAN", TextKind::kInput, &LabelRequest::scan, "scan CSV (header angle,range; radians, metres; - for standard input)", true)};
  return rows;
}

const std::vector<OptionRow<LabelRequest>>& centre_rows() {
  static const std::vector<OptionRow<LabelRequest>> rows = {field_row(
      "fcm", "K", OptionRange::kWholeNumber, &LabelRequest::clusters, "fuzzy c-means centres per segment (0: none)")};
  return rows;
}

int run(const std::vector<std::string>& args) {
  LabelRequest request;
  LabelingOptions options;
  po::options_description described("Labeling");
  add_text_rows(described, scan_rows());
  add_option_rows(described, labeling_option_rows(), options);
  add_choice_rows(described, labeling_choice_rows(), options);
  add_option_rows(described, centre_rows(), request);
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
  read_text_rows(*vm, scan_rows(), request);
  read_option_rows(*vm, centre_rows(), request);

  const Scan scan = read_scan_csv(request.scan);
  const Labeling labeling = label_scan(scan, options);

  std::vector<std::vector<Point2>> centres;
  if (request.clusters > 0) {
    FuzzyCMeansOptions fcm;
    fcm.clusters = request.clusters;
    centres = segment_centres(scan, labeling, fcm);
  }
  std::cout << labeling_to_json(request.scan, scan, options, labeling, centres);
  return 0;
}

const bool registered = register_command({"label", "label a laser scan into segments (sparse connected components)", &run});

}  // namespace
}  // namespace topocut::cli
