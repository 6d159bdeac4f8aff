#include "topocut/core/time_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace topocut {

TimeStatistics time_statistics(std::vector<double> values) {
  TimeStatistics t;
  if (values.empty()) return t;
  std::sort(values.begin(), values.end());
  t.count = static_cast<int>(values.size());
  const std::size_t n = values.size();
  t.median = n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(n)));
  t.p95 = values[std::max<std::size_t>(rank, 1) - 1];
  t.max = values.back();
  for (const double v : values) t.total += v;
  t.mean = t.total / static_cast<double>(n);
  return t;
}

}  // namespace topocut
