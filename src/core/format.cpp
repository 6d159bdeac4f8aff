#include "topocut/core/format.h"

#include <cstdarg>
#include <cstdio>

namespace topocut {

std::string format(const char* pattern, ...) {
  va_list arguments;
  va_start(arguments, pattern);
  va_list again;
  va_copy(again, arguments);
  char buffer[256];
  const int length = std::vsnprintf(buffer, sizeof buffer, pattern, arguments);
  va_end(arguments);
  std::string out;
  if (length < 0) {
    out = pattern;  // an invalid pattern: show it rather than nothing
  } else if (static_cast<std::size_t>(length) < sizeof buffer) {
    out.assign(buffer, static_cast<std::size_t>(length));
  } else {
    out.resize(static_cast<std::size_t>(length) + 1);
    std::vsnprintf(out.data(), out.size(), pattern, again);
    out.resize(static_cast<std::size_t>(length));
  }
  va_end(again);
  return out;
}

std::string fixed(double value, int decimals) { return format("%.*f", decimals, value); }

}  // namespace topocut
