#pragma once
// Scan CSV (DESIGN.md "Data formats"): a header `angle,range`, then one beam per row in radians and
// metres; the n-th data row is beam n. Ranges may be `nan`, `inf` or 0 (kept as invalid beams);
// angles must be finite and strictly increasing.
#include <iosfwd>
#include <string>

#include "topocut/scan/scan.h"

namespace topocut {

// Parses scan CSV text; `source` names it in errors. Throws Error with the line number on a missing
// or wrong header, a wrong column count, a non-numeric field, a non-finite or non-increasing angle.
Scan parse_scan_csv(const std::string& text, const std::string& source = "scan");

// Reads a scan CSV file ("-": standard input; regular files only, at most kMaxScanCsvBytes) and
// parses it (see parse_scan_csv); errors name the path and the line.
Scan read_scan_csv(const std::string& path);

// Formats a scan as CSV that parse_scan_csv reads back bit for bit (shortest round-trip digits).
std::string format_scan_csv(const Scan& scan);

}  // namespace topocut
