// Incremental segmentation during exploration, over the whole Bormann dataset: a simulated robot
// (360° laser, 1° beams, 5 m range, 0.5 m steps) explores each of the 40 images; every update of its
// known map is segmented incrementally and, on the same grid, by batch segment(); the final maps are
// scored against the ground truth. Prints per-image and pooled tables and checks the targets:
// incremental median <= 1 ms and p95 <= 5 ms per update, >= 5x faster than batch on the same updates,
// final precision and recall within 1.5 points of batch, state proportional to the map.
//
// Options: --help.
//
// Times are process CPU time (the machine may be shared), single-threaded OpenCV; the wall-clock
// figures are printed beside them.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "support/benchmark_main.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset_options.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/evaluation/incremental_dataset.h"
#include "topocut/evaluation/incremental_dataset_report.h"
#include "topocut/io/atomic_file.h"

namespace {

using namespace topocut;

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

int run(IncrementalDatasetOptions& options, const DatasetArguments& arguments) {
  benchmarks::require_folder(arguments.dataset);
  if (!arguments.csv.empty()) check_writable(arguments.csv);
  cv::setNumThreads(1);  // both segmenters single-threaded: CPU time is then the work done
  const bool compare = options.exploration.compare_batch;
  const int batch_every = options.exploration.batch_every;
  options.run = arguments.run;
  options.run.progress = [](const std::string& line) { std::cerr << line << std::endl; };
  const std::vector<DatasetMap> maps = select_maps(discover_dataset(arguments.dataset), arguments.run.maps);

  std::cout << "dataset: " << arguments.dataset << " (" << maps.size() << " maps); method: "
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
  std::vector<double> churn, batch_churn;
  // Batch's churn is measured only on images where batch ran on two updates or more (not with a large
  // --batch-every or --no-batch): the churn targets count those images and updates only.
  int maps_meeting_churn = 0, churn_measured_images = 0, stable_images = 0, maps_meeting_ids = 0, maps_final_equal = 0;
  {
    std::vector<std::vector<std::string>> rows{{"map", "variant", "churn median %", "churn p95 %", "batch churn p95 %",
                                                "churn max %", "rooms changed / ids", "changes",
                                                "ids used / final rooms", "final rooms inc (windowed) / batch"}};
    for (const IncrementalImageResult& r : results) {
      if (!r.incremental.ok) continue;
      const StabilityReport& s = r.stability;
      const StabilityReport& bs = r.batch_stability;
      ++stable_images;
      if (bs.churn.size() > 1) {
        churn.insert(churn.end(), s.churn.begin(), s.churn.end());
        batch_churn.insert(batch_churn.end(), bs.churn.begin(), bs.churn.end());
        ++churn_measured_images;
        maps_meeting_churn += s.churn_p95 <= 0.2 * bs.churn_p95 ? 1 : 0;
      }
      maps_meeting_ids += s.distinct_ids <= 1.3 * s.final_rooms ? 1 : 0;
      // Scores summed over rooms in another id order differ in the last bits.
      maps_final_equal += r.incremental.rooms == r.batch.rooms && std::abs(r.incremental.recall - r.batch.recall) < 1e-9 &&
                          std::abs(r.incremental.precision - r.batch.precision) < 1e-9;
      rows.push_back({r.incremental.map, to_string(r.incremental.variant), format("%.3f", 100.0 * s.churn_median),
                      format("%.3f", 100.0 * s.churn_p95), format("%.3f", 100.0 * bs.churn_p95),
                      format("%.2f", 100.0 * s.churn_max),
                      std::to_string(s.rooms_changed) + " / " + std::to_string(s.rooms.size()),
                      std::to_string(s.room_changes),
                      std::to_string(s.distinct_ids) + " / " + std::to_string(s.final_rooms),
                      std::to_string(r.incremental.rooms) + " (" + std::to_string(r.windowed_rooms) + ") / " +
                          std::to_string(r.batch.rooms)});
    }
    std::cout << "## Room stability per image (churn: share of cells labelled before and after an update whose room "
                 "changed)\n\n"
              << markdown_table(rows) << "\n";
  }
  const TimeStatistics churn_pooled = time_statistics(churn), batch_churn_pooled = time_statistics(batch_churn);

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
  // The live-rooms and speed issues' targets (0.5 ms, 5 ms): the 1 ms of the first live version is met long since.
  rows.push_back({"incremental median per update <= 0.5 ms", format("%.3f ms", t.median), timed && t.median <= 0.5 ? "yes" : "NO"});
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
  if (churn_measured_images == 0) {
    rows.push_back({"churn p95 / batch's churn p95 <= 0.2", "batch's churn not measured (batch ran once per image)", "n/a"});
  } else {
    rows.push_back({"churn p95 / batch's churn p95 <= 0.2 (all updates pooled)",
                    format("%.4f %% / %.4f %%", 100.0 * churn_pooled.p95, 100.0 * batch_churn_pooled.p95),
                    churn_pooled.p95 <= 0.2 * batch_churn_pooled.p95 ? "yes" : "NO"});
    rows.push_back({"images with churn p95 <= 0.2 of batch's",
                    std::to_string(maps_meeting_churn) + " of " + std::to_string(churn_measured_images),
                    maps_meeting_churn == churn_measured_images ? "yes" : "NO"});
  }
  rows.push_back({"images with ids used / final rooms <= 1.3", std::to_string(maps_meeting_ids) + " of " + std::to_string(stable_images),
                  maps_meeting_ids == stable_images ? "yes" : "NO"});
  rows.push_back({"images whose final rooms score as batch's", std::to_string(maps_final_equal) + " of " + std::to_string(stable_images),
                  maps_final_equal == stable_images ? "yes" : "NO"});
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  rows.push_back({"state proportional to the map", format("peak %.1f MB segmenter state (11 bytes per cell + rooms); process peak RSS %.0f MB",
                                                       peak / (1024.0 * 1024.0), usage.ru_maxrss / 1024.0),
                  "-"});
  std::cout << markdown_table(rows) << "\n"
            << format("Run time %.1f min; load average at the end ", minutes) << load_average() << "\n";
  if (!arguments.csv.empty()) write_file_atomically(arguments.csv, incremental_results_csv(results));
  return benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut;
  using namespace topocut::benchmarks;
  IncrementalDatasetOptions options;
  options.exploration.compare_batch = true;
  IncrementalOptions& incremental = options.exploration.incremental;
  DatasetArguments arguments;
  const Program program{
      .name = "incremental_benchmark",
      .title = "Incremental segmentation during exploration",
      .about = "A simulated robot explores every Bormann image; each update is segmented incrementally and by batch\n"
               "(every --batch-every'th); prints times, the rooms' stability and the final quality. The segmenter's\n"
               "options below default to IncrementalOptions'; --batch-fraction 1e-12 makes every update a batch one\n"
               "with ids kept by overlap (batch's own churn).\n",
      .options = joined({count("batch-every", options.exploration.batch_every, 1, "compare batch on every N-th update and the last (default 1)"),
                         {"no-batch", "", "no batch comparison", [&options](const std::string&) { options.exploration.compare_batch = false; }}},
                        table_options(incremental_option_rows(), incremental)),
      .dataset = &arguments,
      .tune_allocator = true};
  return benchmark_main(argc, argv, program, [&] { return run(options, arguments); });
}
