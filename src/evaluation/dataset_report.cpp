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

std::string markdown_table(const std::vector<std::vector<std::string>>& rows) {
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

namespace {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

VariantSummary summarize(const std::vector<ImageResult>& results, Variant variant) {
  VariantSummary summary;
  summary.variant = variant;
  std::vector<double> recall, precision, time;
  for (const ImageResult& r : results) {
    if (r.variant != variant) continue;
    ++summary.images;
    if (!r.ok) {
      ++summary.failed;
      continue;
    }
    recall.push_back(r.recall);
    precision.push_back(r.precision);
    time.push_back(r.time_ms);
  }
  const MeanStd rs = mean_std(recall);
  const MeanStd ps = mean_std(precision);
  summary.recall_mean = rs.mean;
  summary.recall_std = rs.std;
  summary.precision_mean = ps.mean;
  summary.precision_std = ps.std;
  const TimeStatistics ts = time_statistics(time);
  summary.time_mean_ms = ts.mean;
  summary.time_median_ms = ts.median;
  summary.time_max_ms = ts.max;
  return summary;
}

std::string format_results_table(const std::vector<ImageResult>& results) {
  std::vector<std::vector<std::string>> rows{
      {"map", "variant", "rooms", "gt rooms", "recall %", "precision %", "ms"}};
  for (const ImageResult& r : results) {
    if (!r.ok) {
      rows.push_back({r.map, to_string(r.variant), "-", "-", "-", "-", "FAILED: " + r.error});
      continue;
    }
    rows.push_back({r.map, to_string(r.variant), std::to_string(r.rooms), std::to_string(r.gt_rooms),
                    format("%.1f", 100.0 * r.recall), format("%.1f", 100.0 * r.precision),
                    format("%.1f", r.time_ms)});
  }
  return markdown_table(rows);
}

std::string format_summary(const std::vector<ImageResult>& results, const std::string& method) {
  std::vector<std::string> row{method};
  std::string notes;
  for (const Variant variant : {Variant::kPlain, Variant::kFurnished}) {
    const VariantSummary s = summarize(results, variant);
    const int succeeded = s.images - s.failed;
    if (succeeded == 0) {
      row.push_back("-");
    } else {
      row.push_back(format("%.1f ± %.1f / %.1f ± %.1f", 100.0 * s.recall_mean, 100.0 * s.recall_std,
                           100.0 * s.precision_mean, 100.0 * s.precision_std));
    }
    if (s.failed > 0) {
      notes += std::to_string(s.failed) + " of " + std::to_string(s.images) + " " + to_string(variant) +
               " images failed; the " + to_string(variant) + " figures are over the " +
               std::to_string(succeeded) + " that succeeded.\n";
    }
  }
  std::vector<double> times;
  for (const ImageResult& r : results) {
    if (r.ok) times.push_back(r.time_ms);
  }
  const TimeStatistics ts = time_statistics(times);
  row.push_back(times.empty() ? "-" : format("%.1f / %.1f / %.1f", ts.mean, ts.median, ts.max));
  const std::string table = markdown_table(
      {{"method", "plain recall / precision %", "furnished recall / precision %",
        "time per map ms (mean / median / max)"},
       row});
  return table + notes;
}

std::string results_csv(const std::vector<ImageResult>& results) {
  std::string csv = "map,variant,rooms,gt_rooms,recall,precision,time_ms\n";
  for (const ImageResult& r : results) {
    csv += csv_field(r.map) + "," + to_string(r.variant) + ",";
    if (r.ok) {
      csv += std::to_string(r.rooms) + "," + std::to_string(r.gt_rooms) + "," +
             format("%.6f,%.6f,%.3f", r.recall, r.precision, r.time_ms);
    } else {
      csv += ",,,,";
    }
    csv += "\n";
  }
  return csv;
}

}  // namespace topocut
