#pragma once
// Order statistics of a list of times (or any values): what every report of the library prints
// about per-image, per-update and per-run times.
#include <vector>

namespace topocut {

// The median of an even count is the mean of the two middle values; p95 is the nearest-rank
// percentile (the smallest value with at least 95 % of the values at or below it).
struct TimeStatistics {
  int count = 0;
  double median = 0.0, p95 = 0.0, max = 0.0, mean = 0.0, total = 0.0;
};

// The statistics of values; everything is 0 for an empty list.
TimeStatistics time_statistics(std::vector<double> values);

}  // namespace topocut
