#include "topocut/labeling/sparse_labeling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "topocut/core/error.h"

namespace topocut {
namespace {

constexpr double kCell = 0.05;

// Points on the x axis: an anchor at the origin (the bounding box corner, so cell i spans
// [i·cell, (i+1)·cell)) and one point at the centre of each listed cell.
std::vector<Point2> points_in_cells(const std::vector<std::pair<int, int>>& cells) {
  std::vector<Point2> points{{0.0, 0.0}};
  for (const auto& [cx, cy] : cells) points.push_back({(cx + 0.5) * kCell, (cy + 0.5) * kCell});
  return points;
}

LabelingOptions options_with(int dilation, StructuringElement element, int connectivity,
                             LabelingMethod method = LabelingMethod::kSparse) {
  LabelingOptions options;
  options.cell_size = kCell;
  options.dilation = dilation;
  options.element = element;
  options.connectivity = connectivity;
  options.method = method;
  return options;
}

// A run of points along x from x0 to x1 every centimetre.
void add_run(std::vector<Point2>& points, double x0, double x1, double y = 0.0) {
  for (double x = x0; x <= x1 + 1e-9; x += 0.01) points.push_back({x, y});
}

TEST(SparseLabeling, GapWiderThanTheDilationSeparatesNarrowerMerges) {
  for (LabelingMethod method : {LabelingMethod::kSparse, LabelingMethod::kRaster}) {
    // One dilation with a cross grows each cell by one, so at most 2 empty cells between two
    // occupied cells are bridged (2k = 2 cells = 10 cm).
    std::vector<Point2> wide;  // 0.50 m gap between the runs: 9 empty cells
    add_run(wide, 0.0, 1.0);
    add_run(wide, 1.5, 2.5);
    const Labeling separate = label_points(wide, options_with(1, StructuringElement::kCross, 8, method));
    ASSERT_EQ(separate.segments.size(), 2u);
    EXPECT_EQ(separate.labels.front(), 0);
    EXPECT_EQ(separate.labels.back(), 1);

    std::vector<Point2> narrow;  // a 6 cm gap: at most 2 empty cells
    add_run(narrow, 0.0, 1.0);
    add_run(narrow, 1.06, 2.0);
    const Labeling merged = label_points(narrow, options_with(1, StructuringElement::kCross, 8, method));
    EXPECT_EQ(merged.segments.size(), 1u);
  }
}

TEST(SparseLabeling, BridgedGapGrowsWithTheDilation) {
  // Occupied cells 0 and g along x: joined exactly when g - 1 empty cells <= 2k.
  for (int k = 0; k <= 3; ++k) {
    for (int g = 1; g <= 2 * k + 4; ++g) {
      const auto points = points_in_cells({{0, 0}, {g, 0}});
      for (LabelingMethod method : {LabelingMethod::kSparse, LabelingMethod::kRaster}) {
        for (auto element : {StructuringElement::kCross, StructuringElement::kSquare}) {
          for (int connectivity : {4, 8}) {
            const Labeling l = label_points(points, options_with(k, element, connectivity, method));
            EXPECT_EQ(l.segments.size(), g - 1 <= 2 * k ? 1u : 2u)
                << "k=" << k << " g=" << g << " conn=" << connectivity;
          }
        }
      }
    }
  }
}

TEST(SparseLabeling, ElementAndConnectivityDecideDiagonalNeighbours) {
  // Hand-checked with one dilation:
  // offset (2,2): cross footprints meet only diagonally ((1,0) and (2,1)) → 8 joins, 4 does not.
  // offset (3,2): cross footprints are 2 apart → never; squares touch side by side ((1,1),(2,1)).
  // offset (3,3): squares meet only diagonally ((1,1),(2,2)) → 8 joins, 4 does not.
  struct Case {
    int dx, dy;
    StructuringElement element;
    int connectivity;
    size_t segments;
  };
  const Case cases[] = {
      {2, 2, StructuringElement::kCross, 8, 1},  {2, 2, StructuringElement::kCross, 4, 2},
      {3, 2, StructuringElement::kCross, 8, 2},  {3, 2, StructuringElement::kSquare, 4, 1},
      {3, 3, StructuringElement::kSquare, 8, 1}, {3, 3, StructuringElement::kSquare, 4, 2},
      {4, 0, StructuringElement::kSquare, 8, 2}, {3, 0, StructuringElement::kCross, 4, 1},
  };
  for (const Case& c : cases) {
    // Shift the pair away from the anchor so the anchor does not take part.
    std::vector<Point2> points{{0.0, 0.0}, {(20.5) * kCell, 20.5 * kCell}, {(20.5 + c.dx) * kCell, (20.5 + c.dy) * kCell}};
    for (LabelingMethod method : {LabelingMethod::kSparse, LabelingMethod::kRaster}) {
      const Labeling l = label_points(points, options_with(1, c.element, c.connectivity, method));
      EXPECT_EQ(l.segments.size(), 1 + c.segments) << c.dx << "," << c.dy << " conn " << c.connectivity;
    }
  }
}

TEST(SparseLabeling, EveryFinitePointIsInExactlyOneSegment) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  std::vector<Point2> points;
  for (int i = 0; i < 500; ++i) points.push_back({coordinate(rng), coordinate(rng) * 0.2});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  points[17] = {nan, 1.0};
  points[300] = {1.0, std::numeric_limits<double>::infinity()};
  const std::vector<Point2> copy = points;
  const Labeling l = label_points(points, options_with(1, StructuringElement::kCross, 8));
  ASSERT_EQ(l.labels.size(), points.size());
  std::vector<int> seen(points.size(), 0);
  for (size_t s = 0; s < l.segments.size(); ++s) {
    ASSERT_FALSE(l.segments[s].empty());
    for (size_t j = 0; j < l.segments[s].size(); ++j) {
      const int i = l.segments[s][j];
      if (j > 0) {
        EXPECT_LT(l.segments[s][j - 1], i);
      }
      ++seen[static_cast<size_t>(i)];
      EXPECT_EQ(l.labels[static_cast<size_t>(i)], static_cast<int>(s));
    }
    if (s > 0) {
      EXPECT_LT(l.segments[s - 1].front(), l.segments[s].front());
    }
  }
  for (size_t i = 0; i < points.size(); ++i) {
    const bool finite = i != 17 && i != 300;
    EXPECT_EQ(seen[i], finite ? 1 : 0) << i;
    if (!finite) {
      EXPECT_EQ(l.labels[i], -1);
    }
  }
  // Points never move.
  for (size_t i = 0; i < points.size(); ++i) {
    if (i == 17) continue;
    EXPECT_EQ(points[i], copy[i]);
  }
}

TEST(SparseLabeling, SparseMethodReproducesTheRasterLabeling) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    // Clustered points with gaps of every size around the dilation reach.
    std::normal_distribution<double> jitter(0.0, 0.04 + 0.02 * (trial % 5));
    std::uniform_real_distribution<double> where(-2.0, 2.0);
    std::vector<Point2> points;
    for (int c = 0; c < 8; ++c) {
      const Point2 centre{where(rng), where(rng)};
      for (int i = 0; i < 30; ++i) points.push_back({centre.x + jitter(rng), centre.y + jitter(rng)});
    }
    std::shuffle(points.begin(), points.end(), rng);
    for (int k = 0; k <= 3; ++k) {
      for (auto element : {StructuringElement::kCross, StructuringElement::kSquare}) {
        for (int connectivity : {4, 8}) {
          const Labeling raster = label_points(points, options_with(k, element, connectivity, LabelingMethod::kRaster));
          const Labeling sparse = label_points(points, options_with(k, element, connectivity, LabelingMethod::kSparse));
          ASSERT_EQ(raster.labels, sparse.labels) << "trial " << trial << " k " << k << " conn " << connectivity;
        }
      }
    }
  }
}

TEST(SparseLabeling, CoincidentPointsAndEmptyInput) {
  const std::vector<Point2> same(5, Point2{3.0, -1.0});
  const Labeling l = label_points(same);
  ASSERT_EQ(l.segments.size(), 1u);
  EXPECT_EQ(l.segments[0].size(), 5u);

  const Labeling empty = label_points(std::vector<Point2>{});
  EXPECT_TRUE(empty.labels.empty());
  EXPECT_TRUE(empty.segments.empty());

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Labeling none = label_points(std::vector<Point2>{{nan, nan}});
  EXPECT_EQ(none.labels, std::vector<int>{-1});
  EXPECT_TRUE(none.segments.empty());
}

TEST(SparseLabeling, FarApartPointsStaySparse) {
  // 2 km apart at 5 cm: the box has 1.6e9 cells, which the raster method refuses and the sparse
  // method does not need.
  const std::vector<Point2> points{{0, 0}, {0.01, 0}, {2000, 2000}, {2000.01, 2000}};
  const Labeling l = label_points(points);
  ASSERT_EQ(l.segments.size(), 2u);
  EXPECT_EQ(l.labels, (std::vector<int>{0, 0, 1, 1}));
  LabelingOptions raster;
  raster.method = LabelingMethod::kRaster;
  EXPECT_THROW(label_points(points, raster), Error);
}

TEST(SparseLabeling, RejectsInvalidOptions) {
  const std::vector<Point2> points{{0, 0}};
  LabelingOptions bad;
  bad.cell_size = 0.0;
  EXPECT_THROW(label_points(points, bad), Error);
  bad = {};
  bad.cell_size = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(label_points(points, bad), Error);
  bad = {};
  bad.dilation = -1;
  EXPECT_THROW(label_points(points, bad), Error);
  bad = {};
  bad.connectivity = 6;
  EXPECT_THROW(label_points(points, bad), Error);
  const std::vector<Point2> huge{{0, 0}, {1e12, 0}};
  EXPECT_THROW(label_points(huge), Error);
}

}  // namespace
}  // namespace topocut

namespace topocut {
namespace {

TEST(SparseLabeling, ScanBeamsKeepTheirRows) {
  // Five beams: two on a near wall 1 m ahead, an invalid beam, two on a wall 3 m ahead.
  Scan scan;
  scan.angles = {-0.02, -0.01, 0.0, 0.01, 0.02};
  scan.ranges = {1.0, 1.0, std::numeric_limits<double>::quiet_NaN(), 3.0, 3.0};
  const Labeling l = label_scan(scan);
  EXPECT_EQ(l.labels, (std::vector<int>{0, 0, -1, 1, 1}));
  ASSERT_EQ(l.segments.size(), 2u);
  EXPECT_EQ(l.segments[1], (std::vector<int>{3, 4}));
  scan.ranges.pop_back();
  EXPECT_THROW(label_scan(scan), Error);
}

}  // namespace
}  // namespace topocut

namespace topocut {
namespace {

// Issue 28: the work of a labelling is bounded, not the size of its file. A large dilation puts
// every cell into one bucket, where each is compared with every other: counted first and refused.
TEST(SparseLabeling, WorkBeyondTheLimitIsRefusedBeforeItIsDone) {
  std::vector<Point2> points;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(0.0, 50.0);
  for (int i = 0; i < 100000; ++i) points.push_back({coordinate(random), coordinate(random)});
  LabelingOptions options;
  options.dilation = 1000;  // buckets of 2002 cells, 100 m a side: all 100,000 cells in one
  try {
    label_points(points, options);
    FAIL() << "labelled 5 * 10^9 cell pairs";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("pairs of cells, more than the limit"), std::string::npos) << e.what();
  }
  options.dilation = 1;  // the same points, small buckets: labelled
  EXPECT_EQ(label_points(points, options).labels.size(), points.size());
}

}  // namespace
}  // namespace topocut
