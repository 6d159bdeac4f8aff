#pragma once
// Tables and CSV for the results of a dataset run: the per-image table, the summary in the shape
// of Bormann et al.'s and Fermin-Leon et al.'s result tables, and the CSV other tools read.
#include <string>
#include <vector>

#include "topocut/core/time_statistics.h"
#include "topocut/evaluation/dataset.h"

namespace topocut {

// Statistics of one variant over the images that succeeded. Standard deviations are population
// deviations (divide by n): the 20 maps are the whole benchmark, not a sample of it.
struct VariantSummary {
  Variant variant = Variant::kPlain;
  int images = 0;  // results of this variant, failed ones included
  int failed = 0;
  double recall_mean = 0.0, recall_std = 0.0;        // fractions
  double precision_mean = 0.0, precision_std = 0.0;  // fractions
  double time_mean_ms = 0.0, time_median_ms = 0.0, time_max_ms = 0.0;
};

// Summarises the results of one variant; all statistics are 0 when no image of it succeeded.
VariantSummary summarize(const std::vector<ImageResult>& results, Variant variant);

// The per-image table (Markdown): map, variant, rooms found, ground-truth rooms, recall and
// precision in percent, milliseconds; a failed image shows FAILED and its reason.
std::string format_results_table(const std::vector<ImageResult>& results);

// The summary (Markdown), one row for method:
//   method | plain recall / precision | furnished recall / precision | time per map (mean / median / max)
// with mean ± std over maps in percent and time over every successful image, then a line per
// variant with failures, if any.
std::string format_summary(const std::vector<ImageResult>& results, const std::string& method);

// A Markdown table (first row = header) with every column padded to its widest cell, so that it
// also reads well in a terminal; "±" and other UTF-8 characters count as one column.
std::string markdown_table(const std::vector<std::vector<std::string>>& rows);

// CSV with exactly the columns map,variant,rooms,gt_rooms,recall,precision,time_ms (recall and
// precision as fractions). A failed image keeps its map and variant and leaves the rest empty.
std::string results_csv(const std::vector<ImageResult>& results);

}  // namespace topocut
