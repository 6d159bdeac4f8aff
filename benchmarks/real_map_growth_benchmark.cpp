// Live rooms on real maps: every map of ../shared/datasets/real_maps (and more with --maps) revealed
// as the simulated robot of `topocut explore` reveals it (360° laser, 5 m range, 0.5 m steps), each
// known map segmented by the incremental segmenter (windowed updates) and, every --batch-every'th
// update and the last, by segment() on the same grid. Prints per map: the update times (CPU), the
// churn of the ids against batch's own churn (ids carried by overlap), the ids used per final room,
// and whether the end equals batch's rooms: the windowed rooms after the last update, and the rooms
// once the map is at rest (resegment(), as the ROS node settles). Targets: churn p95 <= 0.2 of
// batch's, ids used / final rooms <= 1.3, settled end = batch on every map.
//
// Options: --help.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "support/benchmark_main.h"
#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/exploration/exploration_run.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

namespace {

using namespace topocut;

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5)];
}

// Whether a and b are one partition of the same cells under a renaming of the ids.
bool same_partition(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size()) return false;
  std::map<int, int> forward, backward;
  for (int r = 0; r < a.rows; ++r) {
    const int* x = a.ptr<int>(r);
    const int* y = b.ptr<int>(r);
    for (int c = 0; c < a.cols; ++c) {
      if ((x[c] == 0) != (y[c] == 0)) return false;
      if (x[c] == 0) continue;
      if (forward.emplace(x[c], y[c]).first->second != y[c] || backward.emplace(y[c], x[c]).first->second != x[c]) return false;
    }
  }
  return true;
}

// The maps of a folder, by name: each ROS YAML, and each image that is not a YAML's.
std::vector<std::string> maps_in(const std::string& folder) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const fs::path& p = entry.path();
    const std::string ext = p.extension().string();
    if (ext == ".yaml" || ((ext == ".png" || ext == ".pgm") && !fs::exists(fs::path(p).replace_extension(".yaml"))))
      out.push_back(p.string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct Totals {
  int maps = 0, churn_measured = 0, churn_met = 0, ids_met = 0, windowed_equal = 0, settled_equal = 0;
  std::vector<double> update_ms, batch_ms;
};

// One map's row; false when it failed (its error on stderr).
bool run_map(const std::string& path, const ExplorationRunOptions& options, Totals& totals) {
  const std::string name = path.substr(path.find_last_of('/') + 1);
  try {
    const OccupancyGrid world = load_map(path);
    cv::Mat windowed;  // the labels of the last update, before the rest
    ExplorationRunOptions run_options = options;
    run_options.on_update = [&](const ExplorationFrame& frame) { frame.segmentation.labels.copyTo(windowed); };
    const ExplorationRun run = run_exploration(world, run_options);
    std::vector<double> inc, bat;
    int whole = 0;  // updates that segmented the whole map
    for (const UpdateRecord& u : run.updates) {
      inc.push_back(u.incremental_ms);
      whole += u.batch_update;
      if (u.batch_ms >= 0.0) bat.push_back(u.batch_ms);
    }
    const StabilityReport& s = run.stability;
    const StabilityReport& b = run.batch_stability;
    const double ids_ratio = s.final_rooms > 0 ? static_cast<double>(s.distinct_ids) / s.final_rooms : 0.0;
    const bool windowed_equal = same_partition(windowed, run.batch.labels);
    const bool settled_equal = same_partition(run.incremental.labels, run.batch.labels);
    // Batch's churn is measured only when batch ran on two updates or more (not with a large --batch-every).
    const bool churn_measured = b.churn.size() > 1;
    const bool churn_met = churn_measured && s.churn_p95 <= 0.2 * b.churn_p95;
    const std::string churn = churn_measured ? format("%.3f / %.3f (%s)", 100.0 * s.churn_p95, 100.0 * b.churn_p95,
                                                      b.churn_p95 > 0.0 ? format("%.2f", s.churn_p95 / b.churn_p95).c_str()
                                                                        : (s.churn_p95 > 0.0 ? "batch 0" : "0 / 0"))
                                             : format("%.3f / n/a (batch run once)", 100.0 * s.churn_p95);
    std::printf("| %s | %dx%d | %zu (%d) | %.3f / %.3f / %.1f | %.1f | %s | %d / %d = %.2f | %d / %zu %s | %s |\n",
                name.c_str(), world.width(), world.height(), run.updates.size(), whole, quantile(inc, 0.5), quantile(inc, 0.95),
                quantile(inc, 1.0), quantile(bat, 0.5), churn.c_str(), s.distinct_ids, s.final_rooms, ids_ratio,
                run.windowed_rooms, run.batch.rooms.size(), windowed_equal ? "equal" : "differ", settled_equal ? "equal" : "DIFFER");
    std::fflush(stdout);
    ++totals.maps;
    totals.churn_measured += churn_measured;
    totals.churn_met += churn_met;
    totals.ids_met += ids_ratio <= 1.3;
    totals.windowed_equal += windowed_equal;
    totals.settled_equal += settled_equal;
    totals.update_ms.insert(totals.update_ms.end(), inc.begin(), inc.end());
    totals.batch_ms.insert(totals.batch_ms.end(), bat.begin(), bat.end());
    return true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
    return false;
  }
}

int run(const ExplorationRunOptions& options, std::vector<std::string> paths) {
  if (paths.empty()) {
    const std::string folder = std::string(TOPOCUT_SHARED_DIR "/datasets/real_maps");
    benchmarks::require_folder(folder);
    paths = maps_in(folder);
  }
  std::printf("Robot: %.1f m range, %.2f m steps; batch on every %d. update and the last; times: process CPU, "
              "OpenCV single-threaded\n\n",
              options.exploration.range, options.exploration.step, options.batch_every);
  std::printf("| map | cells | updates (whole-map) | update ms median / p95 / max | batch median ms | churn p95 %% inc / batch (ratio, "
              "<= 0.2) | ids used / final rooms (<= 1.3) | windowed end rooms / batch | settled end = batch |\n"
              "|---|---|---|---|---|---|---|---|---|\n");
  Totals totals;
  bool ok = true;
  for (const std::string& path : paths) ok = run_map(path, options, totals) && ok;
  std::printf("\nPooled over %d maps: update median %.3f ms, p95 %.3f ms (batch median %.1f ms, %.1fx); churn target met "
              "on %d of %d measured, ids target on %d, windowed end = batch on %d, settled end = batch on %d\n",
              totals.maps, quantile(totals.update_ms, 0.5), quantile(totals.update_ms, 0.95), quantile(totals.batch_ms, 0.5),
              quantile(totals.batch_ms, 0.5) / std::max(quantile(totals.update_ms, 0.5), 1e-6), totals.churn_met,
              totals.churn_measured, totals.ids_met, totals.windowed_equal, totals.settled_equal);
  return ok ? benchmarks::kDone : benchmarks::kFailed;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  topocut::ExplorationRunOptions options;
  options.compare_batch = true;
  options.batch_every = 5;
  std::vector<std::string> paths;
  const Program program{
      .name = "real_map_growth_benchmark",
      .title = "Live rooms on real maps revealed by the explorer",
      .about = "Every map of ../shared/datasets/real_maps (or the MAP operands) explored by the simulated robot; each\n"
               "known map segmented incrementally and (every --batch-every'th) by segment(). Prints update times,\n"
               "churn against batch's own, ids used per final room and whether the end equals batch's rooms.\n",
      .options = joined({count("batch-every", options.batch_every, 1, "compare batch on every N-th update and the last (default 5)")},
                        table_options(topocut::incremental_option_rows(), options.incremental)),
      .operands = "[MAP ...]",
      .operand = [&paths](const std::string& path) { paths.push_back(path); },
      .tune_allocator = true};
  return benchmark_main(argc, argv, program, [&] {
    cv::setNumThreads(1);  // CPU time is then the work done
    return run(options, paths);
  });
}
