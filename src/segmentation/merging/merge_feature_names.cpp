// The merge features' names, apart from their computation (merge_features.cpp): reading a model
// needs only the names, and so does the build-time compiler of the shipped model
// (tools/compile_merge_model.cpp), which links this file and merge_model.cpp alone.
#include <string>
#include <string_view>
#include <vector>

#include "topocut/segmentation/merge_features.h"

namespace topocut {

const std::vector<std::string>& merge_feature_names() {
  static const std::vector<std::string> names{
      "cut_over_narrow_width",        // cut length / narrow side's width (a door is well below 1), at most 3
      "narrow_over_wide_width",       // narrow width / wide width: 1 a room cut across, small a width step
      "narrow_depth_over_width",      // narrow side's depth behind the cut / its width, at most 5
      "wide_depth_over_narrow_width", // wide side's depth / narrow width, at most 5
      "log_narrow_area",              // log(narrow room's area, m²)
      "log_wide_area",                // log(wide room's area, m²)
      "narrow_thickness",             // 2 area / perimeter of the narrow room, m
      "wide_thickness",               // the same of the wide room
      "union_solidity",               // area of the two rooms / area of their convex hull
      "solidity_loss",                // the less convex side's solidity minus the union's
      "shared_over_perimeter",        // cut length between the two rooms / the shorter room perimeter
      "furniture_end",                // an end of the cut lies on a furniture-sized obstacle
      "min_end_angle",                // the free space's angle at the cut's ends / pi: 1 in a straight wall,
      "max_end_angle",                //   1.5 at a door jamb, 2 at a wall's end, 0.5 in a corner
      "narrow_open_share",            // the narrow room's cuts to other rooms / its perimeter
      "wide_open_share",              // the same of the wide room
      "cut_over_wide_width",          // cut length / the wide side's width
      "union_thickness_over_narrow",  // 2 area / perimeter of the union over the narrow room's
      "log_narrow_elongation",        // log of the narrow room's elongation (second moments: about length / width)
      "log_union_elongation",         // log of the union's elongation
      "ends_on_holes",                // ends of the cut on an obstacle inside the free space (0, 1 or 2);
                                      //   its extent is log_hole_extent_over_scale below
      "narrow_wall_share",            // the narrow room's outline along occupied cells / its outline but cuts
      "wide_wall_share",              // the same of the wide room
      "narrow_unknown_share",         // the narrow room's outline along never-seen cells / the same
      "wide_unknown_share",           // the same of the wide room
      "cut_skew",                     // the cut's angle to the walls at its ends / (pi / 4): 0 along or
                                      //   across them, 1 a diagonal
      // Lengths in the component's own scale (RoomGraph::piece_scale(): the typical piece's thickness;
      // cut_scale(): the typical cut's length), the same whatever a kind's sizes: in metres, the cut's
      // length and the narrow width told the kinds fitted on apart more than doors from rooms, and a
      // model fitted without homes or sketches misjudged theirs (benchmarks/README.md). The areas and
      // thicknesses above stay in metres too: both together generalised best.
      "log_cut_over_scale",           // log(cut length / piece scale)
      "log_cut_over_cut_scale",       // log(cut length / cut scale)
      "log_narrow_width_over_scale",  // log(narrow width / piece scale)
      "log_narrow_width_over_cut_scale",  // log(narrow width / cut scale)
      "log_narrow_area_over_scale",   // log(narrow room's area / piece scale²)
      "log_wide_area_over_scale",     // log(wide room's area / piece scale²)
      "narrow_thickness_over_scale",  // narrow_thickness / piece scale, at most 10
      "wide_thickness_over_scale",    // wide_thickness / piece scale, at most 10
      "log_wall_continued_over_scale",  // log(1 + the wall the cut continues straight on / piece scale)
      "log_hole_extent_over_scale",   // log(1 + the largest such obstacle's bounding-box side / piece scale)
  };
  return names;
}

int merge_feature_index(std::string_view name) {
  // The names by length, in their order (at most six share one), built once: reading the shipped model
  // looks up a name for each of its eight thousand splits.
  const std::vector<std::string>& names = merge_feature_names();
  static const std::vector<std::vector<int>> by_length = [&names] {
    std::vector<std::vector<int>> lengths;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (lengths.size() <= names[i].size()) lengths.resize(names[i].size() + 1);
      lengths[names[i].size()].push_back(static_cast<int>(i));
    }
    return lengths;
  }();
  if (name.size() >= by_length.size()) return -1;
  for (const int i : by_length[name.size()])
    if (names[static_cast<std::size_t>(i)] == name) return i;
  return -1;
}

}  // namespace topocut
