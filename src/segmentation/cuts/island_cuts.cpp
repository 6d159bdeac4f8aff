#include "topocut/segmentation/island_cuts.h"

#include "segmentation/cuts/cut_search.h"
#include "topocut/segmentation/polygon_split.h"

namespace topocut {

using namespace cut_search;

std::vector<Segment2> find_island_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                                       const std::vector<Segment2>& doors, const CutSearchIndex* index) {
  // The outline, then each hole; most maps have no wall island, and then there is nothing to search.
  std::vector<bool> joinable{true};
  bool any = false;
  if (options.island_cuts) {
    for (const Ring& hole : polygon.holes) {
      joinable.push_back(is_wall_island(hole, resolution, options));
      any = any || joinable.back();
    }
  }
  return search_cuts(polygon, resolution, options, any, std::move(joinable), index, [&](const DoorSearch& search, const EdgeGrid& grid) {
    std::vector<Candidate> all = doors_first(doors);
    const std::vector<Candidate> corners = corner_cuts(search, grid, true);
    all.insert(all.end(), corners.begin(), corners.end());
    // The side test only on the candidates no narrower cut has ruled out (a candidate it rejects
    // blocks none, so the same cuts as testing all first); the doors stay as they are.
    const auto wide = [&](const Candidate& c) { return is_door_first(c) || has_wide_sides(search, grid, c); };
    // Only the cuts that, with the doors and each other, close a part off.
    return without_doors(separating_chords(polygon, segments_of(narrowest_compatible(std::move(all), resolution, wide))), doors);
  });
}

}  // namespace topocut
