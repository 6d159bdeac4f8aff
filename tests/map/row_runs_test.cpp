// Run-length masks: every operation gives, cell for cell, what OpenCV gives on the image (its
// morphology with the same structuring element and border, its connected components), on random
// masks whose widths straddle the 64-cell blocks of the scan and whose rows repeat in places.
#include <cmath>
#include <set>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "map/row_runs.h"

namespace topocut {
namespace {

cv::Mat image_of(const RowRuns& runs) {
  cv::Mat image(runs.height(), runs.width(), CV_8UC1);
  write_mask(runs, image, 255, 0);
  return image;
}

int differing(const cv::Mat& a, const cv::Mat& b) { return cv::countNonZero(a != b); }

// Blobs of every size, single cells, thin lines and a band of repeated rows (what maps drawn by hand
// have), as 0 / 255.
cv::Mat random_mask(cv::RNG& rng, int rows, int cols, int blobs) {
  cv::Mat mask = cv::Mat::zeros(rows, cols, CV_8UC1);
  for (int k = 0; k < blobs; ++k) {
    const cv::Point p(rng.uniform(0, cols), rng.uniform(0, rows));
    const int kind = rng.uniform(0, 4);
    const unsigned char value = rng.uniform(0, 5) == 0 ? 0 : 255;
    if (kind == 0) cv::circle(mask, p, rng.uniform(1, 25), cv::Scalar(value), cv::FILLED);
    if (kind == 1) cv::rectangle(mask, cv::Rect(p, cv::Size(rng.uniform(1, 60), rng.uniform(1, 40))), cv::Scalar(value), cv::FILLED);
    if (kind == 2) cv::line(mask, p, p + cv::Point(rng.uniform(-40, 41), rng.uniform(-40, 41)), cv::Scalar(value));
    if (kind == 3) mask.at<unsigned char>(p) = value;
  }
  if (rows > 40) mask.row(rows / 3).copyTo(mask.rowRange(rows / 3, rows / 3 + 30).row(rng.uniform(1, 30)));
  for (int y = rows / 2; y < std::min(rows, rows / 2 + 25); ++y) mask.row(rows / 2).copyTo(mask.row(y));
  return mask;
}

struct Case {
  int rows, cols, blobs;
};

const Case kCases[] = {{1, 1, 1}, {1, 130, 20}, {90, 1, 10}, {70, 63, 30}, {70, 64, 30}, {80, 65, 40}, {120, 129, 60}, {150, 200, 120}};

TEST(RowRuns, ScanAndWriteRoundTrip) {
  cv::RNG rng(1);
  for (const Case& c : kCases) {
    cv::Mat mask = random_mask(rng, c.rows, c.cols, c.blobs);
    // Any nonzero value is set; runs_of_value picks one value among others.
    mask.setTo(7, (mask != 0) & random_mask(rng, c.rows, c.cols, c.blobs));
    EXPECT_EQ(differing(image_of(runs_of(mask)), (mask != 0)), 0) << c.rows << " x " << c.cols;
    EXPECT_EQ(differing(image_of(runs_of_value(mask, 7)), mask == 7), 0);
    EXPECT_EQ(differing(image_of(runs_of_value(mask, 0)), mask == 0), 0);
    EXPECT_EQ(cell_count(runs_of(mask)), cv::countNonZero(mask));
  }
}

TEST(RowRuns, SetOperationsAreTheBitwiseOnes) {
  cv::RNG rng(2);
  for (const Case& c : kCases) {
    const cv::Mat a = random_mask(rng, c.rows, c.cols, c.blobs), b = random_mask(rng, c.rows, c.cols, c.blobs);
    const RowRuns ra = runs_of(a), rb = runs_of(b);
    EXPECT_EQ(differing(image_of(unite(ra, rb)), a | b), 0);
    EXPECT_EQ(differing(image_of(intersect(ra, rb)), a & b), 0);
    EXPECT_EQ(differing(image_of(subtract(ra, rb)), a & ~b), 0);
    EXPECT_EQ(differing(image_of(complement(ra)), ~a), 0);
    // Canonical: the union of touching runs is one run, as a fresh scan of the image gives it.
    EXPECT_EQ(unite(ra, rb).all().size(), runs_of(a | b).all().size());
  }
}

TEST(RowRuns, DiscIsOpenCVsEllipse) {
  for (int r = 1; r <= 120; ++r) {
    const cv::Mat element = cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1});
    const std::vector<int> half = disc_half_widths(r);
    cv::Mat drawn = cv::Mat::zeros(element.size(), CV_8UC1);
    for (int dy = -r; dy <= r; ++dy) {
      const int a = half[static_cast<std::size_t>(std::abs(dy))];
      drawn.row(r + dy).colRange(r - a, r + a + 1).setTo(1);
    }
    ASSERT_EQ(differing(drawn, element), 0) << "r = " << r;
  }
}

TEST(RowRuns, OpeningIsOpenCVsPixelForPixel) {
  cv::RNG rng(3);
  for (const int r : {1, 2, 3, 5, 6, 9, 12, 20, 40}) {
    const cv::Mat element = cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1});
    const std::vector<int> disc = disc_half_widths(r);
    for (const Case& c : kCases) {
      const cv::Mat mask = random_mask(rng, c.rows, c.cols, c.blobs);
      cv::Mat eroded, dilated, opened;
      cv::erode(mask, eroded, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
      cv::dilate(mask, dilated, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
      cv::morphologyEx(mask, opened, cv::MORPH_OPEN, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
      const RowRuns runs = runs_of(mask);
      EXPECT_EQ(differing(image_of(erode(runs, disc)), eroded), 0) << "r " << r << ", " << c.rows << " x " << c.cols;
      EXPECT_EQ(differing(image_of(dilate(runs, disc)), dilated), 0) << "r " << r << ", " << c.rows << " x " << c.cols;
      EXPECT_EQ(differing(image_of(dilate(erode(runs, disc), disc)), opened), 0) << "r " << r;
    }
  }
}

// A room with fans of laser rays out of its doors (what exploration maps have at the frontier): rows
// of many short runs beside one long run, rays of one or two cells that every disc removes.
cv::Mat ray_fans(cv::RNG& rng, int rows, int cols) {
  cv::Mat mask = cv::Mat::zeros(rows, cols, CV_8UC1);
  cv::rectangle(mask, cv::Rect(cols / 4, rows / 4, cols / 2, rows / 2), cv::Scalar(255), cv::FILLED);
  for (int fan = 0; fan < 4; ++fan) {
    const cv::Point from(rng.uniform(cols / 4, 3 * cols / 4), rng.uniform(rows / 4, 3 * rows / 4));
    for (int ray = 0; ray < 40; ++ray) {
      const double angle = rng.uniform(0.0, 6.2832);
      const cv::Point to = from + cv::Point(static_cast<int>(cols * std::cos(angle)), static_cast<int>(rows * std::sin(angle)));
      cv::line(mask, from, to, cv::Scalar(255), rng.uniform(1, 3));
    }
  }
  return mask;
}

TEST(RowRuns, OpeningOfRayFansIsOpenCVs) {
  cv::RNG rng(7);
  for (const int r : {1, 3, 6, 9}) {
    const cv::Mat element = cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1});
    const std::vector<int> disc = disc_half_widths(r);
    for (const cv::Size size : {cv::Size(130, 90), cv::Size(300, 200)}) {
      const cv::Mat mask = ray_fans(rng, size.height, size.width);
      cv::Mat eroded, dilated, opened;
      cv::erode(mask, eroded, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
      cv::dilate(mask, dilated, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
      cv::dilate(eroded, opened, element, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
      const RowRuns runs = runs_of(mask);
      ASSERT_GT(runs.all().size(), static_cast<std::size_t>(4 * size.height));  // rows of many runs
      EXPECT_EQ(differing(image_of(erode(runs, disc)), eroded), 0) << "r " << r << ", " << size;
      EXPECT_EQ(differing(image_of(dilate(runs, disc)), dilated), 0) << "r " << r << ", " << size;
      EXPECT_EQ(differing(image_of(dilate(erode(runs, disc), disc)), opened), 0) << "r " << r << ", " << size;
      // The thick part grown back along the rays (the cleaning's margin).
      cv::Mat grown = eroded.clone();
      for (int step = 0; step < 3; ++step) {
        cv::dilate(grown, grown, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
        grown &= mask;
      }
      EXPECT_EQ(differing(image_of(grow_within(erode(runs, disc), runs, 3)), grown), 0) << "r " << r << ", " << size;
    }
  }
}

TEST(RowRuns, SquareClosingKeepsTheImagesEdge) {
  cv::RNG rng(4);
  for (const int n : {1, 2, 4, 10, 35, 500}) {
    const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {2 * n + 1, 2 * n + 1});
    for (const Case& c : kCases) {
      const cv::Mat mask = random_mask(rng, c.rows, c.cols, c.blobs);
      cv::Mat closed;
      cv::dilate(mask, closed, square, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
      cv::erode(closed, closed, square, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(255));
      EXPECT_EQ(differing(image_of(close_square(runs_of(mask), n)), closed), 0) << "n " << n << ", " << c.rows << " x " << c.cols;
    }
  }
}

TEST(RowRuns, GrowthWithinIsRepeatedDilationCutBack) {
  cv::RNG rng(5);
  const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
  for (const Case& c : kCases) {
    const cv::Mat within = random_mask(rng, c.rows, c.cols, c.blobs);
    const cv::Mat seed = within & random_mask(rng, c.rows, c.cols, c.blobs / 3 + 1);
    cv::Mat grown = seed.clone();
    for (int step = 1; step <= 4; ++step) {
      cv::dilate(grown, grown, square);
      grown &= within;
      EXPECT_EQ(differing(image_of(grow_within(runs_of(seed), runs_of(within), step)), grown), 0) << "step " << step;
    }
  }
}

TEST(RowRuns, ComponentsAreOpenCVs) {
  cv::RNG rng(6);
  for (const bool eight : {true, false}) {
    for (const Case& c : kCases) {
      const cv::Mat mask = random_mask(rng, c.rows, c.cols, c.blobs);
      cv::Mat labels;
      const int n = cv::connectedComponents(mask, labels, eight ? 8 : 4, CV_32S);
      const RowRuns runs = runs_of(mask);
      int count = 0;
      const std::vector<int> component = run_components(runs, eight, count);
      EXPECT_EQ(count, n - 1);
      // The same partition: each component's cells carry one OpenCV label, a different one each
      // (OpenCV numbers 2 x 2 blocks in raster order, not single cells).
      std::vector<int> label_of(static_cast<std::size_t>(count), -1);
      std::set<int> used;
      bool same = true;
      std::size_t i = 0;
      for (int y = 0; y < runs.height(); ++y) {
        for (const CellRun& run : runs.row(y)) {
          int& label = label_of[static_cast<std::size_t>(component[i++])];
          for (int x = run.begin; x < run.end; ++x) {
            const int l = labels.at<int>(y, x);
            if (label < 0 && used.insert(l).second) label = l;
            same = same && l == label;
          }
        }
      }
      EXPECT_TRUE(same) << (eight ? 8 : 4) << "-connected, " << c.rows << " x " << c.cols;
      // Selecting every other component's runs keeps exactly their cells.
      std::vector<unsigned char> keep(component.size());
      for (std::size_t k = 0; k < keep.size(); ++k) keep[k] = component[k] % 2 == 0;
      cv::Mat kept = cv::Mat::zeros(mask.size(), CV_8UC1);
      for (int k = 0; k < count; k += 2) kept.setTo(255, labels == label_of[static_cast<std::size_t>(k)]);
      EXPECT_EQ(differing(image_of(select_runs(runs, keep)), kept), 0);
    }
  }
}

}  // namespace
}  // namespace topocut
