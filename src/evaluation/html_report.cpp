#include "topocut/evaluation/html_report.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "topocut/core/format.h"
#include "topocut/evaluation/comparison_pictures.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/io/atomic_file.h"

namespace topocut {
namespace {

namespace fs = std::filesystem;

std::string picture_name(const std::string& map, Variant variant, const char* side) {
  return map + "_" + to_string(variant) + "_" + side + ".png";
}

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A file name as a relative URL: every byte but unreserved characters percent-encoded.
std::string url(const std::string& name) {
  std::string out;
  for (const unsigned char c : name) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += format("%%%02X", c);
    }
  }
  return out;
}

std::string html_table(const std::vector<std::vector<std::string>>& rows) {
  std::string out = "<table>\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out += "<tr>";
    for (const std::string& cell : rows[r]) out += (r == 0 ? "<th>" : "<td>") + escaped(cell) + (r == 0 ? "</th>" : "</td>");
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

// "13 rooms: 11 matched, 2 missed; 12 segments, 1 merging rooms, 0 others unmatched".
std::string caption(const RoomOutcomes& o) {
  int missed = 0, unmatched = 0;
  for (const auto& [room, segment] : o.room_match) missed += segment == 0;
  for (const auto& [segment, room] : o.segment_match) unmatched += room == 0 && !o.merges.count(segment);
  const int rooms = static_cast<int>(o.room_match.size()), segments = static_cast<int>(o.segment_match.size());
  return format("ground truth: %d rooms, %d matched, %d missed; segmentation: %d segments, %d merging rooms, %d other unmatched",
                rooms, rooms - missed, missed, segments, static_cast<int>(o.merges.size()), unmatched);
}

const char* const kStyle =
    "body{font-family:sans-serif;margin:1.5em;color:#222}table{border-collapse:collapse;margin:0.5em 0 1.5em}"
    "th,td{border:1px solid #bbb;padding:0.2em 0.6em;text-align:right}th{background:#eee}"
    "td:first-child,th:first-child{text-align:left}.pair{display:grid;grid-template-columns:1fr 1fr;gap:1em}"
    ".pair figure{margin:0}.pair img{width:100%;image-rendering:pixelated;border:1px solid #999}"
    ".key span{display:inline-block;width:1em;height:1em;vertical-align:middle;margin:0 0.3em 0 1em;border:1px solid #666}";

}  // namespace

HtmlReport::HtmlReport(std::string folder, EvaluationOptions options) : folder_(std::move(folder)), options_(options) {}

std::vector<std::string> HtmlReport::files(const std::string& folder, const std::vector<DatasetMap>& maps,
                                           const std::vector<Variant>& variants) {
  std::vector<std::string> out{(fs::path(folder) / "index.html").string()};
  for (const DatasetMap& map : maps)
    for (const Variant variant : variants)
      for (const char* side : {"truth", "rooms"}) out.push_back((fs::path(folder) / picture_name(map.name, variant, side)).string());
  return out;
}

void HtmlReport::add(const ImageResult& result, const cv::Mat& segment_labels, const cv::Mat& room_labels,
                     const OccupancyGrid& grid) {
  const ComparisonPictures pictures = comparison_pictures(segment_labels, room_labels, grid.cells, options_);
  write_image_atomically((fs::path(folder_) / picture_name(result.map, result.variant, "truth")).string(), pictures.truth);
  write_image_atomically((fs::path(folder_) / picture_name(result.map, result.variant, "rooms")).string(), pictures.segments);
  drawn_.push_back({result.map, result.variant, caption(pictures.outcomes)});
}

void HtmlReport::finish(const std::vector<ImageResult>& results, const std::string& title, const std::string& method) const {
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escaped(title) +
                     "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" + escaped(title) + "</h1>\n";
  page += "<p>Method: " + escaped(method) + ". Recall and precision as Bormann et al. define them; a segment and a room "
          "match when their IoU over the map's free pixels exceeds " + format("%.2f", options_.match_iou) +
          " (F1, PQ, segments per room).</p>\n";
  page += "<h2>Summary</h2>\n" + html_table(summary_rows(results, method));
  const std::string notes = summary_notes(results);
  if (!notes.empty()) page += "<p>" + escaped(notes) + "</p>\n";
  page += "<h2>Images</h2>\n" + html_table(results_table_rows(results));
  page += "<h2>Ground truth and rooms</h2>\n<p class=\"key\">Left the ground truth's rooms, right the segmentation: a "
          "matched pair has one colour in both."
          "<span style=\"background:#dc2828\"></span>missed room (no segment matches it)"
          "<span style=\"background:#ff8c00\"></span>segment that merged rooms (holds more than half of two or more)"
          "<span style=\"background:#e6e6e6\"></span>other unmatched segment</p>\n";
  for (const ImageResult& r : results) {
    const std::string heading = r.map + " (" + to_string(r.variant) + ")";
    page += "<h3>" + escaped(heading) + "</h3>\n";
    const auto drawn = std::find_if(drawn_.begin(), drawn_.end(), [&](const Drawn& d) { return d.map == r.map && d.variant == r.variant; });
    if (!r.ok || drawn == drawn_.end()) {
      page += "<p>" + escaped(r.missing ? "missing: " + r.error : r.ok ? "not drawn" : "FAILED: " + r.error) + "</p>\n";
      continue;
    }
    page += format("<p>recall %.1f %%, precision %.1f %%, F1 %.1f %%, PQ %.1f %%; ", 100 * r.recall, 100 * r.precision,
                   100 * r.matched.f1, 100 * r.matched.pq) + escaped(drawn->caption) + "</p>\n<div class=\"pair\">";
    for (const auto& [side, what] : {std::pair{"truth", "ground truth"}, std::pair{"rooms", "segmentation"}}) {
      page += "<figure><img src=\"" + url(picture_name(r.map, r.variant, side)) + "\" alt=\"" + escaped(heading + ", " + what) +
              "\"><figcaption>" + what + "</figcaption></figure>";
    }
    page += "</div>\n";
  }
  page += "</body>\n</html>\n";
  write_file_atomically((fs::path(folder_) / "index.html").string(), page);
}

}  // namespace topocut
