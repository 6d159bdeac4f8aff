// Extreme map sizes (issue "Hardening"): a synthetic office floor — a lattice of 10 m x 10 m rooms
// with 0.2 m walls, a 1 m door in each wall and furniture-like blocks — of growing size, up to
// 10,000 x 10,000 cells (500 m x 500 m at 0.05 m). Each size runs in its own child processes, so
// that the peak memory (maximum resident set) is that size's alone:
// - one writes the map, loads it, segments it with segment() and writes the labels (wall-clock
//   seconds and the peak RSS: what `topocut segment` costs);
// - one times the stages of segment() (its own stage times, segment_stages.h: process CPU time,
//   least of --repeat runs) beside the contour floor (decode, threshold, cv::findContours), and prints
//   each stage's time over the floor.
// Then the growth of every stage from one size to the next, beside the growth of the cells.
// With --unexplored CANVAS each floor lies in the middle of a CANVAS x CANVAS map of unknown cells
// (grey 205, as map_server writes it; gmapping's default map is 4000 x 4000), as a SLAM map is.
// Options: --help.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "topocut/io/label_image.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

#include "segment_stages.h"
#include "support/benchmark_main.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

cv::Mat office_floor(int side) {
  constexpr int kRoom = 200, kWall = 4, kDoor = 20;  // cells at 0.05 m: 10 m rooms, 0.2 m walls, 1 m doors
  cv::Mat map(side, side, CV_8UC1, cv::Scalar(255));
  for (int y = 0; y < side; y += kRoom) {
    for (int x = 0; x < side; x += kRoom) {
      map(cv::Rect(x, y, std::min(kWall, side - x), std::min(kRoom, side - y))).setTo(0);  // west wall
      map(cv::Rect(x, y, std::min(kRoom, side - x), std::min(kWall, side - y))).setTo(0);  // north wall
      const int door_x = x + kRoom / 2, door_y = y + kRoom / 2;
      if (door_y + kDoor < side) map(cv::Rect(x, door_y, std::min(kWall, side - x), kDoor)).setTo(255);
      if (door_x + kDoor < side) map(cv::Rect(door_x, y, kDoor, std::min(kWall, side - y))).setTo(255);
      // A table and a cupboard per room.
      if (x + 150 < side && y + 150 < side) map(cv::Rect(x + 60, y + 60, 30, 20)).setTo(0);
      if (x + 190 < side && y + 60 < side) map(cv::Rect(x + 170, y + 20, 20, 40)).setTo(0);
    }
  }
  map.row(side - 1).setTo(0);
  map.col(side - 1).setTo(0);
  return map;
}

// The floor in the middle of a canvas x canvas map of unknown cells (canvas 0: the floor alone).
cv::Mat map_of(int side, int canvas) {
  if (canvas <= side) return office_floor(side);
  cv::Mat map(canvas, canvas, CV_8UC1, cv::Scalar(205));
  office_floor(side).copyTo(map(cv::Rect((canvas - side) / 2, (canvas - side) / 2, side, side)));
  return map;
}

std::string map_path(const std::string& folder, int side) { return folder + "/floor_" + std::to_string(side) + ".png"; }

// Child: writes the map, loads it, segments it and writes the labels; prints the timings on one line.
void run_segment(int side, int canvas, const std::string& folder) {
  const std::string path = map_path(folder, side);
  cv::imwrite(path, map_of(side, canvas));
  const auto t0 = Clock::now();
  const topocut::OccupancyGrid grid = topocut::load_map(path);
  const double load = seconds_since(t0);
  const auto t1 = Clock::now();
  const topocut::Segmentation segmentation = topocut::segment(grid);
  const double seg = seconds_since(t1);
  const auto t2 = Clock::now();
  topocut::write_label_image(folder + "/labels_" + std::to_string(side) + ".png", segmentation.labels);
  const double write = seconds_since(t2);
  std::printf("%.2f %.2f %.2f %zu %zu\n", load, seg, write, segmentation.rooms.size(), segmentation.passages.size());
  std::filesystem::remove(folder + "/labels_" + std::to_string(side) + ".png");
}

// Child: the stages' least times over the runs, on one line (floor first, total last).
void run_stages(int side, const std::string& folder, int repeat) {
  topocut::benchmarks::StageTimes t;
  for (int k = 0; k < repeat; ++k)
    topocut::benchmarks::time_stages(map_path(folder, side), topocut::MapLoadOptions{}, topocut::SegmentOptions{}, t);
  for (const auto& [name, ms] : topocut::benchmarks::least_stage_ms(t)) std::printf("%.1f ", ms);
  std::printf("\n");
}

// Runs work in a forked child whose standard output comes back as the result; the child's peak
// resident memory (MB) goes to peak_mb.
std::string in_child(const std::function<void()>& work, double& peak_mb) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return "error: no pipe";
  std::fflush(stdout);
  const pid_t child = fork();
  if (child == 0) {
    close(pipe_fds[0]);
    dup2(pipe_fds[1], STDOUT_FILENO);
    try {
      work();
    } catch (const std::exception& e) {
      std::printf("error %s\n", e.what());
    }
    std::fflush(stdout);
    _exit(0);
  }
  close(pipe_fds[1]);
  std::string out;
  char buffer[512];
  ssize_t n = 0;
  while ((n = read(pipe_fds[0], buffer, sizeof buffer)) > 0) out.append(buffer, static_cast<std::size_t>(n));
  close(pipe_fds[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  peak_mb = usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
  return out;
}

std::vector<double> numbers_of(const std::string& line) {
  std::vector<double> values;
  const char* p = line.c_str();
  char* end = nullptr;
  for (double v = std::strtod(p, &end); end != p; v = std::strtod(p, &end)) {
    values.push_back(v);
    p = end;
  }
  return values;
}

const std::vector<std::string> kStages = topocut::benchmarks::stage_names();
const std::size_t kStageCount = kStages.size();

void print_header(const char* first, bool with_floor) {
  std::printf("| %s |", first);
  for (std::size_t k = with_floor ? 0 : 1; k < kStageCount; ++k) std::printf(" %s |", kStages[k].c_str());
  std::printf("\n|---|");
  for (std::size_t k = with_floor ? 0 : 1; k < kStageCount; ++k) std::printf("---|");
  std::printf("\n");
}

// The stage tables: CPU ms, each stage over the floor, and each stage's growth from the size before.
void print_stage_tables(const std::vector<int>& sides, const std::vector<double>& mpx, const std::vector<std::vector<double>>& stages,
                        int repeat) {
  std::printf("\nStages of segment(), process CPU ms, least of %d run(s):\n\n", repeat);
  print_header("megapixels", true);
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (stages[i].size() != kStageCount) continue;
    std::printf("| %.1f |", mpx[i]);
    for (const double ms : stages[i]) std::printf(" %.1f |", ms);
    std::printf("\n");
  }
  std::printf("\nEach stage's time over the floor:\n\n");
  print_header("megapixels", false);
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (stages[i].size() != kStageCount) continue;
    std::printf("| %.1f |", mpx[i]);
    for (std::size_t k = 1; k < kStageCount; ++k) std::printf(" %.2f |", stages[i][k] / stages[i][0]);
    std::printf("\n");
  }
  std::printf("\nGrowth from the size before (time ratio; cells grow by the first column):\n\n");
  print_header("megapixels (cells x)", true);
  for (std::size_t i = 1; i < sides.size(); ++i) {
    if (stages[i].size() != kStageCount || stages[i - 1].size() != kStageCount) continue;
    std::printf("| %.1f -> %.1f (%.1f) |", mpx[i - 1], mpx[i], mpx[i] / mpx[i - 1]);
    for (std::size_t k = 0; k < kStageCount; ++k) std::printf(" %.2f |", stages[i][k] / stages[i - 1][k]);
    std::printf("\n");
  }
}

int run(std::vector<int> sides, int canvas, int repeat) {
  if (sides.empty()) sides = {1000, 2500, 5000, 10000};
  const std::string folder = std::filesystem::temp_directory_path() / ("topocut_extreme_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  if (canvas > 0) std::printf("Each floor in the middle of a %d x %d map of unknown cells.\n\n", canvas, canvas);
  std::printf("| side (cells) | megapixels | load s | segment s | write labels s | rooms | passages | peak RSS MB | MB per Mpx |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::vector<double> mpx;
  std::vector<std::vector<double>> stages;
  int failed = 0;
  for (const int side : sides) {
    const double cells_per_side = std::max(side, canvas);
    mpx.push_back(cells_per_side * cells_per_side / 1e6);
    double peak_mb = 0, unused = 0;
    const std::string segmented = in_child([&] { run_segment(side, canvas, folder); }, peak_mb);
    const std::vector<double> v = numbers_of(segmented);
    if (v.size() != 5) {
      std::printf("| %d | %.1f | failed: %s |\n", side, mpx.back(), segmented.c_str());
      stages.emplace_back();
      ++failed;
      continue;
    }
    std::printf("| %d | %.1f | %.2f | %.2f | %.2f | %.0f | %.0f | %.0f | %.1f |\n", side, mpx.back(), v[0], v[1], v[2], v[3],
                v[4], peak_mb, peak_mb / mpx.back());
    std::fflush(stdout);
    stages.push_back(numbers_of(in_child([&] { run_stages(side, folder, repeat); }, unused)));
    std::filesystem::remove(map_path(folder, side));
  }
  print_stage_tables(sides, mpx, stages, repeat);
  std::filesystem::remove_all(folder);
  return failed > 0 ? topocut::benchmarks::kFailed : topocut::benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  std::vector<int> sides;
  int canvas = 0, repeat = 1;
  // The floor's lattice needs a room (100 cells); 40,000 cells a side is 1,600 Mpx.
  const Program program{
      .name = "extreme_maps_benchmark",
      .title = "Extreme map sizes",
      .about = "Segments a synthetic office floor of SIDE x SIDE cells (0.05 m; default 1000 2500 5000 10000) in\n"
               "child processes: load, segment and write times with the peak memory, then the stages' CPU times\n"
               "beside the contour floor and their growth from one size to the next.\n",
      .options = {{"unexplored", "CANVAS", "put each floor in the middle of a CANVAS x CANVAS map of unknown cells (100..40000)",
                   [&canvas](const std::string& value) { canvas = whole_number("--unexplored", value, 100, 40000); }},
                  count("repeat", repeat, 1, "runs of the stages per size, least time taken (default 1)")},
      .operands = "[SIDE ...]",
      .operand = [&sides](const std::string& value) { sides.push_back(whole_number("SIDE", value, 100, 40000)); },
      .tune_allocator = true};
  return benchmark_main(argc, argv, program, [&] { return run(sides, canvas, repeat); });
}
