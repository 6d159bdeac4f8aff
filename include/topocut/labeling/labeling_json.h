#pragma once
// A labelled scan as JSON, as `topocut label` prints it (docs/scans.md).
#include <string>
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/scan/scan.h"

namespace topocut {

// {"scan", "beams", "cell", "dilate", "element", "connectivity", "segments": [{"id", "beams",
// "centres"?}...], "invalid_beams"}, indented by two spaces, ending in a newline. `scan_name` is
// the scan as the user named it; "centres" appear only when `centres` has one list per segment.
std::string labeling_to_json(const std::string& scan_name, const Scan& scan, const LabelingOptions& options,
                             const Labeling& labeling, const std::vector<std::vector<Point2>>& centres = {});

}  // namespace topocut
