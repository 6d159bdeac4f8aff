// decompose() rejects malformed polygons with one clear Error and normalises what it accepts.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "topocut/core/error.h"
#include "topocut/decomposition/decompose.h"

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

}  // namespace
}  // namespace topocut
