// libFuzzer target: scan CSV parsing. Any text must give a scan with one finite, strictly
// increasing angle per range, or a topocut::Error; the scan must survive a format/parse round trip.
#include <cmath>
#include <cstdint>
#include <string>

#include "fuzz_input.h"
#include "topocut/core/error.h"
#include "topocut/scan/scan_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topocut;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Scan scan;
  try {
    scan = parse_scan_csv(text, "fuzz.csv");
  } catch (const Error&) {
    return 0;
  }
  if (scan.angles.size() != scan.ranges.size()) fuzz::fail("angles and ranges differ in count");
  for (std::size_t i = 0; i < scan.angles.size(); ++i) {
    if (!std::isfinite(scan.angles[i])) fuzz::fail("accepted a non-finite angle");
    if (i > 0 && !(scan.angles[i] > scan.angles[i - 1])) fuzz::fail("accepted non-increasing angles");
  }
  Scan again;
  try {
    again = parse_scan_csv(format_scan_csv(scan), "round trip");
  } catch (const Error& e) {
    fuzz::fail(std::string("format_scan_csv output does not parse: ") + e.what());
  }
  if (again.angles != scan.angles) fuzz::fail("angles change in a format/parse round trip");
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double a = scan.ranges[i], b = again.ranges[i];
    if (!(a == b || (std::isnan(a) && std::isnan(b)))) fuzz::fail("ranges change in a format/parse round trip");
  }
  return 0;
}
