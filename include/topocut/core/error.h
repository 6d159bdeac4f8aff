#pragma once
// The one exception type of the library: every failure that a user can cause (bad files, bad
// options, impossible input) is reported as an Error whose message is a complete sentence fit for
// one line on stderr.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace topocut {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// An Error about a file the system does not have or refused to open, with the errno value (ENOENT,
// EACCES, EISDIR, ...) and the path, so that a front end can raise its own kind of error (Python's
// FileNotFoundError, PermissionError).
class FileError : public Error {
 public:
  FileError(int error_number, std::string path, const std::string& message)
      : Error(message), error_number_(error_number), path_(std::move(path)) {}
  int error_number() const { return error_number_; }
  const std::string& path() const { return path_; }

 private:
  int error_number_;
  std::string path_;
};

// A message fit for one line of a terminal: line breaks and control characters become spaces, a
// word longer than 60 characters (a path, a token quoted from a bad file) keeps only its two ends,
// and the whole is cut to at most max_length characters.
std::string one_line_message(const std::string& message, std::size_t max_length = 200);

}  // namespace topocut
