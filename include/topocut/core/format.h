#pragma once
// printf-style formatting into a std::string: the one helper the reports, tables and progress lines
// use for numbers with a fixed count of decimals.
#include <string>

namespace topocut {

// The text std::printf would print for pattern and its arguments, of any length. The compiler checks
// the arguments against the pattern.
std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

// value with exactly decimals digits after the point, as "%.*f" prints it.
std::string fixed(double value, int decimals);

}  // namespace topocut
