// What a robot-made map costs (simulate_map(), `topocut simulate-map`): for every plan of the r2v
// homes, the Bormann offices and the lex sketches (the first --plans of each, by name), --seeds maps
// each, timed in process CPU time, beside segment() on the same clean plan in the same run, so that
// the ratio holds on a loaded machine. Prints one Markdown table: per set the plans, the maps, the
// median output frame, simulate_map's median / p90 / max milliseconds per map, the median scans, the
// median segment() milliseconds and the median per-map ratio of the two.
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "support/benchmark_main.h"
#include "topocut/core/error.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/exploration/simulated_map.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

namespace {

using namespace topocut;

double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5)];
}

struct Set {
  std::string name, folder;
};

// One set's row; false when a plan failed (its error on stderr).
bool run_set(const Set& set, int plans, int seeds) {
  std::vector<DatasetMap> maps = discover_dataset(set.folder);
  if (static_cast<int>(maps.size()) > plans) maps.resize(static_cast<std::size_t>(plans));
  std::vector<double> simulate, segment_ms, ratio, scans, cells;
  bool ok = true;
  for (const DatasetMap& m : maps) {
    try {
      const OccupancyGrid plan = load_map(m.plain);
      const cv::Mat rooms = ground_truth_rooms(load_ground_truth(m.ground_truth));
      const double s0 = cpu_ms();
      const Segmentation clean = segment(plan);
      const double segmented = cpu_ms() - s0;
      if (clean.rooms.empty()) std::fprintf(stderr, "%s %s: the clean plan has no room\n", set.name.c_str(), m.name.c_str());
      segment_ms.push_back(segmented);
      for (int seed = 1; seed <= seeds; ++seed) {
        const double t0 = cpu_ms();
        const SimulatedMap s = simulate_map(plan, rooms, SimulatedMapOptions{}, static_cast<std::uint32_t>(seed));
        const double t = cpu_ms() - t0;
        simulate.push_back(t);
        ratio.push_back(t / std::max(segmented, 1e-3));
        scans.push_back(s.scans);
        cells.push_back(static_cast<double>(s.map.cells.total()));
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s %s: %s\n", set.name.c_str(), m.name.c_str(), e.what());
      ok = false;
    }
  }
  std::printf("| %s | %zu | %zu | %.2f | %.0f / %.0f / %.0f | %.0f | %.1f | %.0f |\n", set.name.c_str(), maps.size(), simulate.size(),
              quantile(cells, 0.5) / 1e6, quantile(simulate, 0.5), quantile(simulate, 0.9),
              quantile(simulate, 1.0), quantile(scans, 0.5), quantile(segment_ms, 0.5), quantile(ratio, 0.5));
  std::fflush(stdout);
  return ok;
}

int run(int plans, int seeds) {
  const std::string data = std::string(TOPOCUT_SHARED_DIR "/datasets");
  const std::vector<Set> sets = {{"r2v homes", data + "/r2v"}, {"Bormann offices", data + "/bormann"},
                                 {"lex sketches", data + "/sketches/lex"}};
  for (const Set& set : sets) benchmarks::require_folder(set.folder);
  std::printf("Default options, seeds 1..%d, the first %d plans of each set by name; process CPU time\n\n", seeds, plans);
  std::printf("| set | plans | maps | median frame (Mcells) | simulate_map ms (median / p90 / max) | median scans | "
              "segment() of the plan, median ms | simulate / segment, median |\n|---|---|---|---|---|---|---|---|\n");
  bool ok = true;
  for (const Set& set : sets) ok = run_set(set, plans, seeds) && ok;
  return ok ? benchmarks::kDone : benchmarks::kFailed;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  int plans = 20, seeds = 3;
  const Program program{
      .name = "simulated_map_benchmark",
      .title = "Robot-made maps (simulate_map)",
      .about = "simulate_map() with default options on the first plans of the r2v, Bormann and lex sketch sets,\n"
               "several seeds each, beside segment() of the same clean plan (process CPU time).\n",
      .options = {count("plans", plans, 1, "plans per set (default 20)"), count("seeds", seeds, 1, "maps per plan (default 3)")}};
  return benchmark_main(argc, argv, program, [&] { return run(plans, seeds); });
}
