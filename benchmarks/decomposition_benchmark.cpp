// Dual-space decomposition speed over input size: floor-plan rasters (rooms, doors, furniture,
// pixel noise), spiky star polygons with a small tau (the reference's worst case: 46 s and 1.8 GB
// for 1000 vertices), and the free-space polygons of the Bormann maps when the dataset is present.
//
//   decomposition_benchmark            one forked child per case: median CPU time and the child's
//                                      own peak RSS (getrusage ru_maxrss), printed as a Markdown table
//   decomposition_benchmark --google-benchmark [--benchmark_...]
//                                      Google Benchmark runs (CPU and wall time, vertices, pieces)
#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "../tests/decomposition/dude_test_shapes.h"
#include "support/benchmark_main.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/map/free_space_polygons.h"

namespace {

using namespace topocut;

struct Case {
  std::string family;
  std::string name;
  std::function<PolygonWithHoles()> make;
  double tau;
};

// Floor plans: side lengths chosen so that the traced polygons span about 100 to 100,000 vertices.
PolygonWithHoles plan(int width) {
  test_shapes::PlanOptions o;
  o.width = width;
  o.height = width * 2 / 3;
  o.wall = 3;
  o.min_room = 14;
  o.furniture = width * width / 1500;
  o.noise = width * width / 60;
  return test_shapes::floor_plan(7, o);
}

PolygonWithHoles spiky(int n) { return test_shapes::star(7, n, 5, 100, true); }

int vertices(const PolygonWithHoles& p) {
  int n = static_cast<int>(p.outer.size());
  for (const Ring& h : p.holes) n += static_cast<int>(h.size());
  return n;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (int w : {40, 60, 80, 160, 320, 640, 1000, 1600}) {
    out.push_back({"floor plan", "plan_" + std::to_string(w), [w] { return plan(w); }, 12.0});
  }
  for (int n : {100, 300, 1000, 3000, 10000, 30000, 100000}) {
    out.push_back({"spiky star", "spiky_" + std::to_string(n), [n] { return spiky(n); }, 3.0});
  }
  const std::string dir = std::string(TOPOCUT_SHARED_DIR "/datasets/bormann");
  if (std::filesystem::exists(dir)) {
    for (const char* map : {"Freiburg52_scan", "lab_ipa", "lab_intel_furnitures", "NLB_furnitures", "office_c_furnitures",
                            "office_e", "office_i_furnitures"}) {
      const std::string path = dir + "/" + map + ".png";
      out.push_back({"Bormann map", map,
                     [path] {
                       // The largest free-space component in grid coordinates, as the segmenter sees it.
                       const cv::Mat img = cv::imread(path, cv::IMREAD_GRAYSCALE);
                       const FreeSpacePolygons fsp = free_space_polygons(img > 250, 0.05);
                       const auto largest = std::max_element(
                           fsp.components.begin(), fsp.components.end(),
                           [](const auto& a, const auto& b) { return a.pixel_count < b.pixel_count; });
                       return largest->polygon;
                     },
                     50.0});  // 2.5 m at 0.05 m per pixel
    }
  }
  return out;
}

double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Row {
  int vertices = 0, holes = 0, pieces = 0, cuts = 0, rounds = 0, runs = 0;
  double median_ms = 0, min_ms = 0;
};

// Runs one case in a child process so that its peak RSS is its own.
bool measure(const Case& c, Row& row, long& peak_kb) {
  int fd[2];
  if (pipe(fd) != 0) return false;
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    const PolygonWithHoles p = c.make();
    DecompositionOptions options;
    options.tau = c.tau;
    Row r;
    r.vertices = vertices(p);
    r.holes = static_cast<int>(p.holes.size());
    std::vector<double> times;
    double spent = 0;
    while (times.size() < 5 && (times.size() < 2 || spent < 3.0)) {
      const double t0 = cpu_seconds();
      const Decomposition d = decompose(p, options);
      const double t = cpu_seconds() - t0;
      times.push_back(t * 1e3);
      spent += t;
      r.pieces = static_cast<int>(d.pieces.size());
      r.cuts = static_cast<int>(d.cuts.size());
      r.rounds = d.rounds;
    }
    std::sort(times.begin(), times.end());
    r.median_ms = times[times.size() / 2];
    r.min_ms = times.front();
    r.runs = static_cast<int>(times.size());
    const ssize_t written = write(fd[1], &r, sizeof r);
    _exit(written == static_cast<ssize_t>(sizeof r) ? 0 : 1);
  }
  close(fd[1]);
  const bool ok = read(fd[0], &row, sizeof row) == static_cast<ssize_t>(sizeof row);
  close(fd[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  peak_kb = usage.ru_maxrss;
  return ok && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

int print_table() {
  long base_kb = 0;
  {
    const pid_t pid = fork();
    if (pid == 0) _exit(0);
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    base_kb = usage.ru_maxrss;
  }
  std::printf("| family | case | tau | vertices | holes | pieces | cuts | rounds | CPU ms (median) | us / vertex | peak RSS MB |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  int failed = 0;
  for (const Case& c : cases()) {
    Row row;
    long peak_kb = 0;
    if (!measure(c, row, peak_kb)) {
      std::printf("| %s | %s | failed |\n", c.family.c_str(), c.name.c_str());
      ++failed;
      continue;
    }
    std::printf("| %s | %s | %g | %d | %d | %d | %d | %d | %.2f | %.2f | %.1f |\n", c.family.c_str(), c.name.c_str(), c.tau,
                row.vertices, row.holes, row.pieces, row.cuts, row.rounds, row.median_ms,
                1e3 * row.median_ms / std::max(1, row.vertices), static_cast<double>(peak_kb) / 1024.0);
    std::fflush(stdout);
  }
  std::printf("\n(peak RSS of an idle child: %.1f MB)\n", static_cast<double>(base_kb) / 1024.0);
  return failed > 0 ? benchmarks::kFailed : benchmarks::kDone;
}

// The cases under Google Benchmark, with its flags.
int run_google_benchmark(const char* program, const std::vector<std::string>& flags) {
  for (const Case& c : cases()) {
    benchmark::RegisterBenchmark((c.family + "/" + c.name).c_str(), [c](benchmark::State& state) {
      const PolygonWithHoles p = c.make();
      DecompositionOptions options;
      options.tau = c.tau;
      Decomposition d;
      for (auto _ : state) {
        d = decompose(p, options);
        benchmark::DoNotOptimize(d);
      }
      state.counters["vertices"] = vertices(p);
      state.counters["pieces"] = static_cast<double>(d.pieces.size());
      rusage usage{};
      getrusage(RUSAGE_SELF, &usage);
      state.counters["process_peak_RSS_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
    })->Unit(benchmark::kMillisecond);
  }
  std::vector<char*> argv{const_cast<char*>(program)};
  for (const std::string& flag : flags) argv.push_back(const_cast<char*>(flag.c_str()));
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
  if (benchmark::ReportUnrecognizedArguments(argc, argv.data())) return benchmarks::kBadUsage;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  bool google_benchmark = false;
  std::vector<std::string> flags;
  const Program program{
      .name = "decomposition_benchmark",
      .title = "Decomposition over input size",
      .about = "Times decompose() on floor plans, spiky stars and the Bormann maps' largest free-space polygons\n"
               "(when the dataset is present): one forked child per case, median CPU time and its own peak RSS.\n",
      .options = {flag("google-benchmark", google_benchmark,
                       "run the cases under Google Benchmark instead; its --benchmark_... flags are passed on")},
      .pass_on_prefix = "--benchmark_",
      .passed_on = &flags};
  return benchmark_main(argc, argv, program, [&] {
    if (!google_benchmark && !flags.empty()) {
      std::fprintf(stderr, "decomposition_benchmark: error: %s needs --google-benchmark\n", flags.front().c_str());
      return kBadUsage;
    }
    return google_benchmark ? run_google_benchmark(argv[0], flags) : print_table();
  });
}
