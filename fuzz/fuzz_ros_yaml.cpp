// libFuzzer target: ROS map_server YAML parsing. Any text must give metadata that satisfies the
// documented invariants or a topocut::Error (never a yaml-cpp exception, crash or hang).
#include <cmath>
#include <cstdint>
#include <string>

#include "fuzz_input.h"
#include "topocut/core/error.h"
#include "topocut/io/map_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topocut;
  const std::string text(reinterpret_cast<const char*>(data), size);
  RosMapMetadata m;
  try {
    m = parse_ros_map_yaml(text, "fuzz.yaml");
  } catch (const Error&) {
    return 0;
  }
  if (m.image.empty()) fuzz::fail("accepted an empty image name");
  if (!(m.resolution > 0.0) || !std::isfinite(m.resolution)) fuzz::fail("accepted a non-positive or non-finite resolution");
  if (!std::isfinite(m.origin.x) || !std::isfinite(m.origin.y)) fuzz::fail("accepted a non-finite origin");
  if (!(m.free_thresh >= 0.0 && m.free_thresh <= m.occupied_thresh && m.occupied_thresh <= 1.0))
    fuzz::fail("accepted thresholds outside 0 <= free <= occupied <= 1");
  return 0;
}
