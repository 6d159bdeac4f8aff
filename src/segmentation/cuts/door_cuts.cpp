#include "topocut/segmentation/door_cuts.h"

#include "segmentation/cuts/cut_search.h"
#include "topocut/segmentation/wall_openings.h"

namespace topocut {

using namespace cut_search;

void validate(const DoorOptions& options) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(options.max_width) || !positive(options.door_like.ratio) || !positive(options.door_like.width_depth))
    throw Error("the door width, ratio and depth must be positive numbers");
  if (!std::isfinite(options.min_turn) || options.min_turn < 0.0) throw Error("the door corner turn must be a non-negative angle");
  if (!positive(options.max_gap) || !positive(options.max_wall_thickness) || !std::isfinite(options.min_wall_length) ||
      options.min_wall_length < 0.0 || !std::isfinite(options.gap_alignment) || options.gap_alignment < 0.0 ||
      !std::isfinite(options.min_side_width) || options.min_side_width < 0.0 || !positive(options.wall_end_probe))
    throw Error("the wall opening gap, wall thickness and wall end probe must be positive, the other opening options non-negative");
  if (!positive(options.max_wall_line) || !positive(options.wall_line_wall) || !std::isfinite(options.wall_line_straightness) ||
      options.wall_line_straightness < 0.0 || !std::isfinite(options.wall_line_spacing) || options.wall_line_spacing < 0.0 ||
      !std::isfinite(options.wall_line_side) || options.wall_line_side < 0.0)
    throw Error("the wall line length and wall length must be positive, the straightness, spacing and side width non-negative");
  if (!positive(options.max_island_thickness) || !std::isfinite(options.min_island_length) || options.min_island_length < 0.0)
    throw Error("the wall island thickness must be positive, its length non-negative");
}

std::vector<Segment2> find_passage_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options) {
  return search_cuts(polygon, resolution, options, options.passages, {}, [&](const DoorSearch& search, const EdgeGrid& grid) {
    std::vector<Candidate> doors;
    for (const Candidate& c : corner_cuts(search, grid, false)) {
      if (has_wide_sides(search, grid, c)) doors.push_back(c);
    }
    return segments_of(narrowest_compatible(std::move(doors), resolution));
  });
}

std::vector<Segment2> find_door_cuts(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options) {
  validate(options);
  std::vector<Segment2> cuts = find_passage_cuts(polygon, resolution, options);
  const std::vector<Segment2> openings = find_wall_openings(polygon, resolution, options, cuts);
  cuts.insert(cuts.end(), openings.begin(), openings.end());
  return cuts;
}

}  // namespace topocut
