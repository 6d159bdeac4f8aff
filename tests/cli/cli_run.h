#pragma once
// Runs the topocut binary as a separate process under a time limit and collects exit code, stdout
// and stderr, for tests of what a user sees.
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

// `topocut COMMAND ARGS...` with stdin from stdin_path, killed after `seconds` (exit code 124).
inline CliResult run_cli(const TempDir& dir, const std::string& command, const std::vector<std::string>& args,
                         int seconds = 10, const std::string& stdin_path = "/dev/null") {
  std::string line = "timeout -s KILL " + std::to_string(seconds) + " " + shell_quoted(TOPOCUT_CLI) + " " + command;
  for (const std::string& a : args) line += " " + shell_quoted(a);
  line += " <" + shell_quoted(stdin_path) + " >" + shell_quoted(dir.file("stdout.txt")) + " 2>" +
          shell_quoted(dir.file("stderr.txt"));
  const int status = std::system(line.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (r.code == 137) r.code = 124;  // timeout -s KILL reports 128 + 9
  r.out = file_text(dir.file("stdout.txt"));
  r.err = file_text(dir.file("stderr.txt"));
  std::filesystem::remove(dir.file("stdout.txt"));
  std::filesystem::remove(dir.file("stderr.txt"));
  return r;
}

// A clean failure: the given exit code, one line on stderr naming the command and containing fragment.
inline void expect_clean_error(const CliResult& r, const std::string& command, const std::string& fragment, int code = 1) {
  EXPECT_EQ(r.code, code) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("topocut " + command + ": error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << "expected '" << fragment << "' in: " << r.err;
}

}  // namespace topocut::testing
