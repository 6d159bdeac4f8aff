#pragma once
// The one way the CLI tests run the topocut binary: a separate process under a time limit, its exit
// code, stdout and stderr collected, for tests of what a user sees.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/temp_dir.h"

namespace topocut::testing {

struct CliResult {
  int code = -1;  // 124: killed by the time limit
  std::string out;
  std::string err;
};

inline std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// `topocut ARGUMENTS` (a shell fragment: quoted as the caller needs, may redirect stdin) with
// stdout and stderr captured through files in dir, killed after `seconds` (exit code 124); `before`
// is a shell fragment run first in the same shell (a ulimit).
inline CliResult run_cli_line(const std::filesystem::path& dir, const std::string& arguments, int seconds = 600,
                              const std::string& before = "") {
  const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + a temporary string.
  std::string line = before;
  line += "timeout -s KILL ";
  line += std::to_string(seconds);
  line += ' ';
  line += shell_quoted(TOPOCUT_CLI);
  line += ' ';
  line += arguments;
  line += " >";
  line += shell_quoted(out);
  line += " 2>";
  line += shell_quoted(err);
  const int status = std::system(line.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (r.code == 137) r.code = 124;  // timeout -s KILL reports 128 + 9
  r.out = file_text(out);
  r.err = file_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// A memory limit of kilobytes for run_cli_line's `before` ("ulimit -v KB;"), or none in a build with
// AddressSanitizer: it reserves terabytes of address space at start, so under any such limit every
// run aborts before main(). There the test still checks the message and the time.
inline std::string memory_limit(long kilobytes) {
#if defined(__SANITIZE_ADDRESS__)
  static_cast<void>(kilobytes);
  return "";
#else
  return "ulimit -v " + std::to_string(kilobytes) + ";";
#endif
}

// The arguments shell-quoted one by one, each after a space.
inline std::string quoted_arguments(const std::vector<std::string>& args) {
  std::string line;
  for (const std::string& a : args) {
    line += ' ';
    line += shell_quoted(a);
  }
  return line;
}

// `topocut COMMAND ARGS...` with stdin from stdin_path, killed after `seconds` (exit code 124).
inline CliResult run_cli(const TempDir& dir, const std::string& command, const std::vector<std::string>& args,
                         int seconds = 10, const std::string& stdin_path = "/dev/null") {
  std::string line = command + quoted_arguments(args);
  line += " <";
  line += shell_quoted(stdin_path);
  return run_cli_line(dir.path(), line, seconds);
}

// A clean failure: the given exit code, one line on stderr naming the command and containing fragment.
inline void expect_clean_error(const CliResult& r, const std::string& command, const std::string& fragment, int code = 1) {
  EXPECT_EQ(r.code, code) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("topocut " + command + ": error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << "expected '" << fragment << "' in: " << r.err;
}

}  // namespace topocut::testing
