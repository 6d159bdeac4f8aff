// Label runs: the runs of a label image give its labels back cell for cell, and the runs of pieces
// made without an image are those of rasterize_polygons()'s image, overlaps included (the earlier
// piece keeps a cell).
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/map/label_runs.h"
#include "topocut/map/rasterize.h"

namespace topocut {
namespace {

cv::Mat image_of(const LabelRuns& runs) {
  cv::Mat image = cv::Mat::zeros(runs.size(), CV_32SC1);
  for (int r = 0; r < image.rows; ++r)
    for (const LabelRun& run : runs.row(r))
      for (int c = run.begin; c < run.end; ++c) image.at<int>(r, c) = run.label;
  return image;
}

// Every run is maximal, lies in its row and the label index lists exactly the runs of each label.
void expect_well_formed(const LabelRuns& runs) {
  std::size_t listed = 0;
  for (const int label : runs.labels()) {
    int previous_row = -1;
    for (const std::size_t i : runs.runs_of(label)) {
      EXPECT_EQ(runs.all()[i].label, label);
      EXPECT_GE(runs.row_of(i), previous_row);
      previous_row = runs.row_of(i);
      ++listed;
    }
  }
  EXPECT_EQ(listed, runs.all().size());
  for (int r = 0; r < runs.size().height; ++r) {
    const auto row = runs.row(r);
    for (std::size_t k = 0; k < row.size(); ++k) {
      EXPECT_LT(row[k].begin, row[k].end);
      EXPECT_GT(row[k].label, 0);
      if (k > 0) {
        EXPECT_TRUE(row[k].begin > row[k - 1].end || (row[k].begin == row[k - 1].end && row[k].label != row[k - 1].label));
      }
    }
  }
}

TEST(LabelRuns, RoundTripAndLookUp) {
  cv::RNG rng(5);
  for (int round = 0; round < 20; ++round) {
    cv::Mat labels = cv::Mat::zeros(rng.uniform(1, 60), rng.uniform(1, 90), CV_32SC1);
    for (int k = 0; k < 15; ++k)
      cv::rectangle(labels, cv::Rect(rng.uniform(-5, labels.cols), rng.uniform(-5, labels.rows), rng.uniform(1, 30), rng.uniform(1, 20)),
                    cv::Scalar(rng.uniform(-2, 9)), cv::FILLED);
    const LabelRuns runs = label_runs(labels);
    expect_well_formed(runs);
    cv::Mat positive = labels.clone();
    positive.setTo(0, labels < 0);
    EXPECT_EQ(cv::countNonZero(image_of(runs) != positive), 0);
    for (int k = 0; k < 50; ++k) {
      const int r = rng.uniform(0, labels.rows), c = rng.uniform(0, labels.cols);
      EXPECT_EQ(runs.at(r, c), positive.at<int>(r, c));
    }
    EXPECT_TRUE(runs.runs_of(1000).empty());
  }
}

Ring random_ring(cv::RNG& rng, double x, double y, double radius, int corners) {
  Ring ring;
  for (int k = 0; k < corners; ++k) {
    const double angle = 2.0 * CV_PI * k / corners, r = radius * rng.uniform(0.4, 1.0);
    ring.push_back({x + r * std::cos(angle), y + r * std::sin(angle)});
  }
  return ring;
}

TEST(LabelRuns, PiecesAreTheirRasterizedImage) {
  cv::RNG rng(6);
  for (int round = 0; round < 40; ++round) {
    const cv::Size size(rng.uniform(1, 80), rng.uniform(1, 60));
    std::vector<PolygonWithHoles> pieces;
    for (int k = 0; k < rng.uniform(1, 10); ++k) {
      PolygonWithHoles piece;
      const double x = rng.uniform(-10.0, size.width + 10.0), y = rng.uniform(-10.0, size.height + 10.0);
      const double radius = rng.uniform(0.5, 30.0);
      if (rng.uniform(0, 2) == 0) {
        // Corners on whole and half cells, as traced outlines and their cuts have them.
        const double w = std::round(radius) + 0.5, h = std::round(radius * rng.uniform(0.3, 1.5)) + 0.5;
        piece.outer = {{std::round(x), std::round(y)}, {std::round(x) + w, std::round(y)}, {std::round(x) + w, std::round(y) + h}, {std::round(x), std::round(y) + h}};
      } else {
        piece.outer = random_ring(rng, x, y, radius, rng.uniform(3, 12));
        if (radius > 8.0 && rng.uniform(0, 2) == 0) {
          Ring hole = random_ring(rng, x, y, radius / 3.0, 5);
          std::reverse(hole.begin(), hole.end());
          piece.holes.push_back(hole);
        }
      }
      pieces.push_back(piece);
    }
    const LabelRuns runs = polygon_label_runs(pieces, size);
    expect_well_formed(runs);
    EXPECT_EQ(cv::countNonZero(image_of(runs) != rasterize_polygons(pieces, size)), 0) << "round " << round;
    // From spans rasterized beforehand (the open rooms' stage reads the labelling's): the same runs.
    const LabelRuns from_spans = polygon_label_runs(polygon_spans(pieces, size), size);
    EXPECT_EQ(cv::countNonZero(image_of(from_spans) != image_of(runs)), 0) << "round " << round;
    EXPECT_EQ(from_spans.all().size(), runs.all().size()) << "round " << round;
  }
}

// run_end() against a cell-at-a-time reference, on runs of every length from every start, so that the
// eight-cell compares meet the rows' ends and unaligned starts.
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
      ASSERT_EQ(run_end(row.data(), begin, cols, row[static_cast<std::size_t>(begin)]), reference_run_end(row, begin))
          << "round " << round << " from " << begin;
  }
}

TEST(RunEnd, AWholeRowIsOneRun) {
  const std::vector<int> row(37, 4);
  EXPECT_EQ(run_end(row.data(), 0, 37, 4), 37);
  EXPECT_EQ(run_end(row.data(), 36, 37, 4), 37);
  EXPECT_EQ(run_end(row.data(), 0, 1, 4), 1);  // n bounds the run, not the data
}

}  // namespace
}  // namespace topocut
