#pragma once
// Fuzzy c-means clustering of 2-D points (Bezdek, "Pattern Recognition with Fuzzy Objective
// Function Algorithms", 1981). Ravankar et al. run it on each labelled segment of a scan and join
// the cluster centres to draw the map; here it returns the centres in an order fit for joining.
#include <span>
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut {

struct FuzzyCMeansOptions {
  int clusters = 2;           // c, the number of centres wanted
  double fuzzifier = 2.0;     // m > 1; Bezdek's customary value is 2
  double tolerance = 1e-5;    // ε: stop when no membership changes by more than this
  int max_iterations = 300;   // stop here if ε is not reached
};

struct FuzzyCMeansResult {
  std::vector<Point2> centres;      // at most options.clusters (fewer if fewer distinct points)
  std::vector<double> memberships;  // row-major points × centres; each row sums to 1
  int iterations = 0;               // membership updates performed
  bool converged = false;           // true if the tolerance was reached

  // Membership of input point i in centre j.
  double membership(int point, int centre) const {
    return memberships[static_cast<size_t>(point) * centres.size() + static_cast<size_t>(centre)];
  }
};

// Clusters the points into min(clusters, number of distinct points) fuzzy clusters. Initialisation
// is deterministic (maximin: the point farthest from the mean, then repeatedly the point farthest
// from the centres chosen so far; ties to the lower index). Centres are returned ordered by the mean
// input index of the points they hold most, so consecutive centres of a scan segment (points in beam
// order) can be joined into a polyline. An empty input gives an empty result. Throws Error on a
// non-finite point or invalid options (clusters < 1, fuzzifier <= 1, tolerance < 0 or non-finite,
// max_iterations < 1).
FuzzyCMeansResult fuzzy_c_means(std::span<const Point2> points, const FuzzyCMeansOptions& options = {});

}  // namespace topocut
