#include "topocut/labeling/labeling_json.h"

#include <nlohmann/json.hpp>

namespace topocut {

std::string labeling_to_json(const std::string& scan_name, const Scan& scan, const LabelingOptions& options,
                             const Labeling& labeling, const std::vector<std::vector<Point2>>& centres) {
  const bool with_centres = !centres.empty() && centres.size() == labeling.segments.size();
  nlohmann::json out;
  out["scan"] = scan_name;
  out["beams"] = scan.size();
  out["cell"] = options.cell_size;
  out["dilate"] = options.dilation;
  out["element"] = options.element == StructuringElement::kCross ? "cross" : "square";
  out["connectivity"] = options.connectivity;
  nlohmann::json segments = nlohmann::json::array();
  for (std::size_t s = 0; s < labeling.segments.size(); ++s) {
    nlohmann::json segment;
    segment["id"] = s;
    segment["beams"] = labeling.segments[s];
    if (with_centres) {
      nlohmann::json list = nlohmann::json::array();
      for (const Point2& c : centres[s]) list.push_back({c.x, c.y});
      segment["centres"] = list;
    }
    segments.push_back(segment);
  }
  out["segments"] = segments;
  nlohmann::json invalid = nlohmann::json::array();
  for (std::size_t i = 0; i < labeling.labels.size(); ++i)
    if (labeling.labels[i] < 0) invalid.push_back(i);
  out["invalid_beams"] = invalid;
  return out.dump(2) + "\n";
}

}  // namespace topocut
