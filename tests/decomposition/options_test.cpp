// The named switches of DecompositionOptions: each one changes what it claims to and nothing breaks.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "decomposition/dude_properties.h"
#include "decomposition/dude_test_shapes.h"
#include "topocut/decomposition/concavity.h"
#include "topocut/decomposition/decompose.h"

namespace topocut {
namespace {

using test_props::canonical;
using test_props::expect_valid;

const PolygonWithHoles kSlot{
    {{0, 0}, {100, 0}, {100, 100}, {60, 100}, {60, 50}, {90, 50}, {90, 30}, {40, 30}, {40, 100}, {0, 100}}, {}};

std::map<std::pair<double, double>, double> first_pass_minima(const Decomposition& d) {
  std::map<std::pair<double, double>, double> pms;
  for (const PocketMinimum& pm : d.pocket_minima) {
    if (pm.pass == 0) pms[{pm.vertex.x, pm.vertex.y}] = pm.concavity;
  }
  return pms;
}

// §3.4: the paper's hierarchical concavity adds the depths along the pocket tree, so it is never
// below the straight-line distance and exceeds it where the path bends (the nested slot's (90,50)).
TEST(DudeOptions, HierarchicalConcavity) {
  DecompositionOptions straight;
  straight.tau = 10;
  DecompositionOptions hierarchical = straight;
  hierarchical.concavity = ConcavityMeasure::kHierarchical;
  const Decomposition ds = decompose(kSlot, straight);
  const Decomposition dh = decompose(kSlot, hierarchical);
  const auto s = first_pass_minima(ds);
  const auto h = first_pass_minima(dh);
  ASSERT_TRUE(s.count({90, 50}));
  ASSERT_TRUE(h.count({90, 50}));
  EXPECT_DOUBLE_EQ((s.at({90, 50})), 50.0);
  EXPECT_GT((h.at({90, 50})), 50.0 + 1e-9);
  for (const auto& [v, c] : h) {
    if (s.count(v)) {
      EXPECT_GE(c, s.at(v) - 1e-9);
    }
  }
  expect_valid(kSlot, dh, "hierarchical");
  for (unsigned seed = 0; seed < 10; ++seed) {
    const PolygonWithHoles p = test_shapes::floor_plan(300 + seed, {});
    DecompositionOptions o;
    o.tau = 10;
    o.concavity = ConcavityMeasure::kHierarchical;
    expect_valid(p, decompose(p, o), "hierarchical plan " + std::to_string(seed), 100);
  }
}

// The skinny filter only ever removes cuts: with it off a pass applies a superset.
TEST(DudeOptions, SkinnyFilterRemovesCuts) {
  test_shapes::PlanOptions o;
  o.width = 60;
  o.height = 40;
  o.min_room = 10;
  o.noise = 20;
  int differing = 0;
  for (unsigned seed = 0; seed < 10; ++seed) {
    const PolygonWithHoles p = test_shapes::floor_plan(seed, o);
    for (double tau : {4.0, 8.0}) {
      DecompositionOptions all, off;
      all.tau = off.tau = tau;
      all.skinny_cuts = SkinnyCutFilter::kAll;
      off.skinny_cuts = SkinnyCutFilter::kOff;
      const Decomposition da = decompose(p, all), doff = decompose(p, off);
      expect_valid(p, da, "skinny all", 100);
      expect_valid(p, doff, "skinny off", 100);
      // Same first pass minima; the first pass without the filter keeps every cut it had with it.
      std::set<std::vector<double>> first_all, first_off;
      for (const Cut& c : da.cuts) {
        if (c.pass == 0) first_all.insert({c.segment.a.x, c.segment.a.y, c.segment.b.x, c.segment.b.y});
      }
      for (const Cut& c : doff.cuts) {
        if (c.pass == 0) first_off.insert({c.segment.a.x, c.segment.a.y, c.segment.b.x, c.segment.b.y});
      }
      for (const auto& c : first_all) EXPECT_TRUE(first_off.count(c));
      differing += da.cuts.size() != doff.cuts.size();
    }
  }
  EXPECT_GT(differing, 0);  // the filter does something on these inputs
}

// §4.2: small holes are absorbed by default; kept, the pieces tile the free space exactly.
TEST(DudeOptions, KeepSmallHoles) {
  const PolygonWithHoles p{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{3, 3}, {3, 7}, {7, 7}, {7, 3}}}};
  DecompositionOptions o;
  o.tau = 6;
  o.absorb_small_holes = false;
  const Decomposition d = decompose(p, o);
  EXPECT_TRUE(d.absorbed_holes.empty());
  ASSERT_EQ(d.pieces.size(), 1u);
  EXPECT_EQ(d.pieces[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ(area(d.pieces[0]), 84.0);
  expect_valid(p, d, "kept hole");
}

// A cut that merges a hole into the outer ring leaves a keyhole ring: returned as outer ring plus
// hole by default, as the keyhole ring itself on request.
TEST(DudeOptions, KeyholeRingsAndRestoredHoles) {
  // L-room whose corner cut (4,4)-(0,0) runs through a small kept hole: the cut ends on the hole.
  const PolygonWithHoles p{{{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}},
                           {{{1.5, 1.5}, {1.5, 2.5}, {2.5, 2.5}, {2.5, 1.5}}}};
  DecompositionOptions o;
  o.tau = 2;
  o.absorb_small_holes = false;
  o.max_rounds = 1;
  const Decomposition restored = decompose(p, o);
  o.restore_holes = false;
  const Decomposition keyholes = decompose(p, o);
  ASSERT_EQ(restored.cuts.size(), 1u);
  EXPECT_EQ(restored.cuts[0].segment, keyholes.cuts[0].segment);
  ASSERT_EQ(restored.pieces.size(), 1u);
  ASSERT_EQ(keyholes.pieces.size(), 1u);
  EXPECT_EQ(restored.pieces[0].holes.size(), 1u);
  EXPECT_EQ(restored.pieces[0].outer.size(), 6u);
  EXPECT_TRUE(keyholes.pieces[0].holes.empty());
  EXPECT_EQ(keyholes.pieces[0].outer.size(), 6u + 4u + 2u);  // both cut ends visited twice
  EXPECT_DOUBLE_EQ(area(restored.pieces[0]), area(keyholes.pieces[0]));
  EXPECT_DOUBLE_EQ(area(restored.pieces[0]), area(p));
}

// With a selection limit below the number of cut sets the reference DP falls back to greedy.
TEST(DudeOptions, ReferenceSelectionLimit) {
  const PolygonWithHoles p = test_shapes::floor_plan(77, {});
  DecompositionOptions greedy;
  greedy.tau = 8;
  DecompositionOptions capped = greedy;
  capped.selection = CutSelection::kReference;
  capped.reference_selection_limit = 0;
  EXPECT_EQ(canonical(decompose(p, capped)), canonical(decompose(p, greedy)));
  DecompositionOptions reference = greedy;
  reference.selection = CutSelection::kReference;
  reference.reference_selection_limit = 1000;
  expect_valid(p, decompose(p, reference), "reference DP");
}

// Every reference switch at once still gives exact tilings of map-like input (the reference's own
// boundary-crossing cuts are dropped, never applied).
TEST(DudeOptions, AllReferenceSwitches) {
  for (unsigned seed = 0; seed < 15; ++seed) {
    test_shapes::PlanOptions po;
    po.noise = 40;
    const PolygonWithHoles plan = test_shapes::floor_plan(500 + seed, po);
    const PolygonWithHoles star = test_shapes::star(500 + seed, 60, 5, 100, seed % 2);
    for (const PolygonWithHoles& p : {plan, star}) {
      DecompositionOptions o;
      o.tau = 6;
      o.selection = CutSelection::kReference;
      o.candidates = CandidateCuts::kReference;
      o.pocket_polygon = PocketPolygon::kReference;
      o.hull_chain_distance = HullChainDistance::kLine;
      expect_valid(p, decompose(p, o), "reference switches " + std::to_string(seed), 100);
    }
  }
}

}  // namespace
}  // namespace topocut
