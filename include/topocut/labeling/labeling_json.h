#pragma once
// A labelled scan as JSON, as `topocut label` prints it (README, "Laser scans and logs").
#include <string>
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/labeling/fuzzy_c_means.h"
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/scan/scan.h"

namespace topocut {

// The fuzzy c-means centres of every segment of a labelled scan (sensor frame, ordered along the
// segment as fuzzy_c_means orders them), one list per segment. Throws Error as fuzzy_c_means.
std::vector<std::vector<Point2>> segment_centres(const Scan& scan, const Labeling& labeling,
                                                 const FuzzyCMeansOptions& options);

// {"scan", "beams", "cell", "dilate", "element", "connectivity", "segments": [{"id", "beams",
// "centres"?}...], "invalid_beams"}, indented by two spaces, ending in a newline. `scan_name` is
// the scan as the user named it; "centres" appear only when `centres` has one list per segment.
std::string labeling_to_json(const std::string& scan_name, const Scan& scan, const LabelingOptions& options,
                             const Labeling& labeling, const std::vector<std::vector<Point2>>& centres = {});

}  // namespace topocut
