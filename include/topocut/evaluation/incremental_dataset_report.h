#pragma once
// Tables and CSV for the results of an incremental dataset run (run_incremental_dataset()): the
// batch mode's tables of the final maps plus the time per update.
#include <string>
#include <vector>

#include "topocut/evaluation/incremental_dataset.h"

namespace topocut {

// results_csv() of the incremental results plus the columns
// updates,update_median_ms,update_p95_ms,update_max_ms,batch_update_median_ms
// (the last one empty unless batch was compared on the same updates).
std::string incremental_results_csv(const std::vector<IncrementalImageResult>& results);

// Markdown table of per-update times per image: updates, incremental median / p95 / max, and when
// compared, batch median on the same updates and the ratio of the medians.
std::string format_update_times_table(const std::vector<IncrementalImageResult>& results);

// The whole report of an incremental dataset run, as `topocut evaluate --mode incremental` prints
// it: the per-image table and summary of the final incremental maps (the same tables as batch
// mode), the summary of batch on the same final maps, and the per-update time tables.
std::string format_incremental_report(const std::vector<IncrementalImageResult>& results, const std::string& method);

// Markdown summary over all images: all updates pooled (median, p95, max), batch on the same
// updates and the speed-up, quality of incremental and batch on the final maps, peak state.
std::string format_incremental_summary(const std::vector<IncrementalImageResult>& results);

}  // namespace topocut
