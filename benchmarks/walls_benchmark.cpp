// Pipeline C on the shared CARMEN logs: walls from laser scans, their fidelity to the raw hits,
// the time from file to rooms, and the labeling speed. A plain program that prints tables.
// Options: --help.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "support/benchmark_main.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/carmen_log.h"
#include "topocut/io/overlay.h"
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/segmentation/segmenter.h"
#include "topocut/segmentation/wall_map_segment_options.h"
#include "topocut/walls/walls_pipeline.h"

namespace {

using namespace topocut;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

std::vector<Point2> laser_hits(const std::vector<PosedScan>& scans) {
  std::vector<Point2> hits;
  for (const PosedScan& s : scans)
    for (std::size_t i = 0; i < s.scan.size(); ++i)
      if (s.scan.is_valid(i)) hits.push_back(to_world(s.pose, beam_point(s.scan, i)));
  return hits;
}

struct Fidelity {
  double precision = 0.0;  // share of wall cells within the tolerance of a hit cell
  double coverage = 0.0;   // share of hit cells within the tolerance of a wall cell
  long wall_cells = 0;
  long hit_cells = 0;
};

// Wall cells are the occupied cells of the wall map; hit cells are the cells holding at least one
// laser hit (a valid beam below the no-return range), on the same lattice, extended to hold every
// hit. Distances are between cell centres.
Fidelity fidelity(const OccupancyGrid& grid, const std::vector<Point2>& hits, double tolerance) {
  int c0 = 0, b0 = 0, c1 = grid.width() - 1, b1 = grid.height() - 1;  // columns, rows from the bottom
  std::vector<cv::Point> hit_cells;
  for (const Point2& h : hits) {
    const int c = static_cast<int>(std::floor((h.x - grid.origin.x) / grid.resolution));
    const int b = static_cast<int>(std::floor((h.y - grid.origin.y) / grid.resolution));
    hit_cells.push_back({c, b});
    c0 = std::min(c0, c), c1 = std::max(c1, c), b0 = std::min(b0, b), b1 = std::max(b1, b);
  }
  const int width = c1 - c0 + 1, height = b1 - b0 + 1;
  cv::Mat hit = cv::Mat::zeros(height, width, CV_8UC1);
  for (const cv::Point& p : hit_cells) hit.at<unsigned char>(b1 - p.y, p.x - c0) = 255;
  cv::Mat wall = cv::Mat::zeros(height, width, CV_8UC1);
  const cv::Mat occupied = grid.cells == kOccupied;
  occupied.copyTo(wall(cv::Rect(-c0, b1 - (grid.height() - 1), grid.width(), grid.height())));
  cv::Mat to_hit, to_wall;
  cv::distanceTransform(~hit, to_hit, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::distanceTransform(~wall, to_wall, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const double limit = tolerance / grid.resolution + 1e-6;
  Fidelity f;
  long good_walls = 0, good_hits = 0;
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      if (wall.at<unsigned char>(r, c)) {
        ++f.wall_cells;
        good_walls += to_hit.at<float>(r, c) <= limit;
      }
      if (hit.at<unsigned char>(r, c)) {
        ++f.hit_cells;
        good_hits += to_wall.at<float>(r, c) <= limit;
      }
    }
  }
  f.precision = f.wall_cells ? static_cast<double>(good_walls) / f.wall_cells : 0.0;
  f.coverage = f.hit_cells ? static_cast<double>(good_hits) / f.hit_cells : 0.0;
  return f;
}

struct Run {
  std::vector<PosedScan> scans;
  WallsResult result;
  Segmentation rooms;
  Fidelity fidelity;
  double read_ms = 0, segments_ms = 0, merge_ms = 0, map_ms = 0, rooms_ms = 0, total_ms = 0;
};

// File to rooms, timed stage by stage (the stages of walls_from_scans, then segment()).
Run run_log(const std::string& path, const WallsOptions& options, bool rooms) {
  Run run;
  const auto start = Clock::now();
  auto t = start;
  run.scans = posed_scans(read_carmen_log(path));
  run.read_ms = ms_since(t);
  t = Clock::now();
  for (std::size_t i = 0; i < run.scans.size(); ++i) {
    const auto found = extract_wall_segments(run.scans[i].scan, run.scans[i].pose, options.extraction, static_cast<int>(i));
    run.result.segments.insert(run.result.segments.end(), found.begin(), found.end());
  }
  run.segments_ms = ms_since(t);
  t = Clock::now();
  run.result.walls = merge_wall_segments(run.result.segments, options.merge);
  run.merge_ms = ms_since(t);
  t = Clock::now();
  run.result.grid = build_wall_map(run.scans, run.result.walls, options.map);
  run.map_ms = ms_since(t);
  if (rooms) {
    t = Clock::now();
    run.rooms = segment(run.result.grid, wall_map_segment_options());
    run.rooms_ms = ms_since(t);
  }
  run.total_ms = ms_since(start);
  run.fidelity = fidelity(run.result.grid, laser_hits(run.scans), 0.10);
  return run;
}

// Left: the raw hits (grey) and the merged walls (red) on white; right: the rooms overlay.
cv::Mat picture(const Run& run, const WallsOptions& options) {
  const OccupancyGrid& grid = run.result.grid;
  cv::Mat left(grid.height(), grid.width(), CV_8UC3, cv::Scalar(255, 255, 255));
  for (const Point2& h : laser_hits(run.scans)) {
    const cv::Point c = world_to_cell(grid, h);
    if (c.x >= 0 && c.y >= 0 && c.x < grid.width() && c.y < grid.height()) left.at<cv::Vec3b>(c) = {120, 120, 120};
  }
  auto pixel = [&](const Point2& p) {
    return cv::Point(static_cast<int>(std::lround(((p.x - grid.origin.x) / grid.resolution - 0.5) * 16)),
                     static_cast<int>(std::lround((grid.height() - 0.5 - (p.y - grid.origin.y) / grid.resolution) * 16)));
  };
  for (const Wall& w : run.result.walls)
    cv::line(left, pixel(w.segment.a), pixel(w.segment.b), cv::Scalar(0, 0, 220), 1, cv::LINE_8, 4);
  OverlayOptions overlay;
  overlay.scale = 1;
  cv::Mat right = render_overlay(grid, run.rooms, overlay);
  // Only the part that was seen (free or wall), plus a small border.
  const cv::Rect seen = cv::boundingRect(grid.cells != kUnknown);
  const cv::Rect crop = (seen - cv::Point(10, 10) + cv::Size(20, 20)) & cv::Rect(0, 0, grid.width(), grid.height());
  cv::Mat both;
  cv::hconcat(std::vector<cv::Mat>{left(crop), right(crop)}, both);
  (void)options;
  return both;
}

// PNG at the strongest compression, shrunk by 15 % steps until it is below max_bytes.
void write_small_png(const std::string& path, cv::Mat image, std::size_t max_bytes) {
  std::vector<unsigned char> bytes;
  while (true) {
    cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_COMPRESSION, 9});
    if (bytes.size() <= max_bytes || image.cols < 400) break;
    cv::resize(image, image, cv::Size(), 0.85, 0.85, cv::INTER_AREA);
  }
  write_file_atomically(path, std::string(bytes.begin(), bytes.end()));
}

int run(std::vector<std::string> names, bool methods, bool sweep, const std::string& pictures) {
  if (names.empty()) names = {"intel", "aces", "csail", "fhw"};
  const std::string folder = std::string(TOPOCUT_SHARED_DIR "/datasets/carmen");
  benchmarks::require_folder(folder);
  auto path_of = [&](const std::string& name) { return folder + "/" + name + "-corrected.log.gz"; };

  // Whole logs, default options: fidelity and time from file to rooms (median of 5 runs).
  const WallsOptions defaults;
  std::printf("Pipeline C with default options (%s lines, labeling cell %.2f m, dilation %d), median of 5 runs:\n\n",
              to_string(defaults.extraction.lines.method).c_str(), defaults.extraction.labeling.cell_size,
              defaults.extraction.labeling.dilation);
  std::printf("| log | scans | segments | walls | wall precision | hit coverage | rooms | read ms | lines ms | merge ms | map ms | rooms ms | file→rooms ms |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& name : names) {
    if (!std::filesystem::exists(path_of(name))) {
      std::printf("| %s | (missing) |\n", name.c_str());
      continue;
    }
    std::vector<Run> runs;
    for (int k = 0; k < 5; ++k) runs.push_back(run_log(path_of(name), defaults, true));
    auto med = [&](double Run::*field) {
      std::vector<double> v;
      for (const Run& r : runs) v.push_back(r.*field);
      return median(v);
    };
    const Run& run = runs.front();
    std::printf("| %s | %zu | %zu | %zu | %.1f %% | %.1f %% | %zu | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f |\n", name.c_str(),
                run.scans.size(), run.result.segments.size(), run.result.walls.size(), 100 * run.fidelity.precision,
                100 * run.fidelity.coverage, run.rooms.rooms.size(), med(&Run::read_ms), med(&Run::segments_ms),
                med(&Run::merge_ms), med(&Run::map_ms), med(&Run::rooms_ms), med(&Run::total_ms));
    if (!pictures.empty()) write_small_png(pictures + "/walls_" + name + ".png", picture(run, defaults), 290 * 1024);
  }

  // Labeling one scan: every scan of each log, both methods, at the CLI default (5 cm) and at the
  // walls default (10 cm).
  std::printf("\nLabeling one scan (median over all scans of the log, 20 repetitions each), microseconds:\n\n");
  std::printf("| log | beams | sparse 5 cm | raster 5 cm | sparse 10 cm | raster 10 cm |\n|---|---:|---:|---:|---:|---:|\n");
  for (const std::string& name : names) {
    if (!std::filesystem::exists(path_of(name))) continue;
    const std::vector<PosedScan> scans = posed_scans(read_carmen_log(path_of(name)));
    double cells[2] = {0.05, 0.10};
    double result[2][2];
    for (int c = 0; c < 2; ++c) {
      for (int m = 0; m < 2; ++m) {
        LabelingOptions options;
        options.cell_size = cells[c];
        options.method = m == 0 ? LabelingMethod::kSparse : LabelingMethod::kRaster;
        std::vector<double> times;
        std::size_t sink = 0;
        for (const PosedScan& s : scans) {
          const auto t = Clock::now();
          for (int k = 0; k < 20; ++k) sink += label_scan(s.scan, options).segments.size();
          times.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t).count() / 20);
        }
        result[c][m] = median(times) + (sink == 0 ? 1e-9 : 0.0);
      }
    }
    std::printf("| %s | %zu | %.1f | %.1f | %.1f | %.1f |\n", name.c_str(), scans.front().scan.size(), result[0][0],
                result[0][1], result[1][0], result[1][1]);
  }

  if (methods) {
    std::printf("\nLine extractors inside pipeline C (all other options default):\n\n");
    std::printf("| log | method | segments | walls | wall precision | hit coverage | lines ms |\n|---|---|---:|---:|---:|---:|---:|\n");
    for (const std::string& name : names) {
      if (!std::filesystem::exists(path_of(name))) continue;
      for (LineMethod m : {LineMethod::kSef, LineMethod::kLt, LineMethod::kIepf, LineMethod::kSmf, LineMethod::kAle}) {
        WallsOptions options;
        options.extraction.lines.method = m;
        const Run run = run_log(path_of(name), options, false);
        std::printf("| %s | %s | %zu | %zu | %.1f %% | %.1f %% | %.0f |\n", name.c_str(), to_string(m).c_str(),
                    run.result.segments.size(), run.result.walls.size(), 100 * run.fidelity.precision,
                    100 * run.fidelity.coverage, run.segments_ms);
      }
    }
  }
  if (sweep) {
    // The labeling cell and the minimum support of a wall line, with the default extractor.
    std::printf("\nLabeling cell and minimum line support (%s lines):\n\n", to_string(defaults.extraction.lines.method).c_str());
    std::printf("| log | cell m | min points | max gap m | segments | walls | wall precision | hit coverage |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& name : names) {
      if (!std::filesystem::exists(path_of(name))) continue;
      for (double cell : {0.05, 0.10, 0.15}) {
        for (std::size_t min_points : {3, 4, 5}) {
          for (double gap : {0.3, 0.5}) {
            WallsOptions options;
            options.extraction.labeling.cell_size = cell;
            options.extraction.min_points = min_points;
            options.extraction.max_gap = gap;
            const Run run = run_log(path_of(name), options, false);
            std::printf("| %s | %.2f | %zu | %.1f | %zu | %zu | %.1f %% | %.1f %% |\n", name.c_str(), cell, min_points, gap,
                        run.result.segments.size(), run.result.walls.size(), 100 * run.fidelity.precision,
                        100 * run.fidelity.coverage);
          }
        }
      }
    }
  }
  return benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  std::string pictures;
  bool methods = false, sweep = false;
  std::vector<std::string> names;
  const Program program{
      .name = "walls_benchmark",
      .title = "Walls from the shared CARMEN logs",
      .about = "Walls from laser logs (LOG: intel, aces, csail or fhw; default all four): their fidelity to the raw\n"
               "hits, the time from file to rooms and the labeling speed.\n",
      .options = {text("pictures", "DIR", pictures, "write DIR/walls_<log>.png (walls over the raw hits | rooms)"),
                  flag("methods", methods, "compare the five line extractors"),
                  flag("sweep", sweep, "sweep the labeling cell and the line support")},
      .operands = "[LOG ...]",
      .operand = [&names](const std::string& name) { names.push_back(name); },
      .tune_allocator = true};
  return benchmark_main(argc, argv, program, [&] { return run(names, methods, sweep, pictures); });
}
