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
  int images = 0;   // results of this variant, failed and missing ones included
  int failed = 0;   // failed, not counting the missing ones
  int missing = 0;  // no segmentation to score (ImageResult::missing)
  double recall_mean = 0.0, recall_std = 0.0;        // fractions
  double precision_mean = 0.0, precision_std = 0.0;  // fractions
  double f1_mean = 0.0, f1_std = 0.0;                // matched rooms, fractions
  double pq_mean = 0.0, pq_std = 0.0;
  // All counted segments over all counted rooms (matched rooms' counts, pooled over the maps rather
  // than a mean of per-map ratios, so that a map with many rooms weighs as much as its rooms).
  double segments_per_room = 0.0;
  double precision_inside_mean = 0.0;  // fractions
  double far_share_mean = 0.0;
  double time_mean_ms = 0.0, time_median_ms = 0.0, time_max_ms = 0.0;

  int succeeded() const { return images - failed - missing; }
};

// Summarises the results of one variant; all statistics are 0 when no image of it succeeded.
VariantSummary summarize(const std::vector<ImageResult>& results, Variant variant);

// The per-image table (Markdown): map, variant, rooms found, ground-truth rooms, recall, precision,
// matched-room F1 and PQ in percent, segments per room, precision inside annotated space and far
// share in percent, milliseconds; a failed image shows FAILED and its reason, a missing one "missing".
std::string format_results_table(const std::vector<ImageResult>& results);

// The per-image table's rows, header first (format_results_table() as data, for other formats).
std::vector<std::vector<std::string>> results_table_rows(const std::vector<ImageResult>& results);

// The summary (Markdown), one row per variant that was run:
//   method | variant | maps | recall / precision | F1 / PQ | segments per room | P inside annotated |
//   far | time per map (mean / median / max)
// with mean ± std over the maps that succeeded, in percent, then a line per variant with failed or
// missing images saying over how many maps its means run.
std::string format_summary(const std::vector<ImageResult>& results, const std::string& method);

// The summary's rows, header first, and its notes on failed or missing images (one line each):
// format_summary() as data.
std::vector<std::vector<std::string>> summary_rows(const std::vector<ImageResult>& results, const std::string& method);
std::string summary_notes(const std::vector<ImageResult>& results);

// A Markdown table (first row = header) with every column padded to its widest cell, so that it
// also reads well in a terminal; "±" and other UTF-8 characters count as one column.
std::string markdown_table(const std::vector<std::vector<std::string>>& rows);

// CSV with exactly the columns map,variant,rooms,gt_rooms,recall,precision,time_ms,matches,
// free_segments,free_rooms,f1,pq,segments_per_room,precision_inside,far_share,status (scores as
// fractions; free_* are matched rooms' counts; status ok, failed or missing). A failed or missing
// image keeps its map, variant and status and leaves the rest empty.
std::string results_csv(const std::vector<ImageResult>& results);

}  // namespace topocut
