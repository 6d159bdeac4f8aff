#pragma once
// Fuzzy c-means clustering of 2-D points (Bezdek, "Pattern Recognition with Fuzzy Objective
// Function Algorithms", 1981). Ravankar et al. run it on each labelled segment of a scan and join
// the cluster centres to draw the map; here it returns the centres in an order fit for joining.
#include <span>
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut {

struct FuzzyCMeansOptions {
  int clusters = 2;           // c >= 1, the number of centres wanted
  double fuzzifier = 2.0;     // m > 1; Bezdek's customary value is 2
  double tolerance = 1e-5;    // ε >= 0: stop when no membership changes by more than this
  int max_iterations = 300;   // >= 1: stop here if ε is not reached
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

// Clusters the points into min(clusters, distinct points) fuzzy clusters, seeded deterministically
// (maximin from the point farthest from the mean; ties to the lower index). Centres come in the order
// of the points they hold most, so a scan segment's centres form a polyline; empty input, empty result.
// Throws Error on a non-finite point or invalid options.
FuzzyCMeansResult fuzzy_c_means(std::span<const Point2> points, const FuzzyCMeansOptions& options = {});

}  // namespace topocut
