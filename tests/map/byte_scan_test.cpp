// The byte scans give what a cell-by-cell scan gives, from every start, on rows whose widths
// straddle the 16-cell blocks and whose differences sit at every position of a block.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "map/byte_scan.h"

namespace topocut {
namespace {

int naive_first_difference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, int from, int to) {
  while (from < to && a[from] == b[from]) ++from;
  return from;
}

int naive_first_nonzero(const std::vector<unsigned char>& row, int from, int to) {
  while (from < to && row[from] == 0) ++from;
  return from;
}

// Rows mostly equal (or zero), with a few cells changed: the scans' common case.
std::vector<unsigned char> sparse_row(std::mt19937& rng, int width, unsigned char fill, int changes) {
  std::vector<unsigned char> row(static_cast<std::size_t>(width), fill);
  for (int k = 0; k < changes && width > 0; ++k) row[rng() % width] = static_cast<unsigned char>(rng() % 256);
  return row;
}

TEST(ByteScan, FirstDifferenceEqualsTheCellByCellScan) {
  std::mt19937 rng(7);
  for (int width = 0; width <= 70; ++width) {
    for (int trial = 0; trial < 20; ++trial) {
      const std::vector<unsigned char> a = sparse_row(rng, width, 255, 0);
      const std::vector<unsigned char> b = sparse_row(rng, width, 255, trial % 4);
      for (int from = 0; from <= width; ++from)
        ASSERT_EQ(first_difference(a.data(), b.data(), from, width), naive_first_difference(a, b, from, width))
            << "width " << width << " from " << from;
    }
  }
}

TEST(ByteScan, FirstNonzeroEqualsTheCellByCellScan) {
  std::mt19937 rng(11);
  for (int width = 0; width <= 70; ++width) {
    for (int trial = 0; trial < 20; ++trial) {
      const std::vector<unsigned char> row = sparse_row(rng, width, 0, trial % 4);
      for (int from = 0; from <= width; ++from)
        ASSERT_EQ(first_nonzero(row.data(), from, width), naive_first_nonzero(row, from, width))
            << "width " << width << " from " << from;
    }
  }
}

TEST(ByteScan, StopsAtTheEndItIsGiven) {
  const std::vector<unsigned char> zeros(40, 0);
  std::vector<unsigned char> ones(40, 0);
  ones[35] = 1;
  EXPECT_EQ(first_nonzero(ones.data(), 0, 30), 30);
  EXPECT_EQ(first_nonzero(ones.data(), 0, 40), 35);
  EXPECT_EQ(first_difference(zeros.data(), ones.data(), 0, 35), 35);
  EXPECT_EQ(first_difference(zeros.data(), ones.data(), 3, 40), 35);
}

}  // namespace
}  // namespace topocut
