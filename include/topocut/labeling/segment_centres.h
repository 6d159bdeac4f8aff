#pragma once
// Fuzzy c-means on every segment of a labelled scan: the centres Ravankar et al. join into a map.
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/labeling/fuzzy_c_means.h"
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/scan/scan.h"

namespace topocut {

// The point-centre pairs fuzzy c-means may weigh per iteration over a whole scan (points of each
// segment times its centres): 1 million beams with 10 centres each are 10^7, seconds of work
// (benchmarks/README.md, "Scans of a million beams"); the bound is five times that.
inline constexpr double kMaxCentrePairs = 5e7;

// The fuzzy c-means centres of every segment of a labelled scan (sensor frame, ordered along the
// segment as fuzzy_c_means orders them), one list per segment. Throws Error as fuzzy_c_means, and
// before any work when the segments' points times their centres exceed kMaxCentrePairs.
std::vector<std::vector<Point2>> segment_centres(const Scan& scan, const Labeling& labeling,
                                                 const FuzzyCMeansOptions& options);

}  // namespace topocut
