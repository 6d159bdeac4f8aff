// decompose() rejects malformed polygons with one clear Error and normalises what it accepts.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "decomposition/dude_test_shapes.h"
#include "decomposition/validate.h"
#include "topocut/core/error.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/decomposition/ring_intersections.h"

namespace topocut {
namespace {

PolygonWithHoles square(double size) { return {{{0, 0}, {size, 0}, {size, size}, {0, size}}, {}}; }

void expect_error(const PolygonWithHoles& polygon, const std::string& fragment, double tau = 1.0) {
  DecompositionOptions options;
  options.tau = tau;
  try {
    decompose(polygon, options);
    FAIL() << "expected an Error mentioning '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(DecomposeValidation, RejectsTooFewVertices) {
  expect_error({{{0, 0}, {1, 0}}, {}}, "fewer than 3");
  expect_error({{{0, 0}, {1, 0}, {1, 0}, {0, 0}}, {}}, "fewer than 3");
}

TEST(DecomposeValidation, RejectsNonFiniteCoordinates) {
  PolygonWithHoles p = square(10);
  p.outer[1].x = std::numeric_limits<double>::quiet_NaN();
  expect_error(p, "non-finite");
  p = square(10);
  p.outer[2].y = std::numeric_limits<double>::infinity();
  expect_error(p, "non-finite");
}

TEST(DecomposeValidation, RejectsSelfIntersection) {
  expect_error({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}, {}}, "intersects itself");  // bow tie
  expect_error({{{0, 0}, {10, 0}, {5, 0}, {5, 5}}, {}}, "intersects itself");    // folds back
}

TEST(DecomposeValidation, RejectsHolesOutsideOrTouching) {
  PolygonWithHoles p = square(10);
  p.holes.push_back({{20, 20}, {21, 20}, {21, 21}});
  expect_error(p, "not inside the outer ring");
  p = square(10);
  p.holes.push_back({{0, 5}, {3, 4}, {3, 6}});  // touches the outer ring at (0,5)
  expect_error(p, "intersect or touch");
  p = square(10);
  p.holes.push_back({{1, 1}, {9, 1}, {9, 9}, {1, 9}});
  p.holes.push_back({{4, 4}, {5, 4}, {5, 5}});
  expect_error(p, "inside hole 0");
}

TEST(DecomposeValidation, RejectsBadTau) {
  expect_error(square(10), "tau", 0.0);
  expect_error(square(10), "tau", -1.0);
  expect_error(square(10), "tau", std::numeric_limits<double>::quiet_NaN());
}

TEST(DecomposeValidation, NormalisesOrientationAndRepeats) {
  // Clockwise outer ring with a repeated closing vertex and a duplicate vertex.
  PolygonWithHoles p{{{0, 0}, {0, 10}, {0, 10}, {10, 10}, {10, 0}, {0, 0}}, {}};
  const Decomposition d = decompose(p, {});
  ASSERT_EQ(d.pieces.size(), 1u);
  const Ring expected{{0, 0}, {10, 0}, {10, 10}, {0, 10}};  // reversed, first vertex kept
  EXPECT_EQ(d.pieces[0].outer, expected);
}

// Many holes: the grid finds a hole inside another, a hole outside, and touching holes.
TEST(DecomposeValidation, ManyHoles) {
  PolygonWithHoles p = square(400);
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      const double x = 10 + 19.5 * i, y = 10 + 19.5 * j;
      p.holes.push_back({{x, y}, {x, y + 5}, {x + 5, y + 5}, {x + 5, y}});
    }
  }
  EXPECT_NO_THROW(decompose(p, {}));
  PolygonWithHoles q = p;
  q.holes.push_back({{11, 11}, {11, 12}, {12, 12}});  // inside hole 0
  expect_error(q, "hole 400 lies inside hole 0");
  q = p;
  q.holes.push_back({{401, 1}, {402, 1}, {402, 2}});
  expect_error(q, "hole 400 is not inside the outer ring");
  q = p;
  q.holes.push_back({{15, 12}, {17, 12}, {17, 14}});  // touches hole 0's right edge at x = 15
  expect_error(q, "intersect or touch");
}

// Long spikes overlap every grid cell; such inputs are checked with a triangulation instead.
TEST(DecomposeValidation, SpikyInputsUseTheTriangulation) {
  PolygonWithHoles star = test_shapes::star(3, 6000, 1, 1000, true);
  EXPECT_NO_THROW(decompose(star, {1e9}));
  std::swap(star.outer[100], star.outer[3100]);  // vertices from opposite sides exchanged: the ring crosses
  expect_error(star, "intersects itself", 1e9);
}

TEST(DecomposeValidation, TriangulationCheckFindsEveryDefect) {
  const PolygonWithHoles ok{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{2, 2}, {2, 4}, {4, 4}, {4, 2}}}};
  EXPECT_NO_THROW(dude::check_rings_by_triangulation(ok));
  auto fails = [](const PolygonWithHoles& p) {
    EXPECT_THROW(dude::check_rings_by_triangulation(p), Error);
  };
  fails({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}, {}});                                     // bow tie
  fails({{{0, 0}, {10, 0}, {5, 0}, {5, 5}}, {}});                                        // fold back
  fails({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{0, 5}, {3, 4}, {3, 6}}}});             // hole touches outer
  fails({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{2, 2}, {2, 4}, {4, 4}}, {{2, 2}, {1, 1}, {3, 1}}}});  // shared vertex
  fails({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{5, -1}, {6, 5}, {7, -1}}}});           // hole crosses outer
}

TEST(IntersectingRings, NamesEveryRingThatBreaksTheRule) {
  const Ring outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Ring fine{{2, 2}, {2, 3}, {3, 3}, {3, 2}};
  using Rings = std::vector<int>;
  EXPECT_EQ(intersecting_rings({outer, {fine}}), Rings{});
  EXPECT_EQ(intersecting_rings({outer, {fine, {{6, 6}, {8, 8}, {8, 6}, {6, 8}}}}), Rings{2});   // hole 1 a bow tie
  EXPECT_EQ(intersecting_rings({outer, {{{0, 5}, {3, 4}, {3, 6}}, fine}}), (Rings{0, 1}));       // touches the outer ring
  EXPECT_EQ(intersecting_rings({outer, {fine, {{3, 3}, {4, 3}, {4, 4}}, {{6, 1}, {7, 1}, {7, 2}}}}), (Rings{1, 2}));  // shared corner
  EXPECT_EQ(intersecting_rings({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}, {}}), Rings{0});            // the outer ring a bow tie
  // Many rings, one of them crossing its neighbour: only those two are named.
  PolygonWithHoles many{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}};
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) many.holes.push_back({{10.0 * i + 2, 10.0 * j + 2}, {10.0 * i + 2, 10.0 * j + 6}, {10.0 * i + 6, 10.0 * j + 6}, {10.0 * i + 6, 10.0 * j + 2}});
  EXPECT_EQ(intersecting_rings(many), Rings{});
  many.holes[40][2] = {55, 46};  // hole 40 (ring 41) reaches into hole 49 (ring 50), its neighbour along x
  EXPECT_EQ(intersecting_rings(many), (Rings{41, 50}));
}

}  // namespace
}  // namespace topocut
