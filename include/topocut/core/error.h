#pragma once
// The one exception type of the library: every failure that a user can cause (bad files, bad
// options, impossible input) is reported as an Error whose message is a complete sentence fit for
// one line on stderr.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace topocut {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// A message fit for one line of a terminal: line breaks and control characters become spaces, a
// word longer than 60 characters (a path, a token quoted from a bad file) keeps only its two ends,
// and the whole is cut to at most max_length characters.
std::string one_line_message(const std::string& message, std::size_t max_length = 200);

}  // namespace topocut
