// The segmentation module's option tables (segmenter.h, door_cuts.h, room_merging.h, open_rooms.h,
// rooms_from_pieces.h, room_kinds.h, incremental_segmenter.h): each field's name, unit, range and
// help once; defaults are the structs' own. The switches of the pipeline's rules (DoorOptions::passages,
// RoomMergeOptions::enabled, ...) are segmentation_rules()' --no-NAME rows, not rows here.
#include "topocut/core/option_table.h"
#include "topocut/segmentation/door_cuts.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/open_rooms.h"
#include "topocut/segmentation/room_kinds.h"
#include "topocut/segmentation/room_merging.h"
#include "topocut/segmentation/rooms_from_pieces.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

const std::vector<OptionRow<SegmentOptions>>& segment_number_option_rows() {
  using S = SegmentOptions;
  static const std::vector<OptionRow<S>> rows = {
      field_row("concavity", "M", OptionRange::kLength, &S::concavity,
                "maximum concavity tau in metres: larger values give fewer, less convex rooms"),
      field_row("simplify", "CELLS", OptionRange::kNonNegative, &S::simplify,
                "tolerance (cells) of the outlines' simplification (0: the exact pixel edges, as --no-simplify)"),
      field_row("oversegment", "F", OptionRange::kFraction, &S::oversegment,
                "with merging, DuDe cuts at F x tau, 0 < F <= 1 (merging then removes the cuts that are not door-like)"),
  };
  return rows;
}

const std::vector<OptionRow<DoorOptions>>& door_option_rows() {
  using D = DoorOptions;
  constexpr OptionRange kLength = OptionRange::kLength, kLengthOrZero = OptionRange::kLengthOrZero;
  static const std::vector<OptionRow<D>> rows = {
      field_row("door-width", "M", kLength, &D::max_width, "widest passage in metres taken for a door (cut before the decomposition)"),
      field_row("door-ratio", "F", OptionRange::kPositive, &D::door_like, &DoorLikeCut::ratio,
                "doors: a door is narrower than this times the space on each side"),
      field_row("door-depth", "M", kLength, &D::door_like, &DoorLikeCut::width_depth, "doors: metres beyond a cut where each side's width is sampled"),
      field_row("door-turn", "RAD", OptionRange::kNonNegative, &D::min_turn,
                "doors: corners turning less (radians) are bends of a wall, not a door's jambs"),
      field_row("max-gap", "M", kLength, &D::max_gap, "wall openings: longest opening (metres) a thin wall is continued across"),
      field_row("wall-thickness", "M", kLength, &D::max_wall_thickness,
                "wall openings: thickest wall (metres) continued; thicker is furniture"),
      field_row("wall-end-probe", "M", kLength, &D::wall_end_probe,
                "wall openings: metres behind a wall's end where its thickness is measured"),
      field_row("gap-wall", "M", kLengthOrZero, &D::min_wall_length, "wall openings: shortest wall (metres) that gives a direction"),
      field_row("gap-alignment", "RAD", OptionRange::kNonNegative, &D::gap_alignment,
                "wall openings: a wall end across the gap this well aligned (radians) faces it"),
      field_row("gap-side", "M", kLengthOrZero, &D::min_side_width, "wall openings: both sides of an opening at least this wide (metres)"),
      field_row("island-thickness", "M", kLength, &D::max_island_thickness,
                "island cuts: thickest free-standing wall (metres, mean thickness) cut onto"),
      field_row("island-length", "M", kLengthOrZero, &D::min_island_length,
                "island cuts: shorter free-standing walls (metres) are furniture"),
      field_row("max-wall-line", "M", kLength, &D::max_wall_line, "longest stretch of free space (metres) a wall line crosses"),
      field_row("wall-line-wall", "M", kLength, &D::wall_line_wall, "shortest straight wall (metres) whose continuation is a wall line"),
      field_row("wall-line-straightness", "M", kLengthOrZero, &D::wall_line_straightness,
                "wall lines: every point of a straight wall this close (metres) to its line"),
      field_row("wall-line-spacing", "M", kLengthOrZero, &D::wall_line_spacing,
                "of two wall lines closer than this (metres) along their whole length only the shorter is kept"),
      field_row("wall-line-side", "M", kLengthOrZero, &D::wall_line_side,
                "a wall line is at least this long (metres) and leaves both sides this wide"),
  };
  return rows;
}

const std::vector<OptionRow<RoomMergeOptions>>& room_merge_option_rows() {
  using R = RoomMergeOptions;
  constexpr OptionRange kNonNegative = OptionRange::kNonNegative;
  static const std::vector<OptionRow<R>> rows = {
      field_row("fold-area", "M2", OptionRange::kArea, &R::min_room_area,
                "rooms smaller than this (m²) are folded into the neighbour they share the longest cut with"),
      field_row("fold-width", "M", OptionRange::kLengthOrZero, &R::min_room_width,
                "rooms whose widest chord along any cut is narrower (metres) fold the same way (0: off)"),
      field_row("fold-thickness", "M", OptionRange::kLengthOrZero, &R::min_room_thickness,
                "(hand rules) rooms thinner than this (metres, 2 area / perimeter) fold the same way"),
      field_row("sliver-thickness", "M", OptionRange::kLengthOrZero, &R::sliver_thickness,
                "(learned merging) rooms thinner than this (metres, 2 area / perimeter) fold the same way: slivers, "
                "not closets (0: off)"),
      field_row("fragment-area", "M2", OptionRange::kArea, &R::fragment_area,
                "(learned merging) rooms smaller than this (m²), bounded more by never-seen cells than by walls and "
                "entered through a gap narrower than fragment-gap, fold the same way (0: off)"),
      field_row("fragment-gap", "M", OptionRange::kLengthOrZero, &R::fragment_gap,
                "fragments: the widest gap (metres) a fragment is entered through; wider is a door"),
      field_row("bay-share", "F", OptionRange::kShare, &R::bay_share,
                "(learned merging) bays: a room whose cuts to a much larger neighbour (door rules' cuts left out) are this share of its "
                "outline joins it (0: off)"),
      field_row("bay-area-ratio", "F", OptionRange::kShare, &R::bay_area_ratio,
                "bays: the room at most this share of the neighbour's area"),
      field_row("hang-probability", "F", OptionRange::kShare, &R::hang_probability,
                "(learned merging) fragments and bays join only where the model's probability of one room is at least this"),
      field_row("merge-door-ratio", "F", OptionRange::kPositive, &R::door_like, &DoorLikeCut::ratio,
                "(hand rules) a cut narrower than this times the room on each side is door-like and stays"),
      field_row("merge-depth", "M", OptionRange::kLengthOrZero, &R::door_like, &DoorLikeCut::width_depth,
                "metres into a room where its width next to a cut is sampled"),
      field_row("furniture-size", "M", OptionRange::kLengthOrZero, &R::furniture_size,
                "obstacles at most this long both ways (metres) are furniture (0: none)"),
      field_row("step-ratio", "F", OptionRange::kShareBelowOne, &R::step_ratio,
                "(hand rules) a room narrower than this times the space it opens onto stays apart (0: off)"),
      field_row("step-area", "M2", OptionRange::kArea, &R::step_min_area, "(hand rules) width steps: both rooms at least this large (m²)"),
      field_row("step-depth", "M", OptionRange::kLengthOrZero, &R::step_min_wide_depth,
                "(hand rules) width steps: the wider space at least this deep (metres)"),
      field_row("step-wall-line-depth", "F", kNonNegative, &R::step_wall_line_depth,
                "(hand rules) across a wall line the wider side need only be this many narrow widths deep"),
  };
  return rows;
}

const std::vector<OptionRow<OpenRoomOptions>>& open_room_option_rows() {
  using O = OpenRoomOptions;
  static const std::vector<OptionRow<O>> rows = {
      field_row("open-min-area", "M2", OptionRange::kArea, &O::min_area, "open rooms: smaller rooms (m²) are never open"),
      field_row("open-share", "F", OptionRange::kShare, &O::share,
                "open rooms: more than this share of the outline runs into never-seen space"),
      field_row("open-ragged-share", "F", OptionRange::kShare, &O::ragged_share,
                "open rooms: and more than this share of those edges turn (rays end raggedly)"),
      field_row("open-wall-reach", "M", OptionRange::kLengthOrZero, &O::wall_reach,
                "open rooms: never-seen cells this close to a wall (metres) count as wall"),
      field_row("open-wall-band", "M", OptionRange::kLengthOrZero, &O::wall_band,
                "open rooms: never-seen bands this thin (metres) between free cells are drawn walls"),
      field_row("open-floor-share", "F", OptionRange::kShare, &O::floor_share,
                "open rooms: or less than this share of the room's cells is floor, the rest rays the cleaning removed "
                "(a fan seen through an opening; 0: off)"),
      field_row("open-fan-ray-share", "F", OptionRange::kShare, &O::fan_ray_share,
                "open rooms: a labelled room still open that the labelling gave at least this share of its cells beyond its "
                "polygon (rays the cleaning removed) is a fan seen through a gap, no room (0: off)"),
      field_row("open-fan-inside-share", "F", OptionRange::kShare, &O::fan_inside_share,
                "open rooms: unless more than this share of its floor lies inside the building (walls closed across "
                "--open-fan-closing): a walled room holding the fan seen through its door, cut back to the inside "
                "(1: leave every fan out)"),
      field_row("open-fan-closing", "M", OptionRange::kLengthOrZero, &O::fan_closing,
                "open rooms: the walls are closed across gaps this wide (metres) to tell the building's inside (0: nothing is inside)"),
  };
  return rows;
}

const std::vector<OptionRow<RoomLabelOptions>>& room_label_option_rows() {
  static const std::vector<OptionRow<RoomLabelOptions>> rows = {
      switch_row("cover-obstacles", &RoomLabelOptions::cover_absorbed_obstacles,
                 "label the obstacles a room absorbed (furniture) with the room, not with 0"),
  };
  return rows;
}

const std::vector<OptionRow<RoomKindOptions>>& room_kind_option_rows() {
  using K = RoomKindOptions;
  constexpr OptionRange kNonNegative = OptionRange::kNonNegative;
  static const std::vector<OptionRow<K>> rows = {
      field_row("corridor-openings", "N", OptionRange::kWholeNumber, &K::openings,
                "room kinds: a corridor has at least this many rooms beside it"),
      field_row("corridor-elongation", "F", kNonNegative, &K::elongation, "room kinds: and is at least this elongated"),
      field_row("corridor-width", "M", OptionRange::kLengthOrZero, &K::width, "room kinds: and at most this wide (metres; a home's corridor)"),
      field_row("hallway-elongation", "F", kNonNegative, &K::hallway_elongation,
                "room kinds: or at least this elongated (an office's hallway)"),
      field_row("kind-min-contact", "M", OptionRange::kLengthOrZero, &K::min_contact,
                "room kinds: a room touching another along less (metres) is not beside it"),
      field_row("kind-sample", "M", OptionRange::kLengthOrZero, &K::sample, "room kinds: shapes are measured every this many metres"),
  };
  return rows;
}

const std::vector<OptionRow<IncrementalOptions>>& incremental_option_rows() {
  using I = IncrementalOptions;
  constexpr OptionRange kNonNegative = OptionRange::kNonNegative;
  static const std::vector<OptionRow<I>> rows = {
      switch_row("windowed", &I::windowed, "update only the rooms a change touches (false: segment the whole map each update)"),
      field_row("absorb-area", "M2", OptionRange::kArea, &I::absorb_area,
                "a new blob touching one room joins it undecomposed within this allowance (m²)"),
      field_row("absorb-fraction", "F", kNonNegative, &I::absorb_fraction, "or within this share of the room's area"),
      switch_row("absorb-across-rooms", &I::absorb_across_rooms,
                 "a new blob where rooms already meet is absorbed too, each cell to the nearest of them"),
      field_row("speck-size", "M", OptionRange::kLengthOrZero, &I::speck_size,
                "obstacle specks up to this size (metres) leave a room undecomposed"),
      field_row("split-after", "N", OptionRange::kCount, &I::split_after,
                "decompositions in a row that must cut a room before it splits"),
      field_row("merge-after", "N", OptionRange::kCount, &I::merge_after,
                "decompositions in a row that must merge two rooms before they merge"),
      switch_row("neighbours-across-doors", &I::neighbours_across_doors,
                 "decompose a touched room's neighbours across doors with it"),
      switch_row("neighbours-across-cuts", &I::neighbours_across_cuts,
                 "decompose a touched room's neighbours across other cuts with it"),
      field_row("partial-area", "M2", OptionRange::kArea, &I::partial_area,
                "touched rooms larger than this (m²) are decomposed again only near the change (0: off)"),
      field_row("partial-margin", "M", OptionRange::kLength, &I::partial_margin, "how near the change (metres)"),
      field_row("batch-fraction", "F", OptionRange::kPositive, &I::batch_fraction,
                "share of changed free cells that makes an update a batch one"),
  };
  return rows;
}

}  // namespace topocut
