#pragma once
// Runs the built topocut binary as a user would (a separate process, a shell-quoted command line)
// and captures its exit code, stdout and stderr, for the command-line tests.
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
  int code = -1;  // exit code, -1 when killed by a signal
  std::string out;
  std::string err;
};

inline std::string slurp_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// `topocut ARGS...` with stdout and stderr captured in files of dir (removed afterwards).
inline CliResult run_topocut(const TempDir& dir, const std::vector<std::string>& args) {
  std::string command = shell_quote(TOPOCUT_CLI);
  for (const std::string& a : args) command += " " + shell_quote(a);
  const std::string out = dir.file(".cli_stdout"), err = dir.file(".cli_stderr");
  command += " >" + shell_quote(out) + " 2>" + shell_quote(err);
  const int status = std::system(command.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp_file(out);
  r.err = slurp_file(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// A failed run: the exit code, and exactly one line on stderr that names the problem.
inline void expect_one_line_error(const CliResult& r, const std::string& fragment, int code = 1) {
  EXPECT_EQ(r.code, code) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
}

}  // namespace topocut::testing
