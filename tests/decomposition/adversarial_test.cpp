// Termination and validity on inputs built to stress the algorithm (§10.12): deep spirals, combs,
// long collinear runs, saw teeth, holes almost touching the boundary, extreme coordinates.
#include <gtest/gtest.h>

#include <cmath>

#include "decomposition/dude_properties.h"
#include "decomposition/dude_test_shapes.h"
#include "topocut/decomposition/concavity.h"
#include "topocut/decomposition/decompose.h"

namespace topocut {
namespace {

using test_props::expect_valid;
using test_props::identical;

Decomposition run(const PolygonWithHoles& p, double tau, int max_rounds = 100) {
  DecompositionOptions o;
  o.tau = tau;
  o.max_rounds = max_rounds;
  return decompose(p, o);
}

void check(const PolygonWithHoles& p, double tau, const std::string& what) {
  const Decomposition d = run(p, tau);
  expect_valid(p, d, what, 200);
  EXPECT_LT(d.rounds, 100) << what;
  EXPECT_TRUE(identical(d, run(p, tau))) << what;
}

// A square spiral corridor (width 3, walls 2) traced from a raster: pockets nest many levels deep.
PolygonWithHoles spiral(int turns) {
  const int size = 10 * turns + 20;
  test_shapes::Grid g(size, size);
  int x = size / 2, y = size / 2, len = 5, dir = 0;
  const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
  for (int i = 0; i < 4 * turns; ++i) {
    for (int k = 0; k < len; ++k) {
      g.fill(x, y, x + 3, y + 3, true);
      x += dx[dir];
      y += dy[dir];
    }
    dir = (dir + 1) % 4;
    if (i % 2 == 1) len += 5;
  }
  test_shapes::remove_pinches(g);
  test_shapes::keep_largest_component(g);
  return test_shapes::trace(g);
}

TEST(DudeAdversarial, Spirals) {
  for (int turns : {3, 8, 15}) {
    const PolygonWithHoles p = spiral(turns);
    for (double tau : {2.0, 6.0, 30.0}) check(p, tau, "spiral " + std::to_string(turns) + " tau " + std::to_string(tau));
  }
}

PolygonWithHoles comb(int teeth) {
  PolygonWithHoles p;
  p.outer.push_back({0, 0});
  p.outer.push_back({3.0 * teeth, 0});
  for (int i = teeth - 1; i >= 0; --i) {  // slots 1 wide and 40 deep, cut from the top
    p.outer.push_back({3.0 * i + 3, 50});
    p.outer.push_back({3.0 * i + 2, 50});
    p.outer.push_back({3.0 * i + 2, 10});
    p.outer.push_back({3.0 * i + 1, 10});
    p.outer.push_back({3.0 * i + 1, 50});
  }
  p.outer.push_back({0, 50});
  return p;
}

TEST(DudeAdversarial, Comb) {
  const PolygonWithHoles p = comb(40);
  for (double tau : {0.5, 5.0, 100.0}) check(p, tau, "comb tau " + std::to_string(tau));
  // Every slot ends up in its own piece (41 teeth between and beside 40 slots, joined below).
  const Decomposition d = run(p, 5.0);
  for (const PolygonWithHoles& piece : d.pieces) EXPECT_LE(measure_concavity(piece).max(), 5.0);
}

// All slot bottoms are collinear, so a pocket's hull chain holds only the two outermost ones and a
// pass cuts two slots (as the reference does): 300 slots need 150 passes. The round cap stops it
// early; the result is still an exact tiling, only coarser.
TEST(DudeAdversarial, CombBeyondTheRoundCap) {
  const PolygonWithHoles p = comb(300);
  const Decomposition d = run(p, 5.0, 20);
  EXPECT_EQ(d.rounds, 20);
  EXPECT_FALSE(d.complete);
  EXPECT_EQ(d.cuts.size(), 40u);
  expect_valid(p, d, "capped comb", 200);
}

// A comb whose base corners see every slot: the full-resolution triangulation gives them a degree
// proportional to the teeth, which the candidate test must not pay per diagonal. With rounds
// enough for every slot the pieces tile the comb and each is within tau.
TEST(DudeAdversarial, WideCombTilesWithinTau) {
  const PolygonWithHoles p = comb(120);
  const Decomposition d = run(p, 5.0, 100);
  EXPECT_LT(d.rounds, 100);
  EXPECT_TRUE(d.complete);
  expect_valid(p, d, "wide comb", 200);
  EXPECT_GE(d.pieces.size(), 120u);
  for (const PolygonWithHoles& piece : d.pieces) EXPECT_LE(measure_concavity(piece).max(), 5.0);
}

TEST(DudeAdversarial, LongCollinearRuns) {
  PolygonWithHoles p;
  const int n = 400;
  for (int i = 0; i < n; ++i) p.outer.push_back({static_cast<double>(i), 0});
  for (int i = 0; i < n; ++i) p.outer.push_back({static_cast<double>(n), static_cast<double>(i)});
  for (int i = n; i > n / 2 + 10; --i) p.outer.push_back({static_cast<double>(i), static_cast<double>(n)});
  for (int i = n; i > n / 3; --i) p.outer.push_back({static_cast<double>(n / 2 + 10), static_cast<double>(i)});  // a slot
  for (int i = n / 3; i < n; ++i) p.outer.push_back({static_cast<double>(n / 2 - 10), static_cast<double>(i)});
  for (int i = n / 2 - 10; i > 0; --i) p.outer.push_back({static_cast<double>(i), static_cast<double>(n)});
  for (int i = n; i > 0; --i) p.outer.push_back({0, static_cast<double>(i)});
  p.holes.push_back({{50, 50}, {50, 60}, {60, 60}, {60, 55}, {60, 50}, {55, 50}});
  for (double tau : {5.0, 50.0}) check(p, tau, "collinear tau " + std::to_string(tau));
  const Decomposition d = run(p, 50);
  EXPECT_GE(d.pieces.size(), 2u);  // the slot (depth 267) must be cut
}

TEST(DudeAdversarial, SawTeeth) {
  for (double amplitude : {0.3, 3.0, 30.0}) {
    PolygonWithHoles p;
    for (int i = 0; i <= 200; ++i) p.outer.push_back({i * 1.0, i % 2 ? amplitude : 0.0});
    p.outer.push_back({200, 100});
    p.outer.push_back({0, 100});
    for (double tau : {1.0, 10.0}) check(p, tau, "saw " + std::to_string(amplitude) + " tau " + std::to_string(tau));
  }
}

TEST(DudeAdversarial, HolesAlmostTouchingTheBoundary) {
  const double eps = 1e-9;
  PolygonWithHoles p{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}};
  p.holes.push_back({{eps, 10}, {eps, 40}, {30, 40}, {30, 10}});           // almost on the left wall
  p.holes.push_back({{60, 60}, {60, 100 - eps}, {90, 100 - eps}, {90, 60}});  // almost on the top wall
  p.holes.push_back({{40, 10}, {40 + eps, 40}, {41, 10}});                 // a needle
  p.holes.push_back({{50, 20}, {50, 30}, {50 + 1e-6, 25}});                // a sliver
  for (double tau : {1.0, 5.0, 25.0, 1000.0}) check(p, tau, "near-touching tau " + std::to_string(tau));
}

TEST(DudeAdversarial, ExtremeCoordinates) {
  const PolygonWithHoles base = test_shapes::floor_plan(5, {});
  for (double scale : {1e-6, 1e6}) {
    const auto p = test_shapes::map_points(base, [&](Point2 v) { return Point2{v.x * scale + 1e3 * scale, v.y * scale}; });
    check(p, 10 * scale, "scale " + std::to_string(scale));
  }
  const auto far = test_shapes::map_points(base, [](Point2 v) { return Point2{v.x + 1e9, v.y - 1e9}; });
  check(far, 10, "translated by 1e9");
}

TEST(DudeAdversarial, ManyTinyHolesAndRoundCap) {
  PolygonWithHoles p{{{0, 0}, {200, 0}, {200, 200}, {0, 200}}, {}};
  for (int i = 0; i < 15; ++i) {
    for (int j = 0; j < 15; ++j) {
      const double x = 5 + 13 * i, y = 5 + 13 * j, s = 1 + (i * 7 + j * 3) % 9;
      p.holes.push_back({{x, y}, {x, y + s}, {x + s, y + s}, {x + s, y}});
    }
  }
  for (double tau : {2.0, 6.0, 20.0}) check(p, tau, "tiny holes tau " + std::to_string(tau));
  // With one round only the result is still an exact tiling, just coarser.
  const Decomposition one = run(p, 2.0, 1);
  EXPECT_EQ(one.rounds, 1);
  expect_valid(p, one, "one round", 200);
}

TEST(DudeAdversarial, NestedCShapedObstacles) {
  PolygonWithHoles p{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}};
  // A C-shaped obstacle around a square one.
  p.holes.push_back({{20, 20}, {20, 80}, {80, 80}, {80, 70}, {30, 70}, {30, 30}, {80, 30}, {80, 20}});
  p.holes.push_back({{45, 45}, {45, 55}, {55, 55}, {55, 45}});
  for (double tau : {2.0, 8.0, 30.0}) check(p, tau, "C obstacle tau " + std::to_string(tau));
}

}  // namespace
}  // namespace topocut
