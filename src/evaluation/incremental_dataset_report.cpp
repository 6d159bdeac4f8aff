#include "topocut/evaluation/incremental_dataset_report.h"

#include <algorithm>
#include <sstream>

#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset_report.h"

namespace topocut {

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
  std::vector<double> all, wall, batch, paired, windowed, whole;
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
    for (std::size_t i = 0; i < r.update_ms.size() && i < r.whole_map_update.size(); ++i)
      (r.whole_map_update[i] ? whole : windowed).push_back(r.update_ms[i]);
    peak = std::max(peak, r.peak_state_bytes);
    updates += r.updates;
    batch_updates += r.batch_updates;
  }
  const TimeStatistics inc = time_statistics(all), inc_wall = time_statistics(wall), bat = time_statistics(batch),
                       pair = time_statistics(paired);
  std::vector<std::vector<std::string>> rows{{"per update (all images pooled)", "median ms", "p95 ms", "max ms", "updates"}};
  const auto time_row = [](const std::string& label, const TimeStatistics& t) {
    return std::vector<std::string>{label, format("%.3f", t.median), format("%.3f", t.p95), format("%.2f", t.max), std::to_string(t.count)};
  };
  rows.push_back(time_row("incremental", inc));
  rows.push_back(time_row("incremental, wall clock", inc_wall));
  // Which updates make the tail: the windowed ones, or those that decomposed the whole map again.
  if (!windowed.empty()) rows.push_back(time_row("incremental, windowed updates", time_statistics(windowed)));
  if (!whole.empty()) rows.push_back(time_row("incremental, whole-map updates", time_statistics(whole)));
  if (bat.count > 0) {
    rows.push_back(time_row("incremental, compared updates", pair));
    rows.push_back({"batch segment(), same updates", format("%.2f", bat.median), format("%.2f", bat.p95),
                    format("%.2f", bat.max), std::to_string(bat.count)});
  }
  std::string out = "Times are process CPU time unless marked wall clock.\n\n" + markdown_table(rows);
  if (bat.count > 0 && pair.median > 0.0 && pair.total > 0.0) {
    out += format("\nSpeed-up on the same updates: %.1fx (medians), %.1fx (total time).\n", bat.median / pair.median,
                  bat.total / pair.total);
  }
  out += format("\n%d updates, %d of them decomposed everything again (the first, a wholesale change, or what a window cannot judge); "
                "peak segmenter state %.1f MB.\n",
                updates, batch_updates, static_cast<double>(peak) / (1024.0 * 1024.0));
  if (failed > 0) out += std::to_string(failed) + " images failed.\n";
  return out;
}

}  // namespace topocut
