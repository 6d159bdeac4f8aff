#include "topocut/exploration/exploration_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "exploration/timed_update.h"
#include "topocut/core/error.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d);
  return buffer;
}

}  // namespace

ExplorationRun run_exploration(const OccupancyGrid& ground_truth, const ExplorationRunOptions& options) {
  if (options.batch_every < 1) throw Error("batch comparison needs an interval of at least one update");
  Explorer explorer(ground_truth, options.exploration);
  IncrementalSegmenter segmenter(options.incremental);
  ExplorationRun run;
  StabilityTracker stability;
  int update = 0;
  while (explorer.next()) {
    const cv::Rect changed = explorer.changed();
    if (changed.empty()) continue;  // the scan saw nothing new: the map did not change
    ++update;
    const OccupancyGrid& grid = explorer.known_map();
    UpdateRecord record = detail::timed_update(segmenter, grid, options.use_hint ? &changed : nullptr,
                                               options.compare_batch && update % options.batch_every == 0);
    record.scan = explorer.scans();
    const Segmentation& result = segmenter.result();
    stability.add(result.labels, grid.origin, grid.resolution);
    run.updates.push_back(record);
    run.peak_state_bytes = std::max(run.peak_state_bytes, segmenter.state_bytes());
    if (options.on_update) options.on_update(ExplorationFrame{update, explorer, grid, result});
    if (options.progress && update % 250 == 0) {
      options.progress("update " + std::to_string(update) + " (scan " + std::to_string(explorer.scans()) + "): " +
                       std::to_string(record.rooms) + " rooms");
    }
  }
  run.scans = explorer.scans();
  run.stop_reason = explorer.stop_reason();
  run.path_length = explorer.path_length();
  run.path = explorer.path();
  run.final_pose = explorer.pose();
  run.final_map = explorer.known_map();
  run.final_map.cells = explorer.known_map().cells.clone();
  run.window = explorer.window();
  run.incremental = segmenter.result();
  run.incremental.labels = segmenter.result().labels.clone();
  run.batch = detail::final_batch(run.final_map, options.incremental.segment, options.compare_batch, run.updates,
                                  &run.batch_final_ms);
  run.stability = stability.report();
  run.known_free_cells = cv::countNonZero(run.final_map.cells == kFree);
  if (!run.path.empty()) run.reachable_free_cells = reachable_free_cells(ground_truth, run.path.front());
  return run;
}

cv::Mat labels_in_frame(const cv::Mat& labels, const cv::Rect& window, const cv::Size& frame) {
  if (labels.type() != CV_32SC1 || labels.size() != window.size() || (window & cv::Rect(cv::Point(0, 0), frame)) != window)
    throw Error("the labels do not fit the given window of the frame");
  cv::Mat out = cv::Mat::zeros(frame, CV_32SC1);
  labels.copyTo(out(window));
  return out;
}

UpdateTimes update_times(std::vector<double> values) {
  UpdateTimes t;
  if (values.empty()) return t;
  std::sort(values.begin(), values.end());
  t.count = static_cast<int>(values.size());
  const std::size_t n = values.size();
  t.median = n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(n)));
  t.p95 = values[std::max<std::size_t>(rank, 1) - 1];
  t.max = values.back();
  for (const double v : values) t.total += v;
  t.mean = t.total / static_cast<double>(n);
  return t;
}

std::string find_ground_truth(const std::string& map_path) {
  namespace fs = std::filesystem;
  const fs::path path(map_path);
  std::string stem = path.stem().string();
  const std::string furnished = "_furnitures";
  if (stem.size() > furnished.size() && stem.compare(stem.size() - furnished.size(), furnished.size(), furnished) == 0)
    stem.resize(stem.size() - furnished.size());
  const fs::path candidate = path.parent_path() / (stem + "_gt_segmentation.png");
  std::error_code error;
  if (candidate != path && fs::is_regular_file(candidate, error)) return candidate.string();
  return {};
}

std::vector<IncrementalImageResult> run_incremental_dataset(const std::vector<DatasetMap>& maps,
                                                            const IncrementalDatasetOptions& options) {
  std::vector<IncrementalImageResult> results;
  const std::size_t total = maps.size() * options.run.variants.size();
  for (const DatasetMap& map : maps) {
    cv::Mat gt_rooms;
    std::string gt_error;
    try {
      gt_rooms = ground_truth_rooms(load_ground_truth(map.ground_truth, options.run.load.limits), options.run.evaluation);
    } catch (const std::exception& e) {
      gt_error = e.what();
    }
    for (const Variant variant : options.run.variants) {
      IncrementalImageResult r;
      r.incremental.map = r.batch.map = map.name;
      r.incremental.variant = r.batch.variant = variant;
      try {
        if (!gt_error.empty()) throw Error(gt_error);
        const OccupancyGrid world = load_map(map.image(variant), options.run.load);
        if (world.cells.size() != gt_rooms.size())
          throw Error("the ground truth's size differs from the map's (" + map.ground_truth + ")");
        ExplorationRunOptions run_options = options.exploration;
        run_options.incremental.segment = options.run.segment;
        run_options.incremental.segment.clean = false;  // not incremental yet (IncrementalOptions)
        const ExplorationRun run = run_exploration(world, run_options);
        auto score = [&](const Segmentation& s, ImageResult& out) {
          const PrecisionRecall pr =
              precision_recall(labels_in_frame(s.labels, run.window, world.cells.size()), gt_rooms, options.run.evaluation);
          out.ok = true;
          out.rooms = pr.segments;
          out.gt_rooms = pr.rooms;
          out.recall = pr.recall;
          out.precision = pr.precision;
        };
        score(run.incremental, r.incremental);
        score(run.batch, r.batch);
        r.batch.time_ms = run.batch_final_ms;
        r.scans = run.scans;
        r.updates = static_cast<int>(run.updates.size());
        r.stop_reason = run.stop_reason;
        r.explored = run.reachable_free_cells > 0
                         ? static_cast<double>(run.known_free_cells) / static_cast<double>(run.reachable_free_cells)
                         : 0.0;
        for (const UpdateRecord& u : run.updates) {
          r.update_ms.push_back(u.incremental_ms);
          r.update_wall_ms.push_back(u.incremental_wall_ms);
          if (u.batch_ms >= 0.0) {
            r.batch_update_ms.push_back(u.batch_ms);
            r.paired_update_ms.push_back(u.incremental_ms);
          }
          r.batch_updates += u.batch_update ? 1 : 0;
        }
        r.incremental_times = update_times(r.update_ms);
        r.incremental_wall_times = update_times(r.update_wall_ms);
        r.batch_times = update_times(r.batch_update_ms);
        r.incremental_compared = update_times(r.paired_update_ms);
        r.incremental.time_ms = r.incremental_times.total;
        r.peak_state_bytes = run.peak_state_bytes;
        r.stability = run.stability;
      } catch (const std::exception& e) {
        r.incremental.ok = r.batch.ok = false;
        r.incremental.error = r.batch.error = e.what();
      }
      results.push_back(r);
      if (options.run.progress) {
        std::string line = "[" + std::to_string(results.size()) + "/" + std::to_string(total) + "] " + map.name + " " +
                           to_string(variant) + ": ";
        if (!r.incremental.ok) {
          line += "FAILED: " + r.incremental.error;
        } else {
          line += std::to_string(r.updates) + " updates, incremental median " +
                  format("%.2f ms, p95 %.2f ms", r.incremental_times.median, r.incremental_times.p95);
          if (r.batch_times.count > 0) line += format(", batch median %.1f ms", r.batch_times.median);
          line += format(", recall/precision %.1f/%.1f (batch %.1f/%.1f)", 100.0 * r.incremental.recall,
                         100.0 * r.incremental.precision, 100.0 * r.batch.recall, 100.0 * r.batch.precision);
        }
        options.run.progress(line);
      }
    }
  }
  return results;
}

std::vector<ImageResult> incremental_image_results(const std::vector<IncrementalImageResult>& results) {
  std::vector<ImageResult> out;
  for (const IncrementalImageResult& r : results) out.push_back(r.incremental);
  return out;
}

std::vector<ImageResult> batch_image_results(const std::vector<IncrementalImageResult>& results) {
  std::vector<ImageResult> out;
  for (const IncrementalImageResult& r : results) out.push_back(r.batch);
  return out;
}

std::string incremental_results_csv(const std::vector<IncrementalImageResult>& results) {
  const std::string base = results_csv(incremental_image_results(results));
  std::istringstream lines(base);
  std::ostringstream out;
  std::string line;
  std::getline(lines, line);
  out << line << ",updates,update_median_ms,update_p95_ms,update_max_ms,batch_update_median_ms\n";
  for (const IncrementalImageResult& r : results) {
    if (!std::getline(lines, line)) throw Error("internal: the results CSV has fewer rows than results");
    out << line;
    if (!r.incremental.ok) {
      out << ",,,,,\n";
      continue;
    }
    out << "," << r.updates << format(",%.4f,%.4f,%.4f,", r.incremental_times.median, r.incremental_times.p95,
                                      r.incremental_times.max);
    if (r.batch_times.count > 0) out << format("%.4f", r.batch_times.median);
    out << "\n";
  }
  return out.str();
}

std::string format_update_times_table(const std::vector<IncrementalImageResult>& results) {
  std::vector<std::vector<std::string>> rows{{"map", "variant", "scans", "updates", "inc median ms", "inc p95 ms",
                                              "inc max ms", "batch median ms", "speed-up", "state MB"}};
  for (const IncrementalImageResult& r : results) {
    if (!r.incremental.ok) {
      rows.push_back({r.incremental.map, to_string(r.incremental.variant), "-", "-", "-", "-", "-", "-", "-",
                      "FAILED: " + r.incremental.error});
      continue;
    }
    const bool compared = r.batch_times.count > 0;
    rows.push_back({r.incremental.map, to_string(r.incremental.variant), std::to_string(r.scans),
                    std::to_string(r.updates), format("%.3f", r.incremental_times.median),
                    format("%.3f", r.incremental_times.p95), format("%.2f", r.incremental_times.max),
                    compared ? format("%.2f", r.batch_times.median) : "-",
                    compared && r.incremental_compared.median > 0.0
                        ? format("%.0fx", r.batch_times.median / r.incremental_compared.median)
                        : "-",
                    format("%.1f", static_cast<double>(r.peak_state_bytes) / (1024.0 * 1024.0))});
  }
  return markdown_table(rows);
}

std::string format_incremental_report(const std::vector<IncrementalImageResult>& results, const std::string& method) {
  const std::vector<ImageResult> incremental = incremental_image_results(results);
  return format_results_table(incremental) + "\n" + format_summary(incremental, method) +
         format_summary(batch_image_results(results), "batch segment() on the same final maps") +
         "\nTime per update:\n\n" + format_update_times_table(results) + "\n" + format_incremental_summary(results);
}

std::string format_incremental_summary(const std::vector<IncrementalImageResult>& results) {
  std::vector<double> all, wall, batch, paired;
  std::size_t peak = 0;
  int updates = 0, batch_updates = 0, failed = 0;
  for (const IncrementalImageResult& r : results) {
    if (!r.incremental.ok) {
      ++failed;
      continue;
    }
    all.insert(all.end(), r.update_ms.begin(), r.update_ms.end());
    wall.insert(wall.end(), r.update_wall_ms.begin(), r.update_wall_ms.end());
    batch.insert(batch.end(), r.batch_update_ms.begin(), r.batch_update_ms.end());
    paired.insert(paired.end(), r.paired_update_ms.begin(), r.paired_update_ms.end());
    peak = std::max(peak, r.peak_state_bytes);
    updates += r.updates;
    batch_updates += r.batch_updates;
  }
  const UpdateTimes inc = update_times(all), inc_wall = update_times(wall), bat = update_times(batch),
                    pair = update_times(paired);
  std::vector<std::vector<std::string>> rows{{"per update (all images pooled)", "median ms", "p95 ms", "max ms", "updates"}};
  rows.push_back({"incremental", format("%.3f", inc.median), format("%.3f", inc.p95), format("%.2f", inc.max),
                  std::to_string(inc.count)});
  rows.push_back({"incremental, wall clock", format("%.3f", inc_wall.median), format("%.3f", inc_wall.p95),
                  format("%.2f", inc_wall.max), std::to_string(inc_wall.count)});
  if (bat.count > 0) {
    rows.push_back({"incremental, compared updates", format("%.3f", pair.median), format("%.3f", pair.p95),
                    format("%.2f", pair.max), std::to_string(pair.count)});
    rows.push_back({"batch segment(), same updates", format("%.2f", bat.median), format("%.2f", bat.p95),
                    format("%.2f", bat.max), std::to_string(bat.count)});
  }
  std::string out = "Times are process CPU time unless marked wall clock.\n\n" + markdown_table(rows);
  if (bat.count > 0 && pair.median > 0.0 && pair.total > 0.0) {
    out += format("\nSpeed-up on the same updates: %.1fx (medians), %.1fx (total time).\n", bat.median / pair.median,
                  bat.total / pair.total);
  }
  out += "\n" + std::to_string(updates) + " updates, " + std::to_string(batch_updates) +
         " of them decomposed everything again (first update or wholesale change); peak segmenter state " +
         format("%.1f MB.\n", static_cast<double>(peak) / (1024.0 * 1024.0));
  if (failed > 0) out += std::to_string(failed) + " images failed.\n";
  return out;
}

}  // namespace topocut
