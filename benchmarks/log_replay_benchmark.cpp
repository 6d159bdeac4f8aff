// Incremental segmentation on real laser logs: each CARMEN log of ../shared/datasets/carmen is
// replayed scan by scan (WallMapReplay: the wall map grows with every scan, drawn as each scan sees
// it, or with --settle its cells settled by occupancy evidence; replay_grids: every change
// goes to the incremental segmenter) and batch segment() runs on the same grids. Prints per log the update
// times, the speed-up over batch, the stability of the room ids and the final rooms, and checks
// issue 26's targets: update p95 <= 10 ms, churn p95 at most 0.2 of batch's own (ids carried by
// overlap on the same updates), ids used at most 1.3 per final room, final rooms equal to batch's.
//
// Options: --help.
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
#include "support/benchmark_main.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/core/format.h"
#include "topocut/exploration/grid_replay.h"
#include "topocut/io/carmen_log.h"
#include "topocut/segmentation/carried_ids.h"
#include "topocut/segmentation/wall_map_segment_options.h"
#include "topocut/walls/wall_map_replay.h"

namespace {

using namespace topocut;

struct LogFigures {
  std::string name;
  GridReplay run;
  TimeStatistics inc, wall, batch, paired;
};

LogFigures replay_file(const std::string& name, const std::string& path, int batch_every, bool settle, bool rest,
                       const IncrementalOptions& incremental) {
  GridReplayOptions options;
  options.resegment_at_rest = rest;
  options.incremental = incremental;
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

// Whether a and b are the same rooms (labels equal once b's ids are carried over from a's).
bool same_partition(const Segmentation& a, const Segmentation& b) {
  if (a.labels.size() != b.labels.size() || a.rooms.size() != b.rooms.size()) return false;
  int next_id = 1 << 20;
  const int labels = b.rooms.empty() ? 0 : b.rooms.back().id;
  return cv::countNonZero(renamed(b, carried_ids(a.labels, b.labels, labels, next_id)).labels != a.labels) == 0;
}

int run(std::vector<std::string> names, int batch_every, bool settle, bool rest, const IncrementalOptions& incremental) {
  if (names.empty()) names = {"intel", "aces", "csail", "fhw"};
  const std::string folder = std::string(TOPOCUT_SHARED_DIR "/datasets/carmen");
  benchmarks::require_folder(folder);
  cv::setNumThreads(1);
  std::printf("grid: %s; batch on %s\n\n",
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
    logs.push_back(replay_file(name, path, batch_every, settle, rest, incremental));
  }

  std::vector<std::vector<std::string>> times{{"log", "grid", "scans", "updates", "whole-map updates", "inc median ms", "inc p95 ms", "inc max ms",
                                               "wall p95 ms", "batch median ms", "speed-up (totals)", "speed-up (medians)"}};
  std::vector<std::vector<std::string>> stability{{"log", "churn median %", "churn p95 %", "batch churn p95 %", "churn max %",
                                                   "updates with churn", "ids used inc / batch", "final rooms inc (windowed) / batch"}};
  std::vector<std::vector<std::string>> targets{{"log", "update p95 <= 10 ms", "churn p95 / batch's <= 0.2",
                                                 "ids used / final rooms <= 1.3", "final rooms = batch's"}};
  for (const LogFigures& f : logs) {
    const StabilityReport& s = f.run.stability;
    const StabilityReport& b = f.run.batch_stability;
    const double ratio = f.paired.total > 0.0 ? f.batch.total / f.paired.total : 0.0;
    times.push_back({f.name, std::to_string(f.run.final_map.width()) + " x " + std::to_string(f.run.final_map.height()),
                     std::to_string(f.run.scans), std::to_string(f.run.updates.size()),
                     std::to_string(std::count_if(f.run.updates.begin(), f.run.updates.end(),
                                                  [](const UpdateRecord& u) { return u.batch_update; })),
                     format("%.3f", f.inc.median),
                     format("%.3f", f.inc.p95), format("%.2f", f.inc.max), format("%.3f", f.wall.p95), format("%.2f", f.batch.median),
                     format("%.1fx", ratio), format("%.1fx", f.paired.median > 0.0 ? f.batch.median / f.paired.median : 0.0)});
    const std::size_t rooms = f.run.incremental.rooms.size(), batch_rooms = f.run.batch.rooms.size();
    stability.push_back({f.name, format("%.3f", 100.0 * s.churn_median), format("%.3f", 100.0 * s.churn_p95),
                         format("%.3f", 100.0 * b.churn_p95), format("%.2f", 100.0 * s.churn_max),
                         std::to_string(s.updates_with_churn) + " / " + std::to_string(s.churn.size()),
                         std::to_string(s.distinct_ids) + " / " + std::to_string(b.distinct_ids),
                         std::to_string(rooms) + " (" + std::to_string(f.run.windowed_rooms) + ") / " + std::to_string(batch_rooms)});
    // Batch run only at the end (--batch-every larger than the log) has no churn to compare with.
    const bool batch_churn_measured = b.churn.size() > 1;
    const double churn_ratio = b.churn_p95 > 0.0 ? s.churn_p95 / b.churn_p95 : (s.churn_p95 > 0.0 ? 1e9 : 0.0);
    const std::string churn_cell = !batch_churn_measured ? std::string("n/a (batch run once)")
                                   : b.churn_p95 > 0.0 ? format("%.2f ", churn_ratio) + (churn_ratio <= 0.2 ? "yes" : "NO")
                                                       : std::string(s.churn_p95 > 0.0 ? "batch 0, live > 0 NO" : "0 / 0 yes");
    const double ids_ratio = s.final_rooms > 0 ? static_cast<double>(s.distinct_ids) / s.final_rooms : 0.0;
    const bool same_rooms = same_partition(f.run.incremental, f.run.batch);
    targets.push_back({f.name, format("%.3f ms ", f.inc.p95) + (f.inc.p95 <= 10.0 ? "yes" : "NO"),
                       churn_cell,
                       format("%.2f ", ids_ratio) + (ids_ratio <= 1.3 ? "yes" : "NO"),
                       std::to_string(rooms) + " / " + std::to_string(batch_rooms) + (same_rooms ? " yes" : " NO")});
  }
  std::printf("## Time per update (CPU)\n\n%s\n## Room stability\n\n%s\n## Targets\n\n%s\npeak RSS %.0f MB\n",
              markdown_table(times).c_str(), markdown_table(stability).c_str(), markdown_table(targets).c_str(),
              topocut::benchmarks::peak_rss_mb());
  return benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut;
  using namespace topocut::benchmarks;
  std::vector<std::string> names;
  int batch_every = 1;
  bool settle = false;
  bool no_rest = false;
  IncrementalOptions incremental = wall_map_incremental_options();  // as `walls --incremental`
  const Program program{
      .name = "log_replay_benchmark",
      .title = "Incremental segmentation replayed from real laser logs",
      .about = "Replays the CARMEN logs of ../shared/datasets/carmen (LOG: intel aces csail fhw by default) into the\n"
               "incremental segmenter with the preset of `topocut walls --incremental`; the options after --settle\n"
               "override the preset to measure a variant. --batch-fraction 1e-12 makes every update a batch one with\n"
               "ids kept by overlap (batch's own churn).\n",
      .options = joined({count("batch-every", batch_every, 1, "compare batch on every N-th update and the last (default 1)"),
                         flag("no-rest", no_rest, "end on the last windowed update (no whole segmentation of the map at rest)"),
                         flag("settle", settle, "settle the grid's cells by occupancy evidence instead of drawing every scan")},
                        table_options(incremental_option_rows(), incremental)),
      .operands = "[LOG ...]",
      .operand = [&names](const std::string& name) { names.push_back(name); },
      .tune_allocator = true};
  return benchmark_main(argc, argv, program, [&] { return run(names, batch_every, settle, !no_rest, incremental); });
}
