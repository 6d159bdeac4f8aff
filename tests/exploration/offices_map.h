#pragma once
// The test map of the exploration tests: a corridor with four rooms behind doors, and the check
// that a segmentation labels exactly the cells segment() labels: the free cells of its grid as the
// real-map cleaning leaves them (rays out of the building unlabelled, unknown floor specks labelled).
#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut::test {

constexpr double kRes = 0.05;

// 15 m x 9 m: a corridor with four rooms behind doors (walls 4 cells).
inline OccupancyGrid offices() {
  OccupancyGrid g;
  g.resolution = kRes;
  g.cells = cv::Mat(180, 300, CV_8UC1, cv::Scalar(kOccupied));
  g.cells(cv::Rect(4, 140, 292, 36)).setTo(kFree);
  int x = 4;
  for (const int width : {70, 60, 80, 70}) {
    g.cells(cv::Rect(x, 4, width, 132)).setTo(kFree);
    g.cells(cv::Rect(x + width / 2 - 9, 136, 18, 4)).setTo(kFree);
    x += width + 4;
  }
  return g;
}

inline void expect_every_free_cell_labelled(const OccupancyGrid& grid, const Segmentation& s,
                                            const SegmentOptions& options = {}) {
  ASSERT_EQ(s.labels.size(), grid.cells.size());
  const cv::Mat free = segmentation_input(grid, options).labelled.cells == kFree;
  EXPECT_EQ(cv::countNonZero(free & (s.labels == 0)), 0);
  EXPECT_EQ(cv::countNonZero(~free & (s.labels != 0)), 0);
}

}  // namespace topocut::test
