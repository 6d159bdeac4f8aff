// topocut lines: extract wall lines from one laser scan (CSV) with one of the five extractors and
// print them as JSON (DESIGN.md "Data formats") or CSV.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/library_options.h"
#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/output_files.h"
#include "topocut/lines/extract.h"
#include "topocut/lines/lines_format.h"
#include "topocut/scan/scan_csv.h"

namespace topocut::cli {
namespace {

// The scan read and how the lines are written.
struct LinesRequest {
  std::string scan, output, format = "json";
};

const std::vector<TextRow<LinesRequest>>& request_rows() {
  static const std::vector<TextRow<LinesRequest>> rows = {
      path_row("scan", "SCAN", TextKind::kInput, &LinesRequest::scan,
               "scan CSV (header angle,range; radians, metres; - for standard input)", true),
      path_row("output", "FILE", TextKind::kOutput, &LinesRequest::output, "write to this file instead of standard output", false, "o")};
  return rows;
}

const std::vector<ChoiceRow<LinesRequest>>& format_rows() {
  static const std::vector<ChoiceRow<LinesRequest>> rows = {choice_row<LinesRequest, std::string>(
      "format", &LinesRequest::format, {{"json", "json"}, {"csv", "csv"}}, "how the lines are printed")};
  return rows;
}

int run(const std::vector<std::string>& args) {
  LinesRequest request;
  LineExtractionOptions options;
  po::options_description described("Line extraction");
  add_text_rows(described, request_rows());
  add_choice_rows(described, line_choice_rows(), options);
  add_choice_rows(described, format_rows(), request);
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

  read_text_rows(*vm, request_rows(), request);
  read_choice_rows(*vm, line_choice_rows(), options);
  read_choice_rows(*vm, format_rows(), request);
  for (const LineOptionRow& option : line_option_rows()) {
    const std::string shown = "--" + option.row.name;
    if (!vm->count(option.row.name)) continue;
    if (std::find(option.methods.begin(), option.methods.end(), options.method) == option.methods.end())
      throw UsageError(shown + " does not apply to --method " + to_string(options.method));
    check_usage([&] { set_option(option.row, options, parse_option_number((*vm)[option.row.name].as<std::string>(), shown), shown); });
  }
  if (!request.output.empty()) check_outputs({request.output}, {request.scan});

  const Scan scan = read_scan_csv(request.scan);
  const std::vector<Line> lines = extract_lines(scan, options);
  const std::string text = request.format == "json" ? format_lines_json(lines) : format_lines_csv(lines);
  if (request.output.empty()) {
    std::cout << text << std::flush;
  } else {
    write_file_atomically(request.output, text);
  }
  return 0;
}

const bool registered =
    register_command({"lines", "extract wall lines from a laser scan (SEF, LT, IEPF, SMF or ALE)", &run});

}  // namespace
}  // namespace topocut::cli
