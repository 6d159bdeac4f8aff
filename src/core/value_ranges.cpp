#include "topocut/core/value_ranges.h"

#include <cmath>
#include <sstream>

#include "topocut/core/error.h"

namespace topocut {

namespace {

[[noreturn]] void out_of_range(const std::string& what, const char* interval, double lo, double hi, const std::string& unit,
                               double value) {
  std::ostringstream text;
  text << what << " must lie in " << interval[0] << lo << ", " << hi << interval[1] << " " << unit << ", got " << value;
  throw Error(text.str());
}

}  // namespace

void check_resolution(double r, const std::string& what) {
  if (!(r >= kMinResolution && r <= kMaxResolution)) out_of_range(what, "[]", kMinResolution, kMaxResolution, "metres per cell", r);
}

void check_world_coordinate(double v, const std::string& what) {
  if (!(std::abs(v) <= kMaxWorldCoordinate)) out_of_range(what, "[]", -kMaxWorldCoordinate, kMaxWorldCoordinate, "metres", v);
}

void check_length(double v, const std::string& what, bool zero_allowed) {
  const bool ok = zero_allowed ? v >= 0.0 && v <= kMaxLength : v > 0.0 && v <= kMaxLength;
  if (!ok) out_of_range(what, zero_allowed ? "[]" : "(]", 0.0, kMaxLength, "metres", v);
}

void check_area(double v, const std::string& what) {
  if (!(v >= 0.0 && v <= kMaxLength * kMaxLength)) out_of_range(what, "[]", 0.0, kMaxLength * kMaxLength, "square metres", v);
}

}  // namespace topocut
