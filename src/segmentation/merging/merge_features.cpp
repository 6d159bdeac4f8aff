#include "topocut/segmentation/merge_features.h"

#include <algorithm>
#include <cmath>

#include "segmentation/merging/room_graph.h"

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

namespace {

// Floors that keep logarithms and ratios finite for slivers (half a 5 cm cell, a tenth of a cell's area).
constexpr double kMinLength = 0.025;
constexpr double kMinArea = 0.00025;

double solidity(double area, double hull) { return hull > 0.0 ? std::min(area / hull, 1.0) : 1.0; }

}  // namespace

std::vector<double> merge_features(RoomGraph& graph, std::size_t k, const RoomMergeOptions& options) {
  const double width_depth = options.door_like.width_depth;
  const RoomGraph::Side& side = graph.sides()[k];
  const int left = graph.root(side.left), right = graph.root(side.right);
  const double width_left = std::max(graph.side_width(k, left, true, width_depth), kMinLength);
  const double width_right = std::max(graph.side_width(k, right, false, width_depth), kMinLength);
  const bool left_narrow = width_left <= width_right;
  const int narrow = left_narrow ? left : right, wide = left_narrow ? right : left;
  const double w_narrow = std::min(width_left, width_right), w_wide = std::max(width_left, width_right);
  const double d_narrow = graph.side_depth(k, narrow, left_narrow), d_wide = graph.side_depth(k, wide, !left_narrow);
  const double a_narrow = std::max(graph.room_area(narrow), kMinArea), a_wide = std::max(graph.room_area(wide), kMinArea);
  const double s_narrow = solidity(a_narrow, graph.convex_hull_area({narrow}));
  const double s_wide = solidity(a_wide, graph.convex_hull_area({wide}));
  const double s_union = solidity(a_narrow + a_wide, graph.convex_hull_area({narrow, wide}));
  // Each measure once: every one walks the rooms' pieces and cuts.
  const double p_narrow = graph.room_perimeter(narrow), p_wide = graph.room_perimeter(wide);
  const double shared = graph.shared_cut_length(narrow, wide);
  // Each room's cuts to other rooms: its open share.
  const double open_narrow = graph.shared_cut_length(narrow, -1), open_wide = graph.shared_cut_length(wide, -1);
  const double t_narrow = graph.room_thickness(narrow);
  const double perimeter = std::max(std::min(p_narrow, p_wide), kMinLength);
  const double length = std::max(side.length, kMinLength);
  const double union_perimeter = p_narrow + p_wide - 2.0 * shared;
  const double union_thickness = union_perimeter > 0.0 ? 2.0 * (a_narrow + a_wide) / union_perimeter : 0.0;
  const double scale = std::max(graph.piece_scale(), kMinLength), cut_scale = std::max(graph.cut_scale(), kMinLength);
  return {
      std::min(length / w_narrow, 3.0),
      w_narrow / w_wide,
      std::min(d_narrow / w_narrow, 5.0),
      std::min(d_wide / w_narrow, 5.0),
      std::log(a_narrow),
      std::log(a_wide),
      t_narrow,
      graph.room_thickness(wide),
      s_union,
      std::min(s_narrow, s_wide) - s_union,
      std::min(shared / perimeter, 1.0),
      side.furniture ? 1.0 : 0.0,
      side.end_angle[0] / M_PI,
      side.end_angle[1] / M_PI,
      std::min(open_narrow / std::max(p_narrow, kMinLength), 1.0),
      std::min(open_wide / std::max(p_wide, kMinLength), 1.0),
      std::min(length / w_wide, 3.0),
      union_thickness / std::max(t_narrow, kMinLength),
      std::log(std::min(graph.elongation({narrow}), 100.0)),
      std::log(std::min(graph.elongation({narrow, wide}), 100.0)),
      static_cast<double>(std::min(side.ends_on_holes, 2)),
      graph.wall_share(narrow),
      graph.wall_share(wide),
      graph.unknown_share(narrow),
      graph.unknown_share(wide),
      side.skew / (M_PI / 4.0),
      std::log(length / scale),
      std::log(length / cut_scale),
      std::log(w_narrow / scale),
      std::log(w_narrow / cut_scale),
      std::log(a_narrow / (scale * scale)),
      std::log(a_wide / (scale * scale)),
      std::min(t_narrow / scale, 10.0),
      std::min(graph.room_thickness(wide) / scale, 10.0),
      std::log1p(side.wall_continued / scale),
      std::log1p(side.hole_extent / scale),
  };
}

}  // namespace topocut
