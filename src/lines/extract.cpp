#include "topocut/lines/extract.h"

#include <algorithm>
#include <cctype>

#include "topocut/core/error.h"

namespace topocut {

std::vector<Line> extract_lines(const Scan& scan, const LineExtractionOptions& options) {
  switch (options.method) {
    case LineMethod::kSef: return extract_lines_sef(scan, options.sef);
    case LineMethod::kLt: return extract_lines_lt(scan, options.lt);
    case LineMethod::kIepf: return extract_lines_iepf(scan, options.iepf);
    case LineMethod::kSmf: return extract_lines_smf(scan, options.smf);
    case LineMethod::kAle: return extract_lines_ale(scan, options.ale);
  }
  throw Error("unknown line extraction method");
}

std::string to_string(LineMethod method) {
  switch (method) {
    case LineMethod::kSef: return "sef";
    case LineMethod::kLt: return "lt";
    case LineMethod::kIepf: return "iepf";
    case LineMethod::kSmf: return "smf";
    case LineMethod::kAle: return "ale";
  }
  return "unknown";
}

LineMethod parse_line_method(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const LineMethod m : {LineMethod::kSef, LineMethod::kLt, LineMethod::kIepf, LineMethod::kSmf, LineMethod::kAle})
    if (to_string(m) == lower) return m;
  throw Error("unknown line extraction method '" + name + "' (expected sef, lt, iepf, smf or ale)");
}

}  // namespace topocut
