#include "topocut/segmentation/segment_switches.h"

#include "topocut/core/error.h"

namespace topocut {

void apply(const SegmentSwitches& s, SegmentOptions& options) {
  if (s.parity && (s.no_doors || s.no_wall_openings || s.no_merge || s.no_simplify || options.labels.cover_absorbed_obstacles ||
                   s.no_clean || s.no_width_steps || s.no_furniture_rule))
    throw Error("--parity already switches every improvement off; give it alone");
  if (s.parity) {
    const SegmentOptions reference = parity_segment_options(options.concavity);
    options.doors = reference.doors;
    options.merge = reference.merge;
    options.simplify = reference.simplify;
    options.labels = reference.labels;
    options.clean = reference.clean;
    if (!s.min_room_area_given) options.contours.min_component_area = reference.contours.min_component_area;
  }
  if (s.no_doors) options.doors.enabled = false;
  if (s.no_wall_openings) options.doors.extend_walls = false;
  if (s.no_merge) options.merge.enabled = false;
  if (s.no_simplify) options.simplify = 0.0;
  if (s.no_clean) options.clean = false;
  options.decompose = !s.trivial;
  if (s.no_width_steps) options.merge.step_ratio = 0.0;
  if (s.no_furniture_rule) options.merge.furniture_size = 0.0;
}

}  // namespace topocut
