#include "topocut/map/rasterize.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"

namespace topocut {
namespace {

TEST(Rasterize, SharedCutThroughCellCentresIsClaimedOnce) {
  // A 5 x 3 block of cells (grid x 0..4, y 0..2) split by the line x = 2 through cell centres.
  const PolygonWithHoles left{{{-0.5, -0.5}, {2, -0.5}, {2, 2.5}, {-0.5, 2.5}}, {}};
  const PolygonWithHoles right{{{2, -0.5}, {4.5, -0.5}, {4.5, 2.5}, {2, 2.5}}, {}};
  const cv::Mat labels = rasterize_polygons({left, right}, cv::Size(5, 3));
  EXPECT_EQ(cv::countNonZero(labels == 1), 6);  // columns 0, 1
  EXPECT_EQ(cv::countNonZero(labels == 2), 9);  // columns 2, 3, 4: centres on the cut go right
  // The order of the pieces does not change who owns the cut cells.
  const cv::Mat swapped = rasterize_polygons({right, left}, cv::Size(5, 3));
  EXPECT_EQ(cv::countNonZero(swapped == 1), 9);
}

TEST(Rasterize, DiagonalCutSplitsWithoutGapsOrOverlaps) {
  // Square cells 0..5, cut from (-0.5, -0.5) to (5.5, 5.5): centres on the diagonal lie on the cut.
  const PolygonWithHoles below{{{-0.5, -0.5}, {5.5, -0.5}, {5.5, 5.5}}, {}};
  const PolygonWithHoles above{{{-0.5, -0.5}, {5.5, 5.5}, {-0.5, 5.5}}, {}};
  const cv::Mat labels = rasterize_polygons({below, above}, cv::Size(6, 6));
  EXPECT_EQ(cv::countNonZero(labels == 0), 0);
  // 15 cells strictly below the diagonal, 15 strictly above, 6 on it go to the piece on the right.
  EXPECT_EQ(cv::countNonZero(labels == 1), 21);
  EXPECT_EQ(cv::countNonZero(labels == 2), 15);
}

TEST(Rasterize, HolesAndKeyholeRingsStayEmpty) {
  // 7x7 cells with a 3x3 hole in the middle (cells 2..4).
  const Ring outer{{-0.5, -0.5}, {6.5, -0.5}, {6.5, 6.5}, {-0.5, 6.5}};
  const Ring hole{{1.5, 1.5}, {1.5, 4.5}, {4.5, 4.5}, {4.5, 1.5}};
  const cv::Mat with_hole = rasterize_polygons({{outer, {hole}}}, cv::Size(7, 7));
  EXPECT_EQ(cv::countNonZero(with_hole), 40);
  EXPECT_EQ(with_hole.at<int>(3, 3), 0);
  // The same region as one keyhole ring: out along y = -0.5 ... in through the slit x = 1.5.
  const Ring keyhole{{-0.5, -0.5}, {1.5, -0.5}, {1.5, 1.5}, {1.5, 4.5}, {4.5, 4.5}, {4.5, 1.5}, {1.5, 1.5},
                     {1.5, -0.5}, {6.5, -0.5}, {6.5, 6.5}, {-0.5, 6.5}};
  const cv::Mat slit = rasterize_polygons({{keyhole, {}}}, cv::Size(7, 7));
  EXPECT_EQ(cv::countNonZero(slit != with_hole), 0);
}

TEST(Rasterize, PolygonsOutsideTheImageAreClipped) {
  const PolygonWithHoles big{{{-10, -10}, {10, -10}, {10, 10}, {-10, 10}}, {}};
  EXPECT_EQ(cv::countNonZero(rasterize_polygons({big}, cv::Size(4, 3))), 12);
  EXPECT_THROW(rasterize_polygons({big}, cv::Size(0, 3)), Error);
  const PolygonWithHoles bad{{{0, 0}, {std::nan(""), 1}, {1, 1}}, {}};
  EXPECT_THROW(rasterize_polygons({bad}, cv::Size(4, 3)), Error);
}

// Rooms dropped from a list keep the spans they had: kept_spans() of the whole list's spans is
// polygon_spans() of the rooms left, in their new numbering (the open rooms' row drops rooms and the
// labelling reads the rest).
TEST(Rasterize, KeptSpansAreThoseOfTheKeptPolygons) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const cv::Size size(60, 40);
  for (int round = 0; round < 30; ++round) {
    std::vector<PolygonWithHoles> all, kept;
    std::vector<int> new_index;
    for (int k = 0; k < 1 + round % 7; ++k) {
      const double x = unit(random) * 70.0 - 5.0, y = unit(random) * 50.0 - 5.0, s = 1.0 + unit(random) * 20.0;
      all.push_back({{{x, y}, {x + s, y + s * 0.3}, {x + s * 0.6, y + s}}, {}});
      const bool keep = unit(random) < 0.6;
      new_index.push_back(keep ? static_cast<int>(kept.size()) : -1);
      if (keep) kept.push_back(all.back());
    }
    const std::vector<CellSpan> expected = polygon_spans(kept, size);
    const std::vector<CellSpan> got = kept_spans(polygon_spans(all, size), new_index);
    ASSERT_EQ(got.size(), expected.size()) << "round " << round;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].row, expected[i].row);
      EXPECT_EQ(got[i].first, expected[i].first);
      EXPECT_EQ(got[i].end, expected[i].end);
      EXPECT_EQ(got[i].index, expected[i].index);
    }
  }
  EXPECT_THROW(kept_spans({{0, 0, 1, 3}}, {0, 1}), Error);  // polygon 3 is not listed
}

TEST(FillLabels, EveryFreeCellLabelledNoObstacleLabelled) {
  // Two rooms separated by a wall with a door; label only a seed in each, let the fill do the rest.
  cv::Mat free(10, 21, CV_8UC1, cv::Scalar(255));
  free.col(10).setTo(0);
  free.at<unsigned char>(5, 10) = 255;  // door
  cv::Mat labels = cv::Mat::zeros(free.size(), CV_32SC1);
  labels.at<int>(0, 0) = 1;
  labels.at<int>(0, 20) = 2;
  labels.at<int>(3, 10) = 7;  // a label on an obstacle cell must go
  fill_free_space_labels(labels, free);
  EXPECT_EQ(cv::countNonZero((labels > 0) != (free > 0)), 0);
  EXPECT_EQ(cv::countNonZero(labels == 7), 0);
  EXPECT_EQ(labels.at<int>(9, 9), 1);
  EXPECT_EQ(labels.at<int>(9, 11), 2);
}

TEST(FillLabels, LabelsFollowFreeSpaceNotStraightLines) {
  // A pocket next to room 1 but reachable only from room 2 (around the end of a wall).
  cv::Mat free(12, 12, CV_8UC1, cv::Scalar(255));
  free.col(5).setTo(0);
  free.row(6).setTo(0);
  free(cv::Rect(6, 7, 6, 5)).setTo(255);
  free.at<unsigned char>(6, 11) = 255;  // pocket (rows 7.., cols 6..) joins room 2 (top right) at column 11
  cv::Mat labels = cv::Mat::zeros(free.size(), CV_32SC1);
  labels(cv::Rect(0, 0, 5, 12)).setTo(1);  // room 1: left, all rows
  labels.at<int>(0, 11) = 2;               // room 2 seed: top right
  labels.setTo(0, free == 0);
  fill_free_space_labels(labels, free);
  EXPECT_EQ(labels.at<int>(9, 6), 2);  // one wall away from room 1, but its free-space path leads to 2
}

TEST(FillLabels, CutOffSpecksTakeTheNearestLabel) {
  cv::Mat free = cv::Mat::zeros(5, 12, CV_8UC1);
  free(cv::Rect(0, 0, 3, 5)).setTo(255);
  free(cv::Rect(9, 0, 3, 5)).setTo(255);
  free.at<unsigned char>(2, 4) = 255;  // speck near room 1
  free.at<unsigned char>(2, 7) = 255;  // speck near room 2
  cv::Mat labels = cv::Mat::zeros(free.size(), CV_32SC1);
  labels(cv::Rect(0, 0, 3, 5)).setTo(1);
  labels(cv::Rect(9, 0, 3, 5)).setTo(2);
  fill_free_space_labels(labels, free);
  EXPECT_EQ(labels.at<int>(2, 4), 1);
  EXPECT_EQ(labels.at<int>(2, 7), 2);
  EXPECT_EQ(labels.at<int>(2, 5), 0);
}

TEST(FillLabels, FarSpecksTakeTheNearestLabelInAStraightLine) {
  // Labels at the two ends of a long strip of obstacles; specks 30 and 60 cells from the left end.
  cv::Mat free = cv::Mat::zeros(3, 101, CV_8UC1);
  free.col(0).setTo(255);
  free.col(100).setTo(255);
  free.at<unsigned char>(1, 30) = 255;
  free.at<unsigned char>(1, 60) = 255;
  cv::Mat labels = cv::Mat::zeros(free.size(), CV_32SC1);
  labels.col(0).setTo(1);
  labels.col(100).setTo(2);
  std::vector<LabelChange> changes;
  fill_free_space_labels(labels, free, false, &changes);
  EXPECT_EQ(labels.at<int>(1, 30), 1);
  EXPECT_EQ(labels.at<int>(1, 60), 2);
  EXPECT_EQ(changes.size(), 2u);
  EXPECT_EQ(cv::countNonZero(labels), 3 + 3 + 2);
}


// Rooms 1 (columns 0..9) and 2 (columns 190..199) and one-pixel free specks on a 4-cell lattice
// between them: far more specks than the per-speck windows can afford, so one transform of the
// whole map serves them. Reference: the room whose nearest cell is nearer in a straight line
// (specks within 4 cells of the middle are left out, where the transform's approximation could tie).
TEST(FillLabels, ManySpecksTakeTheNearerRoomLikeABruteForceReference) {
  const int h = 200, w = 200;
  cv::Mat free = cv::Mat::zeros(h, w, CV_8UC1);
  free(cv::Rect(0, 0, 10, h)).setTo(255);
  free(cv::Rect(190, 0, 10, h)).setTo(255);
  for (int r = 1; r < h; r += 4)
    for (int c = 13; c < 187; c += 4) free.at<unsigned char>(r, c) = 255;
  cv::Mat labels = cv::Mat::zeros(free.size(), CV_32SC1);
  labels(cv::Rect(0, 0, 10, h)).setTo(1);
  labels(cv::Rect(190, 0, 10, h)).setTo(2);
  const cv::Mat before = labels.clone();
  std::vector<LabelChange> changes;
  fill_free_space_labels(labels, free, false, &changes);
  int checked = 0;
  for (int r = 1; r < h; r += 4) {
    for (int c = 13; c < 187; c += 4) {
      const int to_1 = c - 9, to_2 = 190 - c;
      ASSERT_GT(labels.at<int>(r, c), 0) << r << "," << c;
      if (std::abs(to_1 - to_2) <= 8) continue;
      EXPECT_EQ(labels.at<int>(r, c), to_1 < to_2 ? 1 : 2) << r << "," << c;
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000);
  EXPECT_EQ(static_cast<int>(changes.size()), cv::countNonZero(free) - cv::countNonZero(before));
  // The rooms keep their labels; no obstacle is labelled.
  EXPECT_EQ(cv::countNonZero(labels(cv::Rect(0, 0, 10, h)) != 1), 0);
  EXPECT_EQ(cv::countNonZero((labels != 0) & (free == 0)), 0);

  // A single speck far from both rooms, solved in its own window, gets what it got among many.
  cv::Mat one_free = cv::Mat::zeros(h, w, CV_8UC1);
  one_free(cv::Rect(0, 0, 10, h)).setTo(255);
  one_free(cv::Rect(190, 0, 10, h)).setTo(255);
  one_free.at<unsigned char>(101, 61) = 255;
  cv::Mat one = before.clone();
  fill_free_space_labels(one, one_free);
  EXPECT_EQ(one.at<int>(101, 61), labels.at<int>(101, 61));
}

// The nearest label of a speck as a search in square rings around it finds it (rings of 1 to 24
// cells, each row by row and column by column, a label replacing the best only when strictly
// nearer): the test's own definition, kept apart from the library's.
int ring_search_label(const cv::Mat& labels, int r, int c) {
  long best = std::numeric_limits<long>::max();
  int label = 0;
  for (int k = 1; k <= 24 && static_cast<long>(k - 1) * (k - 1) < best; ++k)
    for (int y = r - k; y <= r + k; ++y)
      for (int x = c - k; x <= c + k; ++x) {
        if (std::max(std::abs(y - r), std::abs(x - c)) != k || y < 0 || x < 0 || y >= labels.rows || x >= labels.cols) continue;
        const int l = labels.at<int>(y, x);
        const long d = static_cast<long>(y - r) * (y - r) + static_cast<long>(x - c) * (x - c);
        if (l > 0 && d < best) {
          best = d;
          label = l;
        }
      }
  return label;
}

// Labelled cells on even rows and columns, specks on odd ones (never beside a labelled cell, so
// only the straight-line search reaches them), at random: many specks are equally near two labels.
TEST(FillLabels, SpecksTakeTheNearestLabelFirstInRingOrder) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double density : {0.003, 0.02, 0.1}) {
    const int h = 90, w = 130;
    cv::Mat free = cv::Mat::zeros(h, w, CV_8UC1);
    cv::Mat labels = cv::Mat::zeros(h, w, CV_32SC1);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) {
        if (r % 2 == 0 && c % 2 == 0 && unit(random) < density) {
          free.at<unsigned char>(r, c) = 255;
          labels.at<int>(r, c) = 1 + static_cast<int>(unit(random) * 5);
        } else if (r % 2 == 1 && c % 2 == 1 && unit(random) < 0.3) {
          free.at<unsigned char>(r, c) = 255;
        }
      }
    const cv::Mat before = labels.clone();
    fill_free_space_labels(labels, free);
    int checked = 0;
    for (int r = 1; r < h; r += 2)
      for (int c = 1; c < w; c += 2) {
        if (!free.at<unsigned char>(r, c)) continue;
        const int expected = ring_search_label(before, r, c);
        if (expected == 0) continue;  // no label within the rings: a window's transform settles it
        EXPECT_EQ(labels.at<int>(r, c), expected) << "density " << density << " at " << r << "," << c;
        ++checked;
      }
    EXPECT_GT(checked, 200) << density;
  }
}

// The reference for specks beyond the ring search: the label and distance one distance transform
// of the whole map (OpenCV's) gives every cell.
struct WholeMapNearest {
  cv::Mat label, distance;  // CV_32SC1, CV_32FC1
};

WholeMapNearest whole_map_nearest(const cv::Mat& labels) {
  WholeMapNearest out;
  cv::Mat nearest;
  cv::distanceTransform(labels <= 0, out.distance, nearest, cv::DIST_L2, 5, cv::DIST_LABEL_PIXEL);
  std::vector<int> label_of(labels.total() + 1, 0);
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      if (labels.at<int>(r, c) > 0) label_of[static_cast<std::size_t>(nearest.at<int>(r, c))] = labels.at<int>(r, c);
  out.label.create(labels.size(), CV_32SC1);
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c) out.label.at<int>(r, c) = label_of[static_cast<std::size_t>(nearest.at<int>(r, c))];
  return out;
}

// Many specks more than 24 cells from every label (beyond the ring search), spread so that a window
// each would cost more than the map: each takes the label that one distance transform of the whole
// map gives it (OpenCV's, computed here), whatever windows the library solves them in. Labels on even
// cells make many specks equally near two labels; the labels keep to part of the map, so that some
// specks lie farther than the first windows reach.
TEST(FillLabels, SpreadSpecksTakeWhatTheWholeMapTransformGives) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double farthest = 0.0;
  for (int round = 0; round < 6; ++round) {
    const int h = 240 + 40 * round, w = 400;
    const int labelled_width = 120 + 40 * round;
    cv::Mat free = cv::Mat::zeros(h, w, CV_8UC1);
    cv::Mat labels = cv::Mat::zeros(h, w, CV_32SC1);
    for (int k = 0; k < 30 + 10 * round; ++k) {
      const int r = 2 * static_cast<int>(unit(random) * (h / 2)), c = 2 * static_cast<int>(unit(random) * (labelled_width / 2));
      const cv::Rect block(c, r, 1 + 2 * (k % 3), 1 + 2 * (k % 2));
      labels(block & cv::Rect(0, 0, w, h)).setTo(1 + k % 4);
      free(block & cv::Rect(0, 0, w, h)).setTo(255);
    }
    const cv::Mat before = labels.clone();
    std::vector<cv::Point> specks;
    for (int k = 0; k < 400; ++k) {
      const cv::Point p(static_cast<int>(unit(random) * w), static_cast<int>(unit(random) * h));
      const cv::Rect near = cv::Rect(p.x - 25, p.y - 25, 51, 51) & cv::Rect(0, 0, w - 1, h);  // room for a pair
      if (cv::countNonZero(before(near)) > 0 || free.at<unsigned char>(p) != 0) continue;
      free.at<unsigned char>(p) = 255;
      specks.push_back(p);
      if (k % 5 == 0) {  // a blob of two cells now and then
        free.at<unsigned char>(p + cv::Point(1, 0)) = 255;
        specks.push_back(p + cv::Point(1, 0));
      }
    }
    const WholeMapNearest reference = whole_map_nearest(before);
    fill_free_space_labels(labels, free);
    for (const cv::Point& p : specks) {
      EXPECT_EQ(labels.at<int>(p), reference.label.at<int>(p)) << "round " << round << " at " << p;
      farthest = std::max(farthest, static_cast<double>(reference.distance.at<float>(p)));
    }
    EXPECT_GT(specks.size(), 100u) << "round " << round;
  }
  EXPECT_GT(farthest, 130.0);  // beyond twice the first windows' margin too
}

// Clusters of specks whose first window (64 cells around them) holds a label that is not their
// nearest: one diagonally 60 + 60 cells off, inside the window, while the nearest lies 80 cells
// straight up, beyond it. The round after takes windows grown by the distance the first found, and
// each speck still takes what one transform of the whole map gives it (OpenCV's, computed here).
TEST(FillLabels, SpecksWhoseFirstWindowMissesTheNearestLabelTakeTheWholeMapsAnswer) {
  const int size = 1300, spacing = 300;
  cv::Mat free = cv::Mat::zeros(size, size, CV_8UC1);
  cv::Mat labels = cv::Mat::zeros(size, size, CV_32SC1);
  std::vector<cv::Point> specks;
  std::vector<int> above_label;  // by speck: the label straight up from its cluster
  int station = 0;
  for (int y = 150; y + 150 < size; y += spacing)
    for (int x = 150; x + 150 < size; x += spacing, ++station) {
      const cv::Point diagonal(x + 60, y + 60), above(x, y - 80);
      labels.at<int>(diagonal) = 1 + station % 3;
      labels.at<int>(above) = 4 + station % 2;
      free.at<unsigned char>(diagonal) = free.at<unsigned char>(above) = 255;
      for (int dy = -12; dy <= 12; dy += 3)  // specks apart, each a blob of its own
        for (int dx = -12; dx <= 12; dx += 3) {
          free.at<unsigned char>(y + dy, x + dx) = 255;
          specks.emplace_back(x + dx, y + dy);
          above_label.push_back(4 + station % 2);
        }
    }
  const WholeMapNearest reference = whole_map_nearest(labels);
  fill_free_space_labels(labels, free);
  std::size_t beyond_first_window = 0;
  for (std::size_t i = 0; i < specks.size(); ++i) {
    EXPECT_EQ(labels.at<int>(specks[i]), reference.label.at<int>(specks[i])) << "at " << specks[i];
    beyond_first_window += labels.at<int>(specks[i]) == above_label[i];
  }
  EXPECT_GT(beyond_first_window, specks.size() / 4);
  EXPECT_LT(beyond_first_window, specks.size());  // and some take the diagonal one
}

TEST(FillLabels, SpecksWithoutAnyLabelStayUnlabelled) {
  cv::Mat free = cv::Mat::zeros(120, 120, CV_8UC1);
  for (int r = 1; r < 120; r += 3)
    for (int c = 1; c < 120; c += 3) free.at<unsigned char>(r, c) = 255;
  cv::Mat labels = cv::Mat::zeros(free.size(), CV_32SC1);
  fill_free_space_labels(labels, free);
  EXPECT_EQ(cv::countNonZero(labels), 0);
}

}  // namespace
}  // namespace topocut
