// Incremental segmentation on real laser logs: each CARMEN log of ../shared/datasets/carmen is
// replayed scan by scan (WallMapReplay: the wall map grows with every scan, drawn as each scan sees
// it, or with --settle its cells settled by occupancy evidence; replay_grids: every change
// goes to the incremental segmenter) and batch segment() runs on the same grids. Prints per log the update
// times, the speed-up over batch, the stability of the room ids and the final rooms, and checks
// the targets: update p95 <= 5 ms, incremental >= 5x faster than batch (total time on the same
// updates), churn median 0 and p95 <= 1 % of the labelled cells.
//
// Options: kUsage below (printed by --help).
//
// Times are process CPU time, single-threaded OpenCV; wall clock beside.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "benchmark_machine.h"
#include "topocut/core/allocator.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/core/format.h"
#include "topocut/exploration/grid_replay.h"
#include "topocut/io/carmen_log.h"
#include "topocut/segmentation/wall_map_segment_options.h"
#include "topocut/walls/wall_map_replay.h"

namespace {

using namespace topocut;

struct LogFigures {
  std::string name;
  GridReplay run;
  TimeStatistics inc, wall, batch, paired;
};

// The segmenter's hysteresis and region options, overridable to measure variants in one build.
struct ReplayVariant {
  int split_after = -1;   // -1: the preset's
  int merge_after = -1;
  int door_neighbours = -1;
  int cut_neighbours = -1;
  double absorb_fraction = -1.0;
  double partial_area = -1.0;
  double partial_margin = -1.0;
  int isolated_nearest = -1;
  double batch_fraction = -1.0;  // tiny (1e-12): every update is batch with ids kept by overlap
};

LogFigures replay_file(const std::string& name, const std::string& path, int batch_every, bool settle,
                       const ReplayVariant& variant) {
  GridReplayOptions options;
  options.incremental = wall_map_incremental_options();  // as `walls --incremental`
  if (variant.split_after >= 0) options.incremental.split_after = variant.split_after;
  if (variant.merge_after >= 0) options.incremental.merge_after = variant.merge_after;
  if (variant.door_neighbours >= 0) options.incremental.neighbours_across_doors = variant.door_neighbours != 0;
  if (variant.cut_neighbours >= 0) options.incremental.neighbours_across_cuts = variant.cut_neighbours != 0;
  if (variant.absorb_fraction >= 0.0) options.incremental.absorb_fraction = variant.absorb_fraction;
  if (variant.partial_area >= 0.0) options.incremental.partial_area = variant.partial_area;
  if (variant.partial_margin > 0.0) options.incremental.partial_margin = variant.partial_margin;
  if (variant.isolated_nearest >= 0) options.incremental.isolated_to_nearest_room = variant.isolated_nearest != 0;
  if (variant.batch_fraction > 0.0) options.incremental.batch_fraction = variant.batch_fraction;
  options.compare_batch = true;
  options.batch_every = batch_every;
  const std::vector<PosedScan> scans = posed_scans(read_carmen_log(path));
  WallMapReplay log_map(scans, {}, settle ? std::optional(OccupancyEvidenceOptions{}) : std::nullopt);
  LogFigures f{name, replay_grids(steps_of(log_map), options), {}, {}, {}, {}};
  std::vector<double> inc, wall, batch, paired;
  for (const UpdateRecord& u : f.run.updates) {
    inc.push_back(u.incremental_ms);
    wall.push_back(u.incremental_wall_ms);
    if (u.batch_ms < 0.0) continue;
    batch.push_back(u.batch_ms);
    paired.push_back(u.incremental_ms);
  }
  f.inc = time_statistics(inc);
  f.wall = time_statistics(wall);
  f.batch = time_statistics(batch);
  f.paired = time_statistics(paired);
  return f;
}

}  // namespace

constexpr const char* kUsage =
    "Usage: log_replay_benchmark [--batch-every N] [--settle] [--split-after N] [--merge-after N]\n"
    "         [--door-neighbours on|off] [--cut-neighbours on|off] [--absorb-fraction F]\n"
    "         [--partial-area M2] [--partial-margin M] [--isolated-nearest on|off]\n"
    "         [--batch-fraction F] [LOG_NAME ...]   (default: intel aces csail fhw)\n"
    "Replays the CARMEN logs of ../shared/datasets/carmen into the incremental segmenter (the preset of\n"
    "`topocut walls --incremental`); the options after --settle override the preset to measure a variant.\n"
    "--batch-fraction 1e-12 makes every update a batch one with ids kept by overlap (batch's own churn).\n";

int main(int argc, char** argv) {
  topocut::keep_freed_memory_for_reuse();
  int batch_every = 1;
  bool settle = false;
  ReplayVariant variant;
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--batch-every" && i + 1 < argc) batch_every = std::max(1, std::atoi(argv[++i]));
    else if (a == "--settle") settle = true;
    else if (a == "--split-after" && i + 1 < argc) variant.split_after = std::max(1, std::atoi(argv[++i]));
    else if (a == "--merge-after" && i + 1 < argc) variant.merge_after = std::max(1, std::atoi(argv[++i]));
    else if (a == "--door-neighbours" && i + 1 < argc) variant.door_neighbours = std::string(argv[++i]) == "on";
    else if (a == "--cut-neighbours" && i + 1 < argc) variant.cut_neighbours = std::string(argv[++i]) == "on";
    else if (a == "--absorb-fraction" && i + 1 < argc) variant.absorb_fraction = std::max(0.0, std::atof(argv[++i]));
    else if (a == "--partial-area" && i + 1 < argc) variant.partial_area = std::max(0.0, std::atof(argv[++i]));
    else if (a == "--partial-margin" && i + 1 < argc) variant.partial_margin = std::atof(argv[++i]);
    else if (a == "--isolated-nearest" && i + 1 < argc) variant.isolated_nearest = std::string(argv[++i]) == "on";
    else if (a == "--batch-fraction" && i + 1 < argc) variant.batch_fraction = std::atof(argv[++i]);
    else if (a == "--help" || a == "-h") {
      std::printf("%s", kUsage);
      return 0;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "log_replay_benchmark: unknown option or missing value: %s (see --help)\n", a.c_str());
      return 2;
    } else names.push_back(a);
  }
  if (names.empty()) names = {"intel", "aces", "csail", "fhw"};
  const std::string folder = std::string(TOPOCUT_SHARED_DIR) + "/datasets/carmen";
  if (!std::filesystem::exists(folder)) {
    std::printf("log_replay_benchmark: skipped, the shared logs are not in %s\n", folder.c_str());
    return 0;
  }
  cv::setNumThreads(1);
  std::printf("# Incremental segmentation replayed from real laser logs\n\nmachine: %s; grid: %s; batch on %s\n\n",
              topocut::benchmarks::cpu_model().c_str(),
              settle ? "cells settled by occupancy evidence" : "every scan drawn as it is",
              batch_every == 1 ? "every update" : ("every " + std::to_string(batch_every) + "th update and the last").c_str());
  std::vector<LogFigures> logs;
  for (const std::string& name : names) {
    const std::string path = folder + "/" + name + "-corrected.log.gz";
    if (!std::filesystem::exists(path)) {
      std::printf("(%s missing)\n", name.c_str());
      continue;
    }
    std::fprintf(stderr, "replaying %s ...\n", name.c_str());
    logs.push_back(replay_file(name, path, batch_every, settle, variant));
  }

  std::vector<std::vector<std::string>> times{{"log", "grid", "scans", "updates", "inc median ms", "inc p95 ms", "inc max ms",
                                               "wall p95 ms", "batch median ms", "speed-up (totals)", "speed-up (medians)"}};
  std::vector<std::vector<std::string>> stability{{"log", "churn median %", "churn p95 %", "churn max %", "updates with churn",
                                                   "rooms changed / ids", "changes", "ids used", "final rooms inc / batch"}};
  std::vector<std::vector<std::string>> targets{{"log", "p95 <= 5 ms", ">= 5x (totals)", "churn median 0", "churn p95 <= 1 %"}};
  for (const LogFigures& f : logs) {
    const StabilityReport& s = f.run.stability;
    const double ratio = f.paired.total > 0.0 ? f.batch.total / f.paired.total : 0.0;
    times.push_back({f.name, std::to_string(f.run.final_map.width()) + " x " + std::to_string(f.run.final_map.height()),
                     std::to_string(f.run.scans), std::to_string(f.run.updates.size()), format("%.3f", f.inc.median),
                     format("%.3f", f.inc.p95), format("%.2f", f.inc.max), format("%.3f", f.wall.p95), format("%.2f", f.batch.median),
                     format("%.1fx", ratio), format("%.1fx", f.paired.median > 0.0 ? f.batch.median / f.paired.median : 0.0)});
    stability.push_back({f.name, format("%.3f", 100.0 * s.churn_median), format("%.3f", 100.0 * s.churn_p95),
                         format("%.2f", 100.0 * s.churn_max),
                         std::to_string(s.updates_with_churn) + " / " + std::to_string(s.churn.size()),
                         std::to_string(s.rooms_changed) + " / " + std::to_string(s.rooms.size()),
                         std::to_string(s.room_changes), std::to_string(s.distinct_ids),
                         std::to_string(f.run.incremental.rooms.size()) + " / " + std::to_string(f.run.batch.rooms.size())});
    targets.push_back({f.name, format("%.3f ms ", f.inc.p95) + (f.inc.p95 <= 5.0 ? "yes" : "NO"),
                       format("%.1fx ", ratio) + (ratio >= 5.0 ? "yes" : "NO"),
                       format("%.3f %% ", 100.0 * s.churn_median) + (s.churn_median == 0.0 ? "yes" : "NO"),
                       format("%.3f %% ", 100.0 * s.churn_p95) + (s.churn_p95 <= 0.01 ? "yes" : "NO")});
  }
  std::printf("## Time per update (CPU)\n\n%s\n## Room stability\n\n%s\n## Targets\n\n%s\npeak RSS %.0f MB\n",
              markdown_table(times).c_str(), markdown_table(stability).c_str(), markdown_table(targets).c_str(),
              topocut::benchmarks::peak_rss_mb());
  return 0;
}
