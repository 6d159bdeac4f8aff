#pragma once
// A dataset run as one web page for people who judge segmenters by eye: the summary and the
// per-image table (matched rooms included) and, per image, the ground truth's rooms beside the
// segmentation (comparison_pictures.h), missed rooms and merging segments marked. The page
// (index.html) and its pictures (PNG) go into one folder.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/evaluation/dataset.h"

namespace topocut {

class HtmlReport {
 public:
  // The report in folder, which must exist; images are drawn with options' matching.
  explicit HtmlReport(std::string folder, EvaluationOptions options = {});

  // Every file the report may write for these maps and variants (index.html and two pictures per
  // image), to check against the run's inputs before it starts.
  static std::vector<std::string> files(const std::string& folder, const std::vector<DatasetMap>& maps,
                                        const std::vector<Variant>& variants);

  // Draws one scored image (its segment labels, the ground truth's rooms, the map it was scored on)
  // and writes its two pictures atomically. Throws Error if they cannot be drawn or written.
  void add(const ImageResult& result, const cv::Mat& segment_labels, const cv::Mat& room_labels, const OccupancyGrid& grid);

  // Writes index.html atomically: title, the summary of results under method, the per-image table,
  // then per image its pictures (those added) or why it has none (failed, missing).
  void finish(const std::vector<ImageResult>& results, const std::string& title, const std::string& method) const;

 private:
  struct Drawn {
    std::string map;
    Variant variant = Variant::kPlain;
    std::string caption;
  };
  std::string folder_;
  EvaluationOptions options_;
  std::vector<Drawn> drawn_;
};

}  // namespace topocut
