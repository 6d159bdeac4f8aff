#include "topocut/labeling/segment_centres.h"

#include <algorithm>
#include <sstream>

#include "topocut/core/error.h"

namespace topocut {

std::vector<std::vector<Point2>> segment_centres(const Scan& scan, const Labeling& labeling,
                                                 const FuzzyCMeansOptions& options) {
  double pairs = 0.0;
  for (const std::vector<int>& segment : labeling.segments)
    pairs += static_cast<double>(segment.size()) * std::min<double>(std::max(options.clusters, 0), static_cast<double>(segment.size()));
  if (pairs > kMaxCentrePairs) {
    std::ostringstream text;
    text << "fuzzy c-means with " << options.clusters << " centres per segment would weigh " << pairs
         << " point-centre pairs per iteration, more than the limit of " << kMaxCentrePairs << ": use fewer centres";
    throw Error(text.str());
  }
  std::vector<std::vector<Point2>> centres;
  centres.reserve(labeling.segments.size());
  for (const std::vector<int>& segment : labeling.segments) {
    std::vector<Point2> points;
    points.reserve(segment.size());
    for (const int beam : segment) points.push_back(beam_point(scan, static_cast<std::size_t>(beam)));
    centres.push_back(fuzzy_c_means(points, options).centres);
  }
  return centres;
}

}  // namespace topocut
