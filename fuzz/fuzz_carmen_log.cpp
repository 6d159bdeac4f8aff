// libFuzzer target: CARMEN log parsing. Any text must give scans with finite poses, at least two
// beams and a positive max_range, or a topocut::Error.
#include <cmath>
#include <cstdint>
#include <string_view>

#include "fuzz_input.h"
#include "topocut/core/error.h"
#include "topocut/io/carmen_log.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topocut;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  CarmenLog log;
  try {
    log = parse_carmen_log(text, "fuzz.log");
  } catch (const Error&) {
    return 0;
  }
  if (!(log.max_range > 0.0) || !std::isfinite(log.max_range)) fuzz::fail("max_range not positive and finite");
  for (const CarmenLaserScan& scan : log.scans) {
    if (scan.ranges.size() < 2) fuzz::fail("accepted a scan with fewer than two beams");
    if (!std::isfinite(scan.pose.x) || !std::isfinite(scan.pose.y) || !std::isfinite(scan.pose.theta))
      fuzz::fail("accepted a non-finite pose");
    if (!std::isfinite(scan.angle_step) || !std::isfinite(scan.start_angle)) fuzz::fail("non-finite beam angles");
    if (scan.line == 0 || scan.line > log.lines) fuzz::fail("scan line number outside the log");
  }
  return 0;
}
