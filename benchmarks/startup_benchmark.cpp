// Start-up as a user pays it: the topocut command run as a whole process, N times, its wall time
// and peak memory (wait4's rusage), for `topocut --version` and for `topocut segment` on the bundled
// floor plan; for the latter also the ratio of the whole process to the time topocut itself reports
// (loading + segmentation), and an empty process (/bin/true) as the machine's floor under the same
// load, and empty programs linked with OpenCV core + imgproc and with core alone
// (benchmarks/startup/opencv_floor.cpp), the floor of any binary that uses cv::Mat. With --base, an
// older binary is measured in the same run, alternating run by run so that both see the same machine
// load. Options: --help.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/benchmark_main.h"

namespace {

struct Run {
  double wall_ms = 0, cpu_ms = 0, rss_mb = 0, inside_ms = -1;
};

struct Case {
  std::string binary, label, command;
  std::vector<std::string> args;
  std::vector<Run> runs;
};

std::string read_all(int fd) {
  std::string out;
  char buffer[4096];
  ssize_t n = 0;
  while ((n = ::read(fd, buffer, sizeof buffer)) > 0) out.append(buffer, static_cast<std::size_t>(n));
  return out;
}

// The segmentation and loading times topocut prints ("in X ms (loading Y ms)"), summed; -1 if absent.
double reported_ms(const std::string& out) {
  static const std::regex pattern(R"( in ([0-9.]+) ms \(loading ([0-9.]+) ms\))");
  std::smatch m;
  if (!std::regex_search(out, m, pattern)) return -1.0;
  return std::stod(m[1]) + std::stod(m[2]);
}

Run run_once(const std::string& binary, const std::vector<std::string>& args) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) throw std::runtime_error("no pipe");
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(pipe_fds[1], STDOUT_FILENO);
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    std::vector<char*> argv{const_cast<char*>(binary.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(binary.c_str(), argv.data());
    std::_Exit(127);
  }
  ::close(pipe_fds[1]);
  const std::string out = read_all(pipe_fds[0]);
  ::close(pipe_fds[0]);
  int status = 0;
  rusage usage{};
  ::wait4(pid, &status, 0, &usage);
  const auto end = std::chrono::steady_clock::now();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw std::runtime_error(binary + " failed");
  Run r;
  r.wall_ms = std::chrono::duration<double, std::milli>(end - start).count();
  const auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec / 1e3; };
  r.cpu_ms = ms(usage.ru_utime) + ms(usage.ru_stime);
  r.rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  r.inside_ms = reported_ms(out);
  return r;
}

struct Stats {
  double median = 0, min = 0, max = 0;
};

Stats stats(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return {n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0, v.front(), v.back()};
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::vector<double> column(const Case& c, double Run::*field) {
  std::vector<double> v;
  for (const Run& r : c.runs) v.push_back(r.*field);
  return v;
}

void print_table(const std::vector<Case>& cases) {
  std::cout << "| binary | command | wall ms (median / min / max) | CPU ms (median) | max RSS MB (median) | "
               "in-process ms (median) | whole / in-process (median) |\n"
            << "|---|---|---|---|---|---|---|\n";
  for (const Case& c : cases) {
    const Stats wall = stats(column(c, &Run::wall_ms));
    std::string inside = "-", ratio = "-";
    if (c.runs.front().inside_ms > 0) {
      std::vector<double> ratios;
      for (const Run& r : c.runs) ratios.push_back(r.wall_ms / r.inside_ms);
      inside = fixed(stats(column(c, &Run::inside_ms)).median, 1);
      ratio = fixed(stats(ratios).median, 2);
    }
    std::cout << "| " << c.label << " | `" << c.command << "` | "
              << fixed(wall.median, 1) << " / " << fixed(wall.min, 1) << " / " << fixed(wall.max, 1) << " | "
              << fixed(stats(column(c, &Run::cpu_ms)).median, 1) << " | " << fixed(stats(column(c, &Run::rss_mb)).median, 1)
              << " | " << inside << " | " << ratio << " |\n";
  }
}

// The base binary's medians over the new one's, per command.
void print_ratios(const std::vector<Case>& cases) {
  std::cout << "\n| command | wall: base / new | CPU: base / new | max RSS: base / new |\n|---|---|---|---|\n";
  for (std::size_t i = 0; i < 2; ++i) {
    const Case& now = cases[i];
    const Case& base = cases[i + 2];
    const auto ratio = [&](double Run::*f) {
      return fixed(stats(column(base, f)).median / stats(column(now, f)).median, 1) + " x";
    };
    std::cout << "| `" << now.command << "` | "
              << ratio(&Run::wall_ms) << " | " << ratio(&Run::cpu_ms) << " | " << ratio(&Run::rss_mb) << " |\n";
  }
}

int run(int runs, const std::string& topocut, const std::string& base) {
  const std::string floorplan = std::string(TOPOCUT_SOURCE_DIR "/maps/floorplan.yaml");
  std::vector<Case> cases;
  for (const std::string& binary : {topocut, base}) {
    if (binary.empty()) continue;
    const std::string label = binary == topocut ? "new" : "base";
    cases.push_back({binary, label, "--version", {"--version"}, {}});
    cases.push_back({binary, label, "segment maps/floorplan.yaml", {"segment", floorplan}, {}});
  }
  // The machine's floor under the same load: an empty process (fork, exec, exit).
  cases.push_back({"/bin/true", "empty process", "/bin/true", {}, {}});
  // The floor of any binary with cv::Mat: an empty program linked with OpenCV core + imgproc.
  cases.push_back({TOPOCUT_OPENCV_FLOOR, "OpenCV floor", "empty, core + imgproc", {}, {}});
  // And core alone: what holding a cv::Mat costs before any image function is linked.
  cases.push_back({TOPOCUT_OPENCV_CORE_FLOOR, "OpenCV floor", "empty, core only", {}, {}});
  for (Case& c : cases) run_once(c.binary, c.args);  // warm the page cache
  for (int k = 0; k < runs; ++k)
    for (Case& c : cases) c.runs.push_back(run_once(c.binary, c.args));
  std::cout << runs << " runs each, alternating (wall times grow with the load; CPU = user + system time)\n\n";
  print_table(cases);
  if (!base.empty()) print_ratios(cases);
  return topocut::benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  int runs = 20;
  std::string topocut = TOPOCUT_CLI, base;
  const Program program{
      .name = "startup_benchmark",
      .title = "Start-up",
      .about = "The topocut command run as a whole process (--version, and segment on the bundled floor plan), its\n"
               "wall and CPU time and peak memory, beside an empty process and empty programs linked with OpenCV.\n",
      .options = {count("runs", runs, 1, "runs of each case, alternating (default 20)"),
                  text("base", "OLD_TOPOCUT", base, "also measure an older topocut binary, alternating with the new"),
                  text("topocut", "NEW_TOPOCUT", topocut, "the topocut binary measured (default: this build's)")}};
  return benchmark_main(argc, argv, program, [&] { return run(runs, topocut, base); });
}
