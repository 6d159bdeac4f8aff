#pragma once
// The outputs of one run, treated as one unit: checked together before any work, staged in private
// temporary files while the run writes them, and put in place only when the whole run succeeded. A
// failure, an exception or SIGINT/SIGTERM/SIGHUP leaves every earlier file as it was and no
// temporary file behind.
#include <string>
#include <vector>

namespace topocut {

// Throws Error naming the first output that could not be written safely: one that cannot be created,
// one that is also an input of the run (the same file under any name), two outputs on the same
// file, or an existing target that is neither a regular file nor a character device (character
// devices such as /dev/stdout or /dev/null are written to directly, never replaced).
void check_outputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);

// While an OutputRun is open, write_file_atomically stages each file and commit() puts all of them
// in place; without commit() (an error, an exception) the staged files are removed. One per process.
class OutputRun {
 public:
  OutputRun();
  ~OutputRun();
  OutputRun(const OutputRun&) = delete;
  OutputRun& operator=(const OutputRun&) = delete;

  // Renames every staged file over its target (and writes device targets); throws Error on the first
  // failure, after which the files not yet committed are removed.
  void commit();
};

}  // namespace topocut
