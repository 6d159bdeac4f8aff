#include "topocut/evaluation/dataset_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "topocut/core/format.h"

namespace topocut {

namespace {

struct MeanStd {
  double mean = 0.0;
  double std = 0.0;
};

MeanStd mean_std(const std::vector<double>& values) {
  MeanStd result;
  if (values.empty()) return result;
  double sum = 0.0;
  for (const double v : values) sum += v;
  result.mean = sum / static_cast<double>(values.size());
  double squares = 0.0;
  for (const double v : values) squares += (v - result.mean) * (v - result.mean);
  result.std = std::sqrt(squares / static_cast<double>(values.size()));
  return result;
}

}  // namespace

std::string markdown_table(const std::vector<std::vector<std::string>>& given) {
  // Names come from file names: a control character in one must not reach the terminal.
  std::vector<std::vector<std::string>> rows = given;
  for (auto& row : rows)
    for (std::string& cell : row) cell = terminal_text(cell);
  std::vector<std::size_t> widths;
  const auto display_width = [](const std::string& s) {
    // Count UTF-8 code points, not bytes, so that "±" pads like one character.
    std::size_t n = 0;
    for (const unsigned char c : s) n += (c & 0xC0) != 0x80;
    return n;
  };
  for (const auto& row : rows) {
    widths.resize(std::max(widths.size(), row.size()), 3);
    for (std::size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], display_width(row[i]));
  }
  std::ostringstream out;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out << "|";
    for (std::size_t i = 0; i < widths.size(); ++i) {
      const std::string cell = i < rows[r].size() ? rows[r][i] : "";
      out << " " << cell << std::string(widths[i] - display_width(cell), ' ') << " |";
    }
    out << "\n";
    if (r == 0) {
      out << "|";
      for (const std::size_t w : widths) out << std::string(w + 2, '-') << "|";
      out << "\n";
    }
  }
  return out.str();
}


VariantSummary summarize(const std::vector<ImageResult>& results, Variant variant) {
  VariantSummary summary;
  summary.variant = variant;
  std::vector<double> recall, precision, f1, pq, inside, far, time;
  int segments = 0, rooms = 0;
  for (const ImageResult& r : results) {
    if (r.variant != variant) continue;
    ++summary.images;
    if (!r.ok) {
      ++(r.missing ? summary.missing : summary.failed);
      continue;
    }
    recall.push_back(r.recall);
    precision.push_back(r.precision);
    f1.push_back(r.matched.f1);
    pq.push_back(r.matched.pq);
    inside.push_back(r.precision_inside);
    far.push_back(r.far_share);
    segments += r.matched.segments;
    rooms += r.matched.rooms;
    time.push_back(r.time_ms);
  }
  const MeanStd rs = mean_std(recall), ps = mean_std(precision), fs = mean_std(f1), qs = mean_std(pq);
  summary.recall_mean = rs.mean;
  summary.recall_std = rs.std;
  summary.precision_mean = ps.mean;
  summary.precision_std = ps.std;
  summary.f1_mean = fs.mean;
  summary.f1_std = fs.std;
  summary.pq_mean = qs.mean;
  summary.pq_std = qs.std;
  summary.segments_per_room = rooms > 0 ? static_cast<double>(segments) / rooms : 0.0;
  summary.precision_inside_mean = mean_std(inside).mean;
  summary.far_share_mean = mean_std(far).mean;
  const TimeStatistics ts = time_statistics(time);
  summary.time_mean_ms = ts.mean;
  summary.time_median_ms = ts.median;
  summary.time_max_ms = ts.max;
  return summary;
}

namespace {

std::string percent(double fraction) { return format("%.1f", 100.0 * fraction); }

}  // namespace

std::vector<std::vector<std::string>> results_table_rows(const std::vector<ImageResult>& results) {
  std::vector<std::vector<std::string>> rows{{"map", "variant", "rooms", "gt rooms", "recall %", "precision %", "F1 %",
                                              "PQ %", "seg / room", "P inside %", "far %", "ms"}};
  for (const ImageResult& r : results) {
    if (!r.ok) {
      std::vector<std::string> row(rows.front().size(), "-");
      row[0] = r.map;
      row[1] = to_string(r.variant);
      row.back() = r.missing ? "missing" : "FAILED: " + r.error;
      rows.push_back(row);
      continue;
    }
    rows.push_back({r.map, to_string(r.variant), std::to_string(r.rooms), std::to_string(r.gt_rooms), percent(r.recall),
                    percent(r.precision), percent(r.matched.f1), percent(r.matched.pq),
                    format("%.2f", r.matched.segments_per_room), percent(r.precision_inside), percent(r.far_share),
                    format("%.1f", r.time_ms)});
  }
  return rows;
}

std::string format_results_table(const std::vector<ImageResult>& results) { return markdown_table(results_table_rows(results)); }

std::vector<std::vector<std::string>> summary_rows(const std::vector<ImageResult>& results, const std::string& method) {
  std::vector<std::vector<std::string>> rows{{"method", "variant", "maps", "recall / precision %", "F1 / PQ %",
                                              "segments per room", "P inside annotated %", "far %",
                                              "time per map ms (mean / median / max)"}};
  for (const Variant variant : {Variant::kPlain, Variant::kFurnished}) {
    const VariantSummary s = summarize(results, variant);
    if (s.images == 0) continue;
    const int succeeded = s.succeeded();
    std::vector<std::string> row{method, to_string(variant), std::to_string(succeeded)};
    if (succeeded == 0) {
      row.resize(rows.front().size(), "-");
    } else {
      row.push_back(format("%.1f ± %.1f / %.1f ± %.1f", 100.0 * s.recall_mean, 100.0 * s.recall_std,
                           100.0 * s.precision_mean, 100.0 * s.precision_std));
      row.push_back(format("%.1f ± %.1f / %.1f ± %.1f", 100.0 * s.f1_mean, 100.0 * s.f1_std, 100.0 * s.pq_mean,
                           100.0 * s.pq_std));
      row.push_back(format("%.2f", s.segments_per_room));
      row.push_back(percent(s.precision_inside_mean));
      row.push_back(percent(s.far_share_mean));
      row.push_back(format("%.1f / %.1f / %.1f", s.time_mean_ms, s.time_median_ms, s.time_max_ms));
    }
    rows.push_back(row);
  }
  return rows;
}

std::string summary_notes(const std::vector<ImageResult>& results) {
  std::string notes;
  for (const Variant variant : {Variant::kPlain, Variant::kFurnished}) {
    const VariantSummary s = summarize(results, variant);
    if (s.failed == 0 && s.missing == 0) continue;
    std::string what;
    if (s.failed > 0) what = std::to_string(s.failed) + " failed";
    if (s.missing > 0) what += (what.empty() ? "" : ", ") + std::to_string(s.missing) + " missing";
    notes += "The " + to_string(variant) + " figures are over " + std::to_string(s.succeeded()) + " of " +
             std::to_string(s.images) + " images (" + what + ").\n";
  }
  return notes;
}

std::string format_summary(const std::vector<ImageResult>& results, const std::string& method) {
  return markdown_table(summary_rows(results, method)) + summary_notes(results);
}

std::string results_csv(const std::vector<ImageResult>& results) {
  std::string csv =
      "map,variant,rooms,gt_rooms,recall,precision,time_ms,matches,free_segments,free_rooms,f1,pq,segments_per_room,"
      "precision_inside,far_share,status\n";
  for (const ImageResult& r : results) {
    csv += csv_cell(r.map) + "," + to_string(r.variant) + ",";
    if (r.ok) {
      const MatchedRooms& m = r.matched;
      csv += std::to_string(r.rooms) + "," + std::to_string(r.gt_rooms) + "," +
             format("%.6f,%.6f,%.3f,", r.recall, r.precision, r.time_ms) +
             format("%d,%d,%d,%.6f,%.6f,%.6f,", m.matches, m.segments, m.rooms, m.f1, m.pq, m.segments_per_room) +
             format("%.6f,%.6f,ok", r.precision_inside, r.far_share);
    } else {
      csv += std::string(13, ',') + (r.missing ? "missing" : "failed");
    }
    csv += "\n";
  }
  return csv;
}

}  // namespace topocut
