#pragma once
// Fuzzy c-means on every segment of a labelled scan: the centres Ravankar et al. join into a map.
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

}  // namespace topocut
