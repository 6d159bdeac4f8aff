#pragma once
// The one exception type of the library: every failure that a user can cause (bad files, bad
// options, impossible input) is reported as an Error whose message is a complete sentence fit for
// one line on stderr.
#include <stdexcept>
#include <string>

namespace topocut {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace topocut
