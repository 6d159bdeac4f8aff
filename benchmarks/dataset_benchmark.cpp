// Dataset benchmark: segments every image of a Bormann-format dataset with the given segmenter
// options and prints quality and time per image, plus a summary with medians. Each image's time is
// put next to its "contour floor" (decode the PNG, threshold, cv::findContours: the least work any
// contour-based pipeline must do on it), so runs on different machines compare by the ratio.
// Options: --help.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "benchmark_machine.h"
#include "support/benchmark_main.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/dataset_options.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/evaluation/room_defects.h"
#include "topocut/io/atomic_file.h"

namespace {

using namespace topocut;
using topocut::benchmarks::peak_rss_mb;

double median(std::vector<double> values) { return time_statistics(std::move(values)).median; }

int run(int repeat, int floor_repetitions, DatasetArguments& arguments) {
  benchmarks::require_folder(arguments.dataset);
  if (!arguments.csv.empty()) check_writable(arguments.csv);
  const std::vector<DatasetMap> maps = select_maps(discover_dataset(arguments.dataset), arguments.run.maps);
  const std::string method = method_name(arguments.run.segment);
  std::cout << "dataset: " << arguments.dataset << " (" << maps.size() << " maps)\n"
            << "method: " << method << "\n"
            << "repeat: " << repeat << ", contour floor repetitions: " << floor_repetitions << "\n\n";

  std::vector<double> peak_after;  // running peak RSS after each image of the first run
  arguments.run.progress = [&](const std::string& line) {
    peak_after.push_back(peak_rss_mb());
    std::cerr << line << std::endl;
  };
  std::vector<ImageResult> results = run_dataset(maps, arguments.run, batch_segmenter(arguments.run));
  std::vector<std::vector<double>> times(results.size());
  for (std::size_t i = 0; i < results.size(); ++i) times[i].push_back(results[i].time_ms);
  arguments.run.progress = [](const std::string& line) { std::cerr << line << std::endl; };
  for (int r = 1; r < repeat; ++r) {
    std::cerr << "repeat " << r + 1 << " of " << repeat << "\n";
    const std::vector<ImageResult> again = run_dataset(maps, arguments.run, batch_segmenter(arguments.run));
    for (std::size_t i = 0; i < results.size(); ++i) {
      if (again[i].ok != results[i].ok || again[i].recall != results[i].recall ||
          again[i].precision != results[i].precision) {
        std::cerr << "warning: " << results[i].map << " " << to_string(results[i].variant)
                  << " gave a different result on repeat " << r + 1 << " (not deterministic)\n";
      }
      times[i].push_back(again[i].time_ms);
    }
  }
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (results[i].ok) results[i].time_ms = median(times[i]);
  }

  std::vector<std::vector<std::string>> rows{{"map", "variant", "rooms", "gt rooms", "recall %", "precision %",
                                              "ms", "floor ms", "ms / floor", "peak RSS MB"}};
  std::vector<double> floors, ratios;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const ImageResult& r = results[i];
    const std::string peak = i < peak_after.size() ? fixed(peak_after[i], 0) : "-";
    if (!r.ok) {
      rows.push_back({r.map, to_string(r.variant), "-", "-", "-", "-", "FAILED: " + r.error, "-", "-", peak});
      continue;
    }
    const DatasetMap& map = *std::find_if(maps.begin(), maps.end(), [&](const DatasetMap& m) { return m.name == r.map; });
    const double floor = contour_floor_ms(map.image(r.variant), arguments.run.load.free_min, floor_repetitions);
    floors.push_back(floor);
    ratios.push_back(r.time_ms / floor);
    rows.push_back({r.map, to_string(r.variant), std::to_string(r.rooms), std::to_string(r.gt_rooms),
                    fixed(100.0 * r.recall, 1), fixed(100.0 * r.precision, 1), fixed(r.time_ms, 1), fixed(floor, 2),
                    fixed(r.time_ms / floor, 1), peak});
  }
  std::cout << markdown_table(rows) << "\n" << format_summary(results, method) << "\n";

  std::vector<double> ok_times;
  for (const ImageResult& r : results) {
    if (r.ok) ok_times.push_back(r.time_ms);
  }
  const TimeStatistics time = time_statistics(ok_times);
  const TimeStatistics ratio = time_statistics(ratios);
  std::cout << markdown_table({{"medians over images", "value"},
                               {"segment ms (median / mean / max)",
                                fixed(time.median, 1) + " / " + fixed(time.mean, 1) + " / " + fixed(time.max, 1)},
                               {"contour floor ms (median)", fixed(median(floors), 2)},
                               {"ms / floor (median / max)", fixed(ratio.median, 1) + " / " + fixed(ratio.max, 1)},
                               {"peak RSS MB (whole run)", fixed(peak_rss_mb(), 0)}});

  if (!arguments.csv.empty()) write_file_atomically(arguments.csv, results_csv(results));
  const auto failed = std::count_if(results.begin(), results.end(), [](const ImageResult& r) { return !r.ok; });
  if (failed > 0) {
    std::cerr << "dataset_benchmark: " << failed << " of " << results.size() << " images failed\n";
    return benchmarks::kFailed;
  }
  return benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut;
  using namespace topocut::benchmarks;
  int repeat = 1, floor_repetitions = 5;
  DatasetArguments arguments;
  const Program program{
      .name = "dataset_benchmark",
      .title = "Dataset benchmark",
      .about = "Segments every image of a Bormann-format dataset; prints quality, time and the contour floor per\n"
               "image (decode, threshold, cv::findContours) and the medians.\n",
      .options = {count("repeat", repeat, 1, "run the dataset N times, median time per image (default 1)"),
                  count("floor-repetitions", floor_repetitions, 1, "repetitions of the contour floor per image (default 5)")},
      .dataset = &arguments,
      .tune_allocator = true};
  return benchmark_main(argc, argv, program, [&] { return run(repeat, floor_repetitions, arguments); });
}
