// libFuzzer target: the polygon JSON of `topocut decompose`. Any text must give finite rings or a
// topocut::Error (never a nlohmann exception, crash or hang).
#include <cmath>
#include <cstdint>
#include <string>

#include "fuzz_input.h"
#include "topocut/core/error.h"
#include "topocut/io/polygon_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topocut;
  const std::string text(reinterpret_cast<const char*>(data), size);
  PolygonWithHoles polygon;
  try {
    polygon = parse_polygon_json(text, "fuzz.json");
  } catch (const Error&) {
    return 0;
  }
  const auto check = [](const Ring& ring) {
    for (const Point2& p : ring) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) fuzz::fail("accepted a non-finite coordinate");
    }
  };
  check(polygon.outer);
  for (const Ring& hole : polygon.holes) check(hole);
  return 0;
}
