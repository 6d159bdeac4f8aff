#include "topocut/labeling/segment_centres.h"

namespace topocut {

std::vector<std::vector<Point2>> segment_centres(const Scan& scan, const Labeling& labeling,
                                                 const FuzzyCMeansOptions& options) {
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
