#pragma once
// One entry point for the five line extractors, chosen by a method enum; each method keeps its own
// options struct (defaults from the literature) and its own function in the header named after it.
#include <string>
#include <vector>

#include "topocut/core/option_choice.h"
#include "topocut/core/option_table.h"
#include "topocut/lines/ale.h"
#include "topocut/lines/iepf.h"
#include "topocut/lines/line.h"
#include "topocut/lines/line_tracking.h"
#include "topocut/lines/sef.h"
#include "topocut/lines/smf.h"
#include "topocut/scan/scan.h"

namespace topocut {

enum class LineMethod { kSef, kLt, kIepf, kSmf, kAle };

struct LineExtractionOptions {
  LineMethod method = LineMethod::kSmf;
  SefOptions sef;
  LtOptions lt;
  IepfOptions iepf;
  SmfOptions smf;
  AleOptions ale;
};

// Lines of the scan by the chosen method. Invalid beams are skipped (support rows stay those of the
// scan); fewer than two valid beams give no lines. Throws Error on inconsistent scans (sizes, angles
// not strictly increasing) and on bad options.
std::vector<Line> extract_lines(const Scan& scan, const LineExtractionOptions& options = {});

// "sef", "lt", "iepf", "smf", "ale".
std::string to_string(LineMethod method);

// Parses a method name (case-insensitive); throws Error listing the valid names otherwise.
LineMethod parse_line_method(const std::string& name);

// A tuning option of the extractors as people give it (the lines command): its row, which sets the
// field in every method that has one (get reads the first method's), and those methods.
struct LineOptionRow {
  OptionRow<LineExtractionOptions> row;
  std::vector<LineMethod> methods;
};

// d-max, t-max, sigma-max, fuzzifier, rmse-min, rmse-max, gradient-max, reference-noise,
// smoothing-neighbours, lambda-deg, sigma-r, min-points. Defined in option_rows.cpp.
const std::vector<LineOptionRow>& line_option_rows();

// The extractor chosen by name (--method sef|lt|iepf|smf|ale, Python's method=): names in lower case,
// one spelling everywhere (parse_line_method() also reads other cases, for the library's callers).
const std::vector<ChoiceRow<LineExtractionOptions>>& line_choice_rows();

}  // namespace topocut
