// topocut lines: extract wall lines from one laser scan (CSV) with one of the five extractors and
// print them as JSON (DESIGN.md "Data formats") or CSV.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
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

// An option that only some methods understand: its flag, the methods, and how to apply it.
struct MethodOption {
  const char* flag;
  const char* help;
  std::vector<LineMethod> methods;
  void (*apply)(LineExtractionOptions&, double);
};

std::size_t to_count(double v, const char* flag) {
  if (!(v >= 1.0) || v != std::floor(v) || v > 1e9)
    throw UsageError(std::string("--") + flag + " must be a positive whole number");
  return static_cast<std::size_t>(v);
}

const std::vector<MethodOption>& method_options() {
  using M = LineMethod;
  static const std::vector<MethodOption> table{
      {"d-max", "SEF, LT: gap between consecutive points that ends a line (m)", {M::kSef, M::kLt},
       [](LineExtractionOptions& o, double v) { o.sef.d_max = o.lt.d_max = v; }},
      {"t-max", "SEF, LT, IEPF: distance threshold T_max (m)", {M::kSef, M::kLt, M::kIepf},
       [](LineExtractionOptions& o, double v) { o.sef.t_max = o.lt.t_max = o.iepf.t_max = v; }},
      {"sigma-max", "SMF: dispersion threshold sigma_max (m)", {M::kSmf},
       [](LineExtractionOptions& o, double v) { o.smf.sigma_max = v; }},
      {"fuzzifier", "SMF: fuzzifier m (> 1)", {M::kSmf}, [](LineExtractionOptions& o, double v) { o.smf.fuzzifier = v; }},
      {"rmse-min", "ALE: lower RMSE threshold (m, before noise scaling)", {M::kAle},
       [](LineExtractionOptions& o, double v) { o.ale.rmse_min = v; }},
      {"rmse-max", "ALE: upper RMSE threshold (m, before noise scaling)", {M::kAle},
       [](LineExtractionOptions& o, double v) { o.ale.rmse_max = v; }},
      {"gradient-max", "ALE: relative RMSE gradient that marks a corner", {M::kAle},
       [](LineExtractionOptions& o, double v) { o.ale.gradient_max = v; }},
      {"reference-noise", "ALE: range noise for which the RMSE band holds unscaled (m; 0: never scale)", {M::kAle},
       [](LineExtractionOptions& o, double v) { o.ale.reference_noise = v; }},
      {"smoothing-neighbours", "ALE: lowess neighbourhood in beams", {M::kAle},
       [](LineExtractionOptions& o, double v) { o.ale.smoothing.neighbours = to_count(v, "smoothing-neighbours"); }},
      {"lambda-deg", "IEPF, SMF, ALE: breakpoint angle lambda (degrees)", {M::kIepf, M::kSmf, M::kAle},
       [](LineExtractionOptions& o, double v) {
         o.iepf.breakpoints.lambda = o.smf.breakpoints.lambda = o.ale.breakpoints.lambda = v * std::numbers::pi / 180.0;
       }},
      {"sigma-r", "IEPF, SMF, ALE: range noise for breakpoints (m; 0: estimate from the scan)", {M::kIepf, M::kSmf, M::kAle},
       [](LineExtractionOptions& o, double v) {
         o.iepf.breakpoints.sigma_r = o.smf.breakpoints.sigma_r = o.ale.breakpoints.sigma_r = v;
       }},
      {"min-points", "all: fewest beams a reported line may have", {M::kSef, M::kLt, M::kIepf, M::kSmf, M::kAle},
       [](LineExtractionOptions& o, double v) {
         const std::size_t n = to_count(v, "min-points");
         o.sef.min_points = o.lt.min_points = o.iepf.min_points = o.smf.min_points = o.ale.min_points = n;
       }},
  };
  return table;
}

int run(const std::vector<std::string>& args) {
  std::string scan_path, method_name = "smf", format = "json", output;
  po::options_description described("Line extraction");
  described.add_options()
      ("scan", po::value<std::string>(&scan_path)->required(), "scan CSV (header angle,range; radians, metres; - for standard input)")
      ("method", po::value<std::string>(&method_name)->default_value(method_name), "sef, lt, iepf, smf or ale")
      ("format", po::value<std::string>(&format)->default_value(format), "json or csv")
      ("output,o", po::value<std::string>(&output), "write to this file instead of standard output");
  po::options_description tuning("Method options (defaults from the literature; see the library headers)");
  for (const MethodOption& option : method_options())
    tuning.add_options()(option.flag, po::value<double>(), option.help);
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
  for (const MethodOption& option : method_options()) {
    if (!vm->count(option.flag)) continue;
    if (std::find(option.methods.begin(), option.methods.end(), options.method) == option.methods.end())
      throw UsageError(std::string("--") + option.flag + " does not apply to --method " + to_string(options.method));
    const double value = (*vm)[option.flag].as<double>();
    if (!std::isfinite(value)) throw UsageError(std::string("--") + option.flag + " must be a finite number");
    option.apply(options, value);
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
