// The map module's option tables (binarize.h, free_space_cleaning.h, free_space_polygons.h): each
// field's name, unit, range and help once; defaults are the structs' own.
#include "topocut/core/option_table.h"
#include "topocut/map/binarize.h"
#include "topocut/map/free_space_cleaning.h"
#include "topocut/map/free_space_polygons.h"

namespace topocut {

const std::vector<OptionRow<BinarizeOptions>>& binarize_option_rows() {
  using B = BinarizeOptions;
  static const std::vector<OptionRow<B>> rows = {
      field_row("robot-radius", "M", OptionRange::kLengthOrZero, &B::robot_radius,
                "inflate obstacles by this radius in metres before decomposing (0: raw free space)"),
      switch_row("inflate-unknown", &B::inflate_unknown, "with --robot-radius, inflate unknown cells too (a cautious robot)"),
      field_row("opening", "M", OptionRange::kLengthOrZero, &B::opening_size,
                "open the free space with a square of this side in metres (drops single-ray spurs; 0: off)"),
      field_row("median", "M", OptionRange::kLengthOrZero, &B::median_size,
                "median-filter the free space with a square window of this side in metres (0: off)"),
  };
  return rows;
}

const std::vector<OptionRow<FreeSpaceCleaningOptions>>& cleaning_option_rows() {
  using C = FreeSpaceCleaningOptions;
  static const std::vector<OptionRow<C>> rows = {
      field_row("max-obstacle-speck", "M", OptionRange::kLengthOrZero, &C::max_obstacle_speck,
                "cleaning: obstacles enclosed by free space at most this long both ways (metres) are floor (0: keep all)"),
      field_row("thin-width", "M", OptionRange::kLengthOrZero, &C::min_width,
                "cleaning: free space thinner than a quarter of this width (metres) bordered mostly by unknown is a ray, "
                "removed (0: off)"),
      field_row("inside-closing", "M", OptionRange::kLengthOrZero, &C::inside_closing,
                "cleaning: gaps up to this wide (metres) are closed to tell inside from outside the building (0: all outside)"),
  };
  return rows;
}

const std::vector<OptionRow<ContourOptions>>& contour_option_rows() {
  using C = ContourOptions;
  static const std::vector<OptionRow<C>> rows = {
      field_row("min-room-area", "M2", OptionRange::kArea, &C::min_component_area,
                "free-space components smaller than this (m²) are not rooms; their cells join the nearest room"),
      field_row("min-hole-area", "M2", OptionRange::kArea, &C::min_hole_area,
                "obstacles inside free space smaller than this (m²) are ignored by the decomposition"),
  };
  return rows;
}

}  // namespace topocut
