// Extreme map sizes (issue "Hardening"): a synthetic office floor — a lattice of 10 m x 10 m rooms
// with 0.2 m walls, a 1 m door in each wall and furniture-like blocks — of growing size, up to
// 10,000 x 10,000 cells (500 m x 500 m at 0.05 m). Each size runs in its own child process so that
// the peak memory (maximum resident set) is that size's alone. Prints a Markdown table:
// load (PNG decode), segment, write labels, peak RSS and RSS per megapixel.
// With --unexplored CANVAS each floor lies in the middle of a CANVAS x CANVAS map of unknown cells
// (grey 205, as map_server writes it; gmapping's default map is 4000 x 4000), as a SLAM map is.
//   extreme_maps_benchmark [--unexplored CANVAS] [SIDE...]     (default: 1000 2500 5000 10000)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "topocut/core/allocator.h"
#include "topocut/io/label_image.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

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

// Child: builds, writes, loads and segments one map; prints the timings on one line.
int run_one(int side, int canvas, const std::string& folder) {
  const std::string map_path = folder + "/floor_" + std::to_string(side) + ".png";
  cv::imwrite(map_path, map_of(side, canvas));
  const auto t0 = Clock::now();
  const topocut::OccupancyGrid grid = topocut::load_map(map_path);
  const double load = seconds_since(t0);
  const auto t1 = Clock::now();
  const topocut::Segmentation segmentation = topocut::segment(grid);
  const double seg = seconds_since(t1);
  const auto t2 = Clock::now();
  topocut::write_label_image(folder + "/labels_" + std::to_string(side) + ".png", segmentation.labels);
  const double write = seconds_since(t2);
  std::printf("%.2f %.2f %.2f %zu %zu\n", load, seg, write, segmentation.rooms.size(), segmentation.passages.size());
  std::filesystem::remove(map_path);
  std::filesystem::remove(folder + "/labels_" + std::to_string(side) + ".png");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  topocut::keep_freed_memory_for_reuse();
  std::vector<int> sides;
  int canvas = 0;
  const auto usage = [] {
    std::fprintf(stderr,
                 "usage: extreme_maps_benchmark [--unexplored CANVAS] [SIDE...]   (SIDE, CANVAS: cells per side, 100 to 40000)\n");
    return 2;
  };
  for (int i = 1; i < argc; ++i) {
    const bool unexplored = std::string(argv[i]) == "--unexplored";
    if (unexplored && ++i == argc) return usage();
    const int value = std::atoi(argv[i]);
    if (value < 100 || value > 40000) return usage();  // the floor's lattice needs a room; 40,000 is 1,600 Mpx
    if (unexplored) {
      canvas = value;
    } else {
      sides.push_back(value);
    }
  }
  if (sides.empty()) sides = {1000, 2500, 5000, 10000};
  const std::string folder = std::filesystem::temp_directory_path() / ("topocut_extreme_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  if (canvas > 0) std::printf("Each floor in the middle of a %d x %d map of unknown cells.\n\n", canvas, canvas);
  std::printf("| side (cells) | megapixels | load s | segment s | write labels s | rooms | passages | peak RSS MB | MB per Mpx |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  for (const int side : sides) {
    int pipe_fds[2];
    if (pipe(pipe_fds) != 0) return 1;
    const pid_t child = fork();
    if (child == 0) {
      close(pipe_fds[0]);
      dup2(pipe_fds[1], STDOUT_FILENO);
      try {
        run_one(side, canvas, folder);
      } catch (const std::exception& e) {
        std::printf("error %s\n", e.what());
      }
      std::fflush(stdout);
      _exit(0);
    }
    close(pipe_fds[1]);
    char buffer[512] = {0};
    const ssize_t n = read(pipe_fds[0], buffer, sizeof buffer - 1);
    close(pipe_fds[0]);
    int status = 0;
    rusage usage{};
    wait4(child, &status, 0, &usage);
    const double cells_per_side = std::max(side, canvas);
    const double mpx = cells_per_side * cells_per_side / 1e6;
    const double peak_mb = usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
    double load = 0, seg = 0, write = 0;
    std::size_t rooms = 0, passages = 0;
    if (n <= 0 || std::sscanf(buffer, "%lf %lf %lf %zu %zu", &load, &seg, &write, &rooms, &passages) != 5) {
      std::printf("| %d | %.1f | failed: %s (status %d) |\n", side, mpx, buffer, status);
      continue;
    }
    std::printf("| %d | %.1f | %.2f | %.2f | %.2f | %zu | %zu | %.0f | %.1f |\n", side, mpx, load, seg, write, rooms, passages,
                peak_mb, peak_mb / mpx);
    std::fflush(stdout);
  }
  std::filesystem::remove_all(folder);
  return 0;
}
