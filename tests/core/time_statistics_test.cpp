#include "topocut/core/time_statistics.h"

#include <vector>

#include <gtest/gtest.h>

namespace topocut {
namespace {

TEST(TimeStatistics, CountMedianNearestRankP95MaxTotalMean) {
  const TimeStatistics odd = time_statistics({5.0, 1.0, 3.0, 2.0, 4.0});
  EXPECT_EQ(odd.count, 5);
  EXPECT_DOUBLE_EQ(odd.median, 3.0);
  EXPECT_DOUBLE_EQ(odd.p95, 5.0);  // rank ceil(0.95 * 5) = 5
  EXPECT_DOUBLE_EQ(odd.max, 5.0);
  EXPECT_DOUBLE_EQ(odd.total, 15.0);
  EXPECT_DOUBLE_EQ(odd.mean, 3.0);
  std::vector<double> hundred;
  for (int i = 100; i >= 1; --i) hundred.push_back(i);
  const TimeStatistics h = time_statistics(hundred);
  EXPECT_DOUBLE_EQ(h.median, 50.5);
  EXPECT_DOUBLE_EQ(h.p95, 95.0);  // rank 95
  const TimeStatistics none = time_statistics({});
  EXPECT_EQ(none.count, 0);
  EXPECT_DOUBLE_EQ(none.p95, 0.0);
}

TEST(TimeStatistics, MeanMedianMaxOfTimes) {
  const TimeStatistics even = time_statistics({3.0, 1.0, 2.0, 10.0});
  EXPECT_DOUBLE_EQ(even.mean, 4.0);
  EXPECT_DOUBLE_EQ(even.median, 2.5);
  EXPECT_DOUBLE_EQ(even.max, 10.0);
  const TimeStatistics odd = time_statistics({5.0, 1.0, 9.0});
  EXPECT_DOUBLE_EQ(odd.median, 5.0);
  const TimeStatistics none = time_statistics({});
  EXPECT_EQ(none.mean, 0.0);
}

}  // namespace
}  // namespace topocut
