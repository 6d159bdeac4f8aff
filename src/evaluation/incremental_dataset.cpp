#include "topocut/evaluation/incremental_dataset.h"

#include <optional>

#include <exception>

#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/exploration_report.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/io/map_loader.h"

namespace topocut {

std::vector<IncrementalImageResult> run_incremental_dataset(const std::vector<DatasetMap>& maps,
                                                            const IncrementalDatasetOptions& options) {
  std::vector<IncrementalImageResult> results;
  const std::size_t total = maps.size() * options.run.variants.size();
  for (const DatasetMap& map : maps) {
    cv::Mat gt_rooms;
    std::string gt_error;
    try {
      const std::optional<ExpectedSize> size = map_image_size(map, options.run);
      gt_rooms = ground_truth_rooms(load_ground_truth(map.ground_truth, options.run.load.limits, size ? &*size : nullptr),
                                    options.run.evaluation);
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
        const ExplorationRun run = run_exploration(world, run_options);
        const ExplorationScore score = score_exploration(run, gt_rooms, world.cells == kFree, options.run.evaluation);
        apply_scores(score.incremental, r.incremental);
        apply_scores(score.batch, r.batch);
        r.batch.time_ms = run.batch_final_ms;
        r.scans = run.scans;
        r.updates = static_cast<int>(run.updates.size());
        r.stop_reason = run.stop_reason;
        r.explored = run.reachable_free_cells > 0
                         ? static_cast<double>(run.known_free_cells) / static_cast<double>(run.reachable_free_cells)
                         : 0.0;
        for (const UpdateRecord& u : run.updates) {
          r.update_ms.push_back(u.incremental_ms);
          r.whole_map_update.push_back(u.batch_update ? 1 : 0);
          r.update_wall_ms.push_back(u.incremental_wall_ms);
          if (u.batch_ms >= 0.0) {
            r.batch_update_ms.push_back(u.batch_ms);
            r.paired_update_ms.push_back(u.incremental_ms);
          }
          r.batch_updates += u.batch_update ? 1 : 0;
        }
        r.incremental_times = time_statistics(r.update_ms);
        r.incremental_wall_times = time_statistics(r.update_wall_ms);
        r.batch_times = time_statistics(r.batch_update_ms);
        r.incremental_compared = time_statistics(r.paired_update_ms);
        r.incremental.time_ms = r.incremental_times.total;
        r.peak_state_bytes = run.peak_state_bytes;
        r.stability = run.stability;
        r.batch_stability = run.batch_stability;
        r.windowed_rooms = run.windowed_rooms;
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

}  // namespace topocut
