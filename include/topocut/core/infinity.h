#pragma once
// Infinity as a double, under one name for the whole library: the distance when nothing was found, the
// start of a minimum, the bounds of an empty box.
#include <limits>

namespace topocut {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace topocut
