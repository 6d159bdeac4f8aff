#include "topocut/segmentation/door_cuts.h"

#include "segmentation/cuts/cut_search.h"
#include "topocut/segmentation/wall_openings.h"

namespace topocut {

using namespace cut_search;

void validate(const DoorOptions& options) {
  // Each field's range is its row's (door_option_rows()): one definition, which the front ends check
  // as a value enters and which holds here for callers of the library.
  check_option_rows(door_option_rows(), options);
}

std::vector<Segment2> find_passage_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options,
                                        const CutSearchIndex* index) {
  return search_cuts(polygon, resolution, options, options.passages, {}, index, [&](const DoorSearch& search, const EdgeGrid& grid) {
    return segments_of(narrowest_compatible(corner_cuts(search, grid, false), resolution,
                                            [&](const Candidate& c) { return has_wide_sides(search, grid, c); }));
  });
}

std::vector<Segment2> find_door_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options) {
  validate(options);
  const CutSearchIndex index(polygon, resolution, options);  // both rules search the same edges
  std::vector<Segment2> cuts = find_passage_cuts(polygon, resolution, options, &index);
  const std::vector<Segment2> openings = find_wall_openings(polygon, resolution, options, cuts, &index);
  cuts.insert(cuts.end(), openings.begin(), openings.end());
  return cuts;
}

}  // namespace topocut
