// What the leave-out rows share: run_end() against a cell-at-a-time reference, on runs of every length
// from every start, so that the four-cell compares meet the rows' ends and unaligned starts.
#include "segmentation/merging/window_outline.h"

#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace topocut {
namespace {

int reference_run_end(const std::vector<int>& row, int begin) {
  int end = begin + 1;
  while (end < static_cast<int>(row.size()) && row[end] == row[begin]) ++end;
  return end;
}

TEST(RunEnd, EqualsACellAtATimeFromEveryStart) {
  std::mt19937 random(5);
  for (int round = 0; round < 200; ++round) {
    std::vector<int> row;
    const int cols = 1 + static_cast<int>(random() % 70);
    while (static_cast<int>(row.size()) < cols) {  // runs of 1-13 cells of a few labels, negative ones too
      const int label = static_cast<int>(random() % 5) - 1;
      for (int k = 1 + static_cast<int>(random() % 13); k > 0 && static_cast<int>(row.size()) < cols; --k) row.push_back(label);
    }
    for (int begin = 0; begin < cols; ++begin)
      ASSERT_EQ(run_end(row.data(), begin, cols), reference_run_end(row, begin)) << "round " << round << " from " << begin;
  }
}

TEST(RunEnd, AWholeRowIsOneRun) {
  const std::vector<int> row(37, 4);
  EXPECT_EQ(run_end(row.data(), 0, 37), 37);
  EXPECT_EQ(run_end(row.data(), 36, 37), 37);
  EXPECT_EQ(run_end(row.data(), 0, 1), 1);  // cols bounds the run, not the data
}

}  // namespace
}  // namespace topocut
