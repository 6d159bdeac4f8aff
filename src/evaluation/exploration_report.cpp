#include "topocut/evaluation/exploration_report.h"

#include <sstream>

#include "topocut/core/format.h"
#include "topocut/core/time_statistics.h"

namespace topocut {

ExplorationScore score_exploration(const ExplorationRun& run, const cv::Mat& gt_rooms, const cv::Mat& free,
                                   const EvaluationOptions& options) {
  auto score = [&](const Segmentation& s) {
    return score_segmentation(labels_in_frame(s.labels, run.window, gt_rooms.size()), gt_rooms, free, s.resolution,
                              options);
  };
  return {score(run.incremental), score(run.batch)};
}

std::string format_update_times(const std::vector<UpdateRecord>& updates) {
  std::vector<double> inc, inc_wall, batch, paired;
  for (const UpdateRecord& u : updates) {
    inc.push_back(u.incremental_ms);
    inc_wall.push_back(u.incremental_wall_ms);
    if (u.batch_ms >= 0.0) {
      batch.push_back(u.batch_ms);
      paired.push_back(u.incremental_ms);
    }
  }
  const TimeStatistics inc_t = time_statistics(inc), wall_t = time_statistics(inc_wall),
                       batch_t = time_statistics(batch), paired_t = time_statistics(paired);
  std::string out = "incremental per update: " + format("median %.3f ms, p95 %.3f ms, ", inc_t.median, inc_t.p95) +
                    format("max %.2f ms (total %.1f ms; CPU time)\n", inc_t.max, inc_t.total) +
                    "  wall clock:           " + format("median %.3f ms, p95 %.3f ms, ", wall_t.median, wall_t.p95) +
                    format("max %.2f ms\n", wall_t.max);
  if (batch_t.count == 0) return out;
  out += "batch per update:       " + format("median %.3f ms, p95 %.3f ms, ", batch_t.median, batch_t.p95) +
         format("max %.2f ms (%d updates compared)\n", batch_t.max, batch_t.count);
  if (paired_t.median > 0.0 && paired_t.total > 0.0)
    out += "speed-up on the same updates: " +
           format("%.1fx (medians), %.1fx (totals)\n", batch_t.median / paired_t.median, batch_t.total / paired_t.total);
  return out;
}

std::string format_stability(const StabilityReport& r) {
  return format("churn median %.3f %%, p95 %.3f %%, max %.3f %% (%d of %zu updates); rooms changed %d of %zu (%d "
                "changes); ids used %d, final rooms %d",
                100.0 * r.churn_median, 100.0 * r.churn_p95, 100.0 * r.churn_max, r.updates_with_churn, r.churn.size(),
                r.rooms_changed, r.rooms.size(), r.room_changes, r.distinct_ids, r.final_rooms);
}

std::string final_rooms_line(const GridReplay& run) {
  std::string out = "final rooms: incremental " + std::to_string(run.incremental.rooms.size());
  if (run.windowed_rooms != static_cast<int>(run.incremental.rooms.size()))
    out += " (" + std::to_string(run.windowed_rooms) + " before the map at rest was segmented as a whole)";
  return out + ", batch " + std::to_string(run.batch.rooms.size()) + "\n";
}

std::string format_batch_stability(const GridReplay& run) {
  const StabilityReport& b = run.batch_stability;
  if (b.final_rooms == 0 && b.churn.empty()) return "";
  const StabilityReport& i = run.stability;
  auto ids_per_room = [](const StabilityReport& r) {
    return r.final_rooms > 0 ? static_cast<double>(r.distinct_ids) / r.final_rooms : 0.0;
  };
  std::string out = "batch stability (ids carried by overlap): " + format_stability(b) + "\n";
  out += "against batch: churn p95 ";
  out += b.churn_p95 > 0.0 ? format("%.2f", i.churn_p95 / b.churn_p95) : std::string(i.churn_p95 > 0.0 ? "inf" : "-");
  out += format(" of batch's; ids used per final room %.2f (batch %.2f)\n", ids_per_room(i), ids_per_room(b));
  return out;
}

std::string format_exploration_summary(const ExplorationRun& run, const cv::Mat& gt_rooms, const std::string& ground_truth) {
  std::ostringstream out;
  out << "scans: " << run.scans << ", updates: " << run.updates.size() << " (" << run.stop_reason << "), path "
      << format("%.1f m\n", run.path_length);
  if (run.reachable_free_cells > 0)
    out << "explored: "
        << format("%.1f %% of the reachable free space\n", 100.0 * run.known_free_cells / run.reachable_free_cells);
  out << format_update_times(run.updates);
  out << "stability: " << format_stability(run.stability) << "\n";
  out << format_batch_stability(run);
  out << "peak segmenter state: " << format("%.1f MB\n", run.peak_state_bytes / (1024.0 * 1024.0));
  out << final_rooms_line(run);
  if (gt_rooms.empty()) return out.str();
  const ExplorationScore score = score_exploration(run, gt_rooms);
  const PrecisionRecall& a = score.incremental.overlap;
  const PrecisionRecall& b = score.batch.overlap;
  out << "ground truth " << ground_truth << ":\n"
      << "  incremental: " << format("recall %.1f %%, precision %.1f %%\n", 100.0 * a.recall, 100.0 * a.precision)
      << "  batch:       " << format("recall %.1f %%, precision %.1f %%\n", 100.0 * b.recall, 100.0 * b.precision);
  return out.str();
}

}  // namespace topocut
