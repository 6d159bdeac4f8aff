#include "topocut/segmentation/cut_search_index.h"

#include <gtest/gtest.h>

#include "topocut/segmentation/door_cuts.h"
#include "topocut/segmentation/island_cuts.h"
#include "topocut/segmentation/wall_lines.h"
#include "topocut/segmentation/wall_openings.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;  // 20 units per metre

// Two 3 m x 3 m rooms joined by a 0.9 m door (as in door_cuts_test).
PolygonWithHoles rooms() {
  return {{{0, 0}, {60, 0}, {60, 20}, {64, 20}, {64, 0}, {124, 0}, {124, 60}, {64, 60}, {64, 38}, {60, 38}, {60, 60},
           {0, 60}},
          {}};
}

// A 3.5 m x 4 m room on top of an 8 m x 6 m one, flush with its right wall (as in wall_lines_test).
PolygonWithHoles room_on_a_wider_room() { return {{{0, 0}, {160, 0}, {160, 200}, {90, 200}, {90, 120}, {0, 120}}, {}}; }

TEST(CutSearchIndex, EveryRuleFindsTheSameCutsWithTheSharedEdges) {
  const DoorOptions options;
  for (const PolygonWithHoles& polygon : {rooms(), room_on_a_wider_room()}) {
    const CutSearchIndex index(polygon, kRes, options);
    const std::vector<Segment2> doors = find_passage_cuts(polygon, kRes, options);
    EXPECT_EQ(find_passage_cuts(polygon, kRes, options, &index), doors);
    EXPECT_EQ(find_wall_openings(polygon, kRes, options, doors, &index), find_wall_openings(polygon, kRes, options, doors));
    EXPECT_EQ(find_island_cuts(polygon, kRes, options, doors, &index), find_island_cuts(polygon, kRes, options, doors));
    EXPECT_EQ(find_wall_line_cuts(polygon, kRes, options, doors, &index), find_wall_line_cuts(polygon, kRes, options, doors));
  }
  // The cases find something: a door between the small rooms, a wall line across the wide opening.
  EXPECT_EQ(find_passage_cuts(rooms(), kRes, options).size(), 1u);
  EXPECT_EQ(find_wall_line_cuts(room_on_a_wider_room(), kRes, options, {}).size(), 1u);
}

TEST(CutSearchIndex, IsSharedOnlyForItsOwnPolygonResolutionAndGrid) {
  const PolygonWithHoles polygon = rooms();
  const DoorOptions options;
  const CutSearchIndex index(polygon, kRes, options);
  const cut_search::PolygonEdges* edges = index.edges_for(polygon, kRes, options);
  ASSERT_NE(edges, nullptr);
  EXPECT_EQ(index.edges_for(polygon, kRes, options), edges);  // built once
  const PolygonWithHoles copy = polygon;  // equal, but another polygon: not trusted to stay equal
  EXPECT_EQ(index.edges_for(copy, kRes, options), nullptr);
  EXPECT_EQ(index.edges_for(polygon, 2 * kRes, options), nullptr);
  DoorOptions wider = options;
  wider.max_width = 4 * options.max_width;  // another grid cell
  EXPECT_EQ(index.edges_for(polygon, kRes, wider), nullptr);
  DoorOptions sharper = options;
  sharper.min_turn = options.min_turn + 0.5;  // other reflex corners
  EXPECT_EQ(index.edges_for(polygon, kRes, sharper), nullptr);
  // A rule handed an index of another polygon searches its own edges.
  EXPECT_EQ(find_passage_cuts(room_on_a_wider_room(), kRes, options, &index), find_passage_cuts(room_on_a_wider_room(), kRes, options));
}

}  // namespace
}  // namespace topocut
