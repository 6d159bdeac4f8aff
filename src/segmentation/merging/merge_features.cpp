#include "topocut/segmentation/merge_features.h"

#include <algorithm>
#include <cmath>

#include "segmentation/merging/room_graph.h"

namespace topocut {

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
