// Incremental segmentation during exploration, over the whole Bormann dataset: a simulated robot
// (360° laser, 1° beams, 5 m range, 0.5 m steps) explores each of the 40 images; every update of its
// known map is segmented incrementally and, on the same grid, by batch segment(); the final maps are
// scored against the ground truth. Prints per-image and pooled tables and checks the targets:
// incremental median <= 1 ms and p95 <= 5 ms per update, >= 5x faster than batch on the same updates,
// final precision and recall within 1.5 points of batch, state proportional to the map.
//
// Options: printed by --help (run()).
//
// Times are process CPU time (the machine may be shared), single-threaded OpenCV; the wall-clock
// figures are printed beside them.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/allocator.h"
#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset_options.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/evaluation/incremental_dataset.h"
#include "topocut/evaluation/incremental_dataset_report.h"
#include "topocut/io/atomic_file.h"

namespace {

using namespace topocut;

std::string first_line_with(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) return line.substr(line.find(':') + 1);
  return "?";
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

int run(int argc, char** argv) {
  int batch_every = 1;
  bool compare = true;
  int split_after = 0, merge_after = 0;  // 0: the segmenter's defaults
  double partial_area = -1.0, partial_margin = -1.0;
  int isolated_nearest = -1;
  double batch_fraction = -1.0;  // tiny (1e-12): every update is batch with ids kept by overlap
  std::vector<std::string> rest;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << "Usage: incremental_benchmark [--batch-every N] [--no-batch] [--split-after N] [--merge-after N]\n"
                   "         [--partial-area M2] [--partial-margin M] [--isolated-nearest on|off] [--batch-fraction F]\n"
                   "         [dataset options]\n"
                   "A simulated robot explores every Bormann image; each update is segmented incrementally and by\n"
                   "batch (every --batch-every'th); prints times, the rooms' stability and the final quality.\n"
                   "--batch-fraction 1e-12 makes every update a batch one with ids kept by overlap (batch's own churn).\n\n"
                   "Dataset options (as topocut evaluate):\n"
                << dataset_options_help();
      return 0;
    } else if (arg == "--batch-every" && i + 1 < argc) {
      batch_every = std::stoi(argv[++i]);
    } else if (arg == "--no-batch") {
      compare = false;
    } else if (arg == "--split-after" && i + 1 < argc) {
      split_after = std::max(1, std::stoi(argv[++i]));
    } else if (arg == "--merge-after" && i + 1 < argc) {
      merge_after = std::max(1, std::stoi(argv[++i]));
    } else if (arg == "--partial-area" && i + 1 < argc) {
      partial_area = std::max(0.0, std::stod(argv[++i]));
    } else if (arg == "--partial-margin" && i + 1 < argc) {
      partial_margin = std::stod(argv[++i]);
    } else if (arg == "--isolated-nearest" && i + 1 < argc) {
      isolated_nearest = std::string(argv[++i]) == "on";
    } else if (arg == "--batch-fraction" && i + 1 < argc) {
      batch_fraction = std::stod(argv[++i]);
    } else {
      rest.push_back(arg);
    }
  }
  DatasetArguments arguments = parse_dataset_arguments(rest);
  if (arguments.dataset == DatasetArguments{}.dataset) arguments.dataset = std::string(TOPOCUT_SHARED_DIR) + "/datasets/bormann";
  if (!arguments.csv.empty()) check_writable(arguments.csv);
  cv::setNumThreads(1);  // both segmenters single-threaded: CPU time is then the work done

  IncrementalDatasetOptions options;
  options.run = arguments.run;
  options.run.progress = [](const std::string& line) { std::cerr << line << std::endl; };
  options.exploration.compare_batch = compare;
  options.exploration.batch_every = batch_every;
  if (split_after > 0) options.exploration.incremental.split_after = split_after;
  if (merge_after > 0) options.exploration.incremental.merge_after = merge_after;
  if (partial_area >= 0.0) options.exploration.incremental.partial_area = partial_area;
  if (partial_margin > 0.0) options.exploration.incremental.partial_margin = partial_margin;
  if (isolated_nearest >= 0) options.exploration.incremental.isolated_to_nearest_room = isolated_nearest != 0;
  if (batch_fraction > 0.0) options.exploration.incremental.batch_fraction = batch_fraction;
  const std::vector<DatasetMap> maps = select_maps(discover_dataset(arguments.dataset), arguments.run.maps);

  std::cout << "# Incremental segmentation during exploration\n\n"
            << "machine:" << first_line_with("/proc/cpuinfo", "model name") << ", "
            << std::to_string(cv::getNumberOfCPUs()) << " cores; load average at start " << load_average() << "\n"
            << "dataset: " << arguments.dataset << " (" << maps.size() << " maps); method: "
            << method_name(options.run.segment) << "\n"
            << "robot: 360 deg laser, 1 deg beams, " << options.exploration.exploration.range << " m range, "
            << options.exploration.exploration.step << " m steps, seed " << options.exploration.exploration.seed
            << "; batch compared on " << (compare ? (batch_every == 1 ? std::string("every update") : "every " + std::to_string(batch_every) + "th update and the last") : std::string("no update"))
            << "\n\n"
            << std::flush;

  const auto start = std::chrono::steady_clock::now();
  const std::vector<IncrementalImageResult> results = run_incremental_dataset(maps, options);
  const double minutes = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60.0;

  std::cout << "## Per image (times per update, CPU)\n\n" << format_update_times_table(results) << "\n";
  std::cout << "## Pooled over all updates\n\n" << format_incremental_summary(results) << "\n";
  {
    std::vector<std::vector<std::string>> rows{{"map", "variant", "explored %", "rooms inc / batch",
                                                "inc R / P %", "batch R / P %"}};
    for (const IncrementalImageResult& r : results) {
      if (!r.incremental.ok) continue;
      rows.push_back({r.incremental.map, to_string(r.incremental.variant), format("%.1f", 100.0 * r.explored),
                      std::to_string(r.incremental.rooms) + " / " + std::to_string(r.batch.rooms),
                      format("%.1f / %.1f", 100.0 * r.incremental.recall, 100.0 * r.incremental.precision),
                      format("%.1f / %.1f", 100.0 * r.batch.recall, 100.0 * r.batch.precision)});
    }
    std::cout << "## Final quality per image (rooms = segments > 100 px)\n\n" << markdown_table(rows) << "\n";
  }
  const std::vector<ImageResult> inc = incremental_image_results(results), bat = batch_image_results(results);
  std::cout << "## Final quality (same final maps; time = all incremental updates / one batch call)\n\n"
            << format_summary(inc, "incremental (explored map)") << format_summary(bat, "batch (same map)") << "\n";

  // Stability of the room ids, per image and pooled over every update of every image.
  std::vector<double> churn;
  int maps_meeting_churn = 0, stable_images = 0;
  {
    std::vector<std::vector<std::string>> rows{{"map", "variant", "churn median %", "churn p95 %", "churn max %",
                                                "rooms changed / ids", "changes", "ids used / final rooms"}};
    for (const IncrementalImageResult& r : results) {
      if (!r.incremental.ok) continue;
      const StabilityReport& s = r.stability;
      churn.insert(churn.end(), s.churn.begin(), s.churn.end());
      ++stable_images;
      maps_meeting_churn += s.churn_median == 0.0 && s.churn_p95 <= 0.01 ? 1 : 0;
      rows.push_back({r.incremental.map, to_string(r.incremental.variant), format("%.3f", 100.0 * s.churn_median),
                      format("%.3f", 100.0 * s.churn_p95), format("%.2f", 100.0 * s.churn_max),
                      std::to_string(s.rooms_changed) + " / " + std::to_string(s.rooms.size()),
                      std::to_string(s.room_changes),
                      std::to_string(s.distinct_ids) + " / " + std::to_string(s.final_rooms)});
    }
    std::cout << "## Room stability per image (churn: share of cells labelled before and after an update whose room "
                 "changed)\n\n"
              << markdown_table(rows) << "\n";
  }
  const TimeStatistics churn_pooled = time_statistics(churn);

  // Targets.
  std::vector<double> all, batch, paired;
  std::size_t peak = 0;
  for (const IncrementalImageResult& r : results) {
    if (!r.incremental.ok) continue;
    all.insert(all.end(), r.update_ms.begin(), r.update_ms.end());
    batch.insert(batch.end(), r.batch_update_ms.begin(), r.batch_update_ms.end());
    paired.insert(paired.end(), r.paired_update_ms.begin(), r.paired_update_ms.end());
    if (r.peak_state_bytes > peak) peak = r.peak_state_bytes;
  }
  const TimeStatistics t = time_statistics(all), b = time_statistics(batch), p = time_statistics(paired);
  std::cout << "## Targets\n\n";
  std::vector<std::vector<std::string>> rows{{"target", "measured", "met"}};
  const bool timed = t.count > 0;
  rows.push_back({"incremental median per update <= 1 ms", format("%.3f ms", t.median), timed && t.median <= 1.0 ? "yes" : "NO"});
  rows.push_back({"incremental p95 per update <= 5 ms", format("%.3f ms", t.p95), timed && t.p95 <= 5.0 ? "yes" : "NO"});
  if (b.count > 0 && p.median > 0.0) {
    const double ratio = b.median / p.median;
    rows.push_back({">= 5x faster than batch on the same updates", format("%.1fx (medians), %.1fx (totals)", ratio, b.total / p.total),
                    ratio >= 5.0 ? "yes" : "NO"});
  }
  for (const Variant variant : {Variant::kPlain, Variant::kFurnished}) {
    const VariantSummary a = summarize(inc, variant), c = summarize(bat, variant);
    if (a.images == a.failed) continue;
    const double dr = 100.0 * (a.recall_mean - c.recall_mean), dp = 100.0 * (a.precision_mean - c.precision_mean);
    rows.push_back({to_string(variant) + ": mean recall, precision at most 1.5 points below batch",
                    format("%+.1f, %+.1f points", dr, dp), (dr >= -1.5 && dp >= -1.5) ? "yes" : "NO"});
  }
  rows.push_back({"churn median 0 (all updates pooled)", format("%.4f %%", 100.0 * churn_pooled.median),
                  churn_pooled.median == 0.0 ? "yes" : "NO"});
  rows.push_back({"churn p95 <= 1 % (all updates pooled)", format("%.4f %%", 100.0 * churn_pooled.p95),
                  churn_pooled.p95 <= 0.01 ? "yes" : "NO"});
  rows.push_back({"images meeting both churn targets", std::to_string(maps_meeting_churn) + " of " + std::to_string(stable_images),
                  maps_meeting_churn == stable_images ? "yes" : "NO"});
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  rows.push_back({"state proportional to the map", format("peak %.1f MB segmenter state (6 bytes per cell + rooms); process peak RSS %.0f MB",
                                                       peak / (1024.0 * 1024.0), usage.ru_maxrss / 1024.0),
                  "-"});
  std::cout << markdown_table(rows) << "\n"
            << format("Run time %.1f min; load average at the end ", minutes) << load_average() << "\n";
  if (!arguments.csv.empty()) write_file_atomically(arguments.csv, incremental_results_csv(results));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  topocut::keep_freed_memory_for_reuse();
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "incremental_benchmark: error: " << e.what() << "\n";
    return 1;
  }
}
