// topocut lines: extract wall lines from one laser scan (CSV) with one of the five extractors and
// print them as JSON (DESIGN.md "Data formats") or CSV.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "cli/command.h"
#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/output_files.h"
#include "topocut/lines/extract.h"
#include "topocut/lines/lines_format.h"
#include "topocut/scan/scan_csv.h"

namespace topocut::cli {
namespace {

int run(const std::vector<std::string>& args) {
  std::string scan_path, method_name = "smf", format = "json", output;
  po::options_description described("Line extraction");
  described.add_options()
      ("scan", po::value<std::string>(&scan_path)->required(), "scan CSV (header angle,range; radians, metres; - for standard input)")
      ("method", po::value<std::string>(&method_name)->default_value(method_name), "sef, lt, iepf, smf or ale")
      ("format", po::value<std::string>(&format)->default_value(format), "json or csv")
      ("output,o", po::value<std::string>(&output), "write to this file instead of standard output");
  po::options_description tuning("Method options (defaults from the literature; see the library headers)");
  for (const LineOptionRow& option : line_option_rows())  // no default shown: each method has its own
    tuning.add_options()(option.row.name.c_str(), po::value<std::string>()->value_name(option.row.value_name), option.row.help.c_str());
  described.add(tuning);
  po::positional_options_description positional;
  positional.add("scan", 1);
  const auto vm = parse_options(
      "topocut lines SCAN.csv [--method sef|lt|iepf|smf|ale] [--OPTION VALUE ...] [--format json|csv]",
      "Extracts wall lines from one laser scan. Each line has its polar parameters (rho >= 0, alpha in\n"
      "(-pi, pi], sensor frame), its end points (extreme projections of its beams) and its support: the\n"
      "beam indices (data rows of the CSV, from 0). Invalid readings (nan, inf, 0, negative) are skipped.\n"
      "JSON: [{\"rho\":..., \"alpha\":..., \"start\":[x,y], \"end\":[x,y], \"support\":[i,...]}, ...]",
      described, positional, args);
  if (!vm) return 0;

  LineExtractionOptions options;
  check_usage([&] { options.method = parse_line_method(method_name); });
  if (format != "json" && format != "csv") throw UsageError("--format must be 'json' or 'csv', got '" + format + "'");
  for (const LineOptionRow& option : line_option_rows()) {
    const std::string shown = "--" + option.row.name;
    if (!vm->count(option.row.name)) continue;
    if (std::find(option.methods.begin(), option.methods.end(), options.method) == option.methods.end())
      throw UsageError(shown + " does not apply to --method " + to_string(options.method));
    check_usage([&] { set_option(option.row, options, parse_option_number((*vm)[option.row.name].as<std::string>(), shown), shown); });
  }
  if (!output.empty()) check_outputs({output}, {scan_path});

  const Scan scan = read_scan_csv(scan_path);
  const std::vector<Line> lines = extract_lines(scan, options);
  const std::string text = format == "json" ? format_lines_json(lines) : format_lines_csv(lines);
  if (output.empty()) {
    std::cout << text << std::flush;
  } else {
    write_file_atomically(output, text);
  }
  return 0;
}

const bool registered =
    register_command({"lines", "extract wall lines from a laser scan (SEF, LT, IEPF, SMF or ALE)", &run});

}  // namespace
}  // namespace topocut::cli
