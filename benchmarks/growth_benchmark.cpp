// Work that must grow no faster than its input (issue 12): three cases, each at sizes growing x10.
//   islands  a map of one-pixel free cells on a 4-cell lattice below a room: `segment`, whose label
//            completion gives every speck the nearest room's label
//   comb     a comb polygon (slots 1 wide and 40 deep): `decompose` with tau 5 (the candidate
//            diagonals of every pass)
//   fcm      fuzzy c-means with 10 centres on every segment of a scan of a room (`label --fcm 10`)
//   smf, iepf, sef, lt, ale
//            line extraction with that method on the same scan of a room (`lines --method M`)
// Each size runs in its own forked child so that the peak RSS is that size's alone. Prints one
// Markdown table: size, median process CPU time over the repeats, the ratio to the size a tenth as
// large and the child's peak RSS. Options: --help.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "support/benchmark_main.h"
#include "topocut/core/error.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/io/map_loader.h"
#include "topocut/labeling/fuzzy_c_means.h"
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/lines/extract.h"
#include "topocut/scan/scan.h"
#include "topocut/segmentation/segmenter.h"

namespace {

const std::vector<std::string> kCases = {"islands", "comb", "fcm", "smf", "iepf", "sef", "lt", "ale"};

using namespace topocut;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// `specks` one-pixel free cells, one per 4 x 4 block, below a room as wide as the map and a fifth
// of it high: the specks are cut off from the room, most of them far beyond a few cells.
cv::Mat islands_map(long specks) {
  const int lattice = static_cast<int>(std::lround(std::sqrt(static_cast<double>(specks))));
  const int side = 4 * lattice;
  const int room = side / 5;
  cv::Mat map(side + room, side, CV_8UC1, cv::Scalar(0));
  map(cv::Rect(2, 2, side - 4, room - 4)).setTo(255);
  for (int y = 0; y < lattice; ++y)
    for (int x = 0; x < lattice; ++x) map.at<unsigned char>(room + 4 * y + 1, 4 * x + 1) = 255;
  return map;
}

PolygonWithHoles comb(long teeth) {
  PolygonWithHoles p;
  p.outer.push_back({0, 0});
  p.outer.push_back({3.0 * static_cast<double>(teeth), 0});
  for (long i = teeth - 1; i >= 0; --i) {
    const double x = 3.0 * static_cast<double>(i);
    p.outer.push_back({x + 3, 50});
    p.outer.push_back({x + 2, 50});
    p.outer.push_back({x + 2, 10});
    p.outer.push_back({x + 1, 10});
    p.outer.push_back({x + 1, 50});
  }
  p.outer.push_back({0, 50});
  return p;
}

// A 360 degree scan from inside an 8 m x 5 m room with a 1 m pillar, 1 cm range noise.
Scan room_scan(long beams) {
  Scan scan;
  cv::RNG rng(7);
  for (long i = 0; i < beams; ++i) {
    const double a = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(beams);
    const double dx = std::cos(a), dy = std::sin(a);
    double r = std::min(dx > 0 ? 5.0 / dx : dx < 0 ? -3.0 / dx : 1e9, dy > 0 ? 3.0 / dy : dy < 0 ? -2.0 / dy : 1e9);
    // The pillar: the square [2, 3] x [-0.5, 0.5], hit from the origin when the ray crosses x = 2 inside it.
    if (dx > 0 && std::abs(2.0 * dy / dx) <= 0.5) r = std::min(r, 2.0 / dx);
    scan.angles.push_back(a);
    scan.ranges.push_back(r + rng.gaussian(0.01));
  }
  return scan;
}

// One run of the case at the given size; returns its CPU seconds (setup excluded).
double run_case(const std::string& name, long size, const std::string& folder) {
  if (name == "islands") {
    const std::string path = folder + "/islands_" + std::to_string(size) + ".png";
    cv::imwrite(path, islands_map(size));
    const OccupancyGrid grid = load_map(path);
    std::filesystem::remove(path);
    const double t0 = cpu_seconds();
    const Segmentation s = segment(grid);
    const double t = cpu_seconds() - t0;
    if (s.rooms.empty()) std::fprintf(stderr, "islands %ld: no room\n", size);
    return t;
  }
  if (name == "comb") {
    const PolygonWithHoles p = comb(size);
    DecompositionOptions options;
    options.tau = 5.0;
    const double t0 = cpu_seconds();
    const Decomposition d = decompose(p, options);
    const double t = cpu_seconds() - t0;
    if (d.pieces.empty()) std::fprintf(stderr, "comb %ld: no piece\n", size);
    return t;
  }
  const Scan scan = room_scan(size);
  if (name != "fcm") {
    LineExtractionOptions options;
    options.method = parse_line_method(name);
    const double t0 = cpu_seconds();
    const std::vector<Line> lines = extract_lines(scan, options);
    const double t = cpu_seconds() - t0;
    if (lines.empty()) std::fprintf(stderr, "%s %ld: no line\n", name.c_str(), size);
    return t;
  }
  const double t0 = cpu_seconds();
  const Labeling labeling = label_scan(scan);
  FuzzyCMeansOptions options;
  options.clusters = 10;
  std::size_t centres = 0;
  for (const std::vector<int>& segment : labeling.segments) {
    std::vector<Point2> points;
    points.reserve(segment.size());
    for (const int beam : segment) points.push_back(beam_point(scan, static_cast<std::size_t>(beam)));
    centres += fuzzy_c_means(points, options).centres.size();
  }
  const double t = cpu_seconds() - t0;
  if (centres == 0) std::fprintf(stderr, "fcm %ld: no centre\n", size);
  return t;
}

struct Row {
  double median = -1.0;
  double peak_mb = 0.0;
};

// Runs the case `repeats` times in a forked child; the child reports the median CPU time.
Row measure(const std::string& name, long size, int repeats, const std::string& folder) {
  int fds[2];
  if (pipe(fds) != 0) return {};
  const pid_t child = fork();
  if (child == 0) {
    close(fds[0]);
    double median = -1.0;
    try {
      std::vector<double> times;
      for (int k = 0; k < repeats; ++k) times.push_back(run_case(name, size, folder));
      std::sort(times.begin(), times.end());
      median = times[times.size() / 2];
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s %ld: %s\n", name.c_str(), size, e.what());
    }
    if (write(fds[1], &median, sizeof median) != sizeof median) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  Row row;
  if (read(fds[0], &row.median, sizeof row.median) != sizeof row.median) row.median = -1.0;
  close(fds[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  row.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
  return row;
}

int run(std::vector<std::string> names, long max_size, int repeats) {
  if (names.empty()) names = kCases;
  const std::vector<long> beams = {1000, 10000, 100000, 1000000};
  const std::vector<std::pair<std::string, std::vector<long>>> sizes = {
      {"islands", {250, 2500, 25000, 250000}}, {"comb", {50, 500, 5000, 50000}}, {"fcm", beams}, {"smf", beams},
      {"iepf", beams}, {"sef", beams}, {"lt", beams}, {"ale", beams}};
  const std::string folder = std::filesystem::temp_directory_path() / ("topocut_growth_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  std::printf("Median of %d runs (process CPU time)\n\n", repeats);
  std::printf("| case | size | median CPU s | ratio to size / 10 | peak RSS MB |\n|---|---|---|---|---|\n");
  std::fflush(stdout);
  int failed = 0;
  for (const auto& [name, list] : sizes) {
    if (std::find(names.begin(), names.end(), name) == names.end()) continue;
    double previous = -1.0;
    for (const long size : list) {
      if (max_size > 0 && size > max_size) break;
      const Row row = measure(name, size, repeats, folder);
      if (row.median < 0) {
        std::printf("| %s | %ld | failed | | %.0f |\n", name.c_str(), size, row.peak_mb);
        ++failed;
        break;
      }
      char ratio[32] = "";
      if (previous > 0) std::snprintf(ratio, sizeof ratio, "%.1f", row.median / previous);
      std::printf("| %s | %ld | %.3f | %s | %.0f |\n", name.c_str(), size, row.median, ratio, row.peak_mb);
      std::fflush(stdout);
      previous = row.median;
    }
  }
  std::filesystem::remove_all(folder);
  return failed > 0 ? benchmarks::kFailed : benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  std::vector<std::string> names;
  int max_size = 0, repeats = 3;
  const Program program{
      .name = "growth_benchmark",
      .title = "Growth with the input",
      .about = "Cases whose work must grow no faster than their input, at sizes growing x10, each size in its own\n"
               "child process: islands (segment), comb (decompose), fcm (label with fuzzy c-means), smf, iepf, sef,\n"
               "lt, ale (line extraction with that method); default all.\n",
      .options = {count("max", max_size, 1, "the largest size run (default: all sizes)"),
                  count("repeats", repeats, 1, "runs per size, median taken (default 3)")},
      .operands = "[islands|comb|fcm|smf|iepf|sef|lt|ale ...]",
      .operand = [&names](const std::string& value) {
        if (std::find(kCases.begin(), kCases.end(), value) == kCases.end()) throw topocut::Error("unknown case '" + value + "'");
        names.push_back(value);
      }};
  return benchmark_main(argc, argv, program, [&] { return run(names, max_size, repeats); });
}
