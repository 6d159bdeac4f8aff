// The parts of a mask on its runs: against OpenCV's labelling on random masks (the same cells together,
// the same counts), numbered in the raster order of their first cell; a hand-made case of both
// connectivities.
#include "topocut/map/cell_components.h"

#include <map>
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {
namespace {

TEST(CellComponents, TheSamePartsAndCountsAsOpenCVNumberedInRasterOrder) {
  std::mt19937 random(3);
  for (int round = 0; round < 60; ++round) {
    SCOPED_TRACE(round);
    const int rows = 1 + static_cast<int>(random() % 50), cols = 1 + static_cast<int>(random() % 50);
    cv::Mat mask(rows, cols, CV_8UC1);
    cv::randu(mask, 0, 256);
    mask = mask > static_cast<int>(100 + random() % 100);  // from a third to three in five cells set
    for (const bool eight : {true, false}) {
      std::vector<long long> sizes;
      const cv::Mat labels = cell_components(mask, eight, sizes);
      cv::Mat theirs, stats, centres;
      const int parts = cv::connectedComponentsWithStats(mask, theirs, stats, centres, eight ? 8 : 4, CV_32S);
      ASSERT_EQ(static_cast<int>(sizes.size()), parts - 1);
      std::map<int, int> ours_of;  // their label -> ours: one to one, 0 to 0
      int next = 1;                // the next new label met in raster order
      for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
          const int mine = labels.at<int>(r, c), other = theirs.at<int>(r, c);
          ASSERT_EQ(mine == 0, other == 0);
          if (mine == 0) continue;
          const auto [it, added] = ours_of.emplace(other, mine);
          ASSERT_EQ(it->second, mine) << "at " << r << ", " << c;
          if (added) {
            ASSERT_EQ(mine, next++);
          }
          ASSERT_EQ(sizes[static_cast<std::size_t>(mine - 1)], stats.at<int>(other, cv::CC_STAT_AREA));
        }
    }
  }
}

TEST(CellComponents, DiagonalNeighboursJoinOnlyWhenEightConnected) {
  cv::Mat mask(3, 4, CV_8UC1, cv::Scalar(0));
  mask.at<unsigned char>(0, 0) = 255;
  mask.at<unsigned char>(1, 1) = 255;
  mask.at<unsigned char>(1, 2) = 255;
  mask.at<unsigned char>(2, 3) = 9;
  std::vector<long long> sizes;
  const cv::Mat eight = cell_components(mask, true, sizes);
  EXPECT_EQ(sizes, (std::vector<long long>{4}));
  EXPECT_EQ(eight.at<int>(2, 3), 1);
  const cv::Mat four = cell_components(mask, false, sizes);
  EXPECT_EQ(sizes, (std::vector<long long>{1, 2, 1}));
  EXPECT_EQ(four.at<int>(1, 2), 2);
  EXPECT_EQ(four.at<int>(2, 3), 3);
  EXPECT_EQ(four.at<int>(0, 1), 0);
  EXPECT_THROW(cell_components(cv::Mat(), true, sizes), Error);
  EXPECT_THROW(cell_components(cv::Mat(2, 2, CV_32SC1, cv::Scalar(0)), true, sizes), Error);
}

}  // namespace
}  // namespace topocut
