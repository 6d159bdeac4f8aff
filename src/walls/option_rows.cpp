// The walls module's option tables (wall_map.h, walls_pipeline.h): each field's name, unit, range and
// help once; defaults are the structs' own.
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/walls/walls_pipeline.h"

namespace topocut {

const std::vector<OptionRow<WallMapOptions>>& wall_map_option_rows() {
  using M = WallMapOptions;
  constexpr OptionRange kLengthOrZero = OptionRange::kLengthOrZero;
  static const std::vector<OptionRow<M>> rows = {
      field_row("resolution", "M", OptionRange::kResolution, &M::resolution, "grid resolution in metres per cell"),
      field_row("thickness", "M", kLengthOrZero, &M::wall_thickness, "wall thickness in metres"),
      field_row("no-return-range", "M", kLengthOrZero, &M::no_return_free_range,
                "beams without a return are traced as free this far (metres; glass gives none either; 0: not at all)"),
      field_row("free-range", "M", kLengthOrZero, &M::max_free_range,
                "hits farther than this (metres) are traced as free only up to it (their bearing error grows)"),
      field_row("margin", "M", kLengthOrZero, &M::margin, "metres of unknown around everything seen"),
  };
  return rows;
}

const std::vector<OptionRow<WallsOptions>>& walls_option_rows() {
  using W = WallsOptions;
  static const std::vector<OptionRow<W>> rows = [] {
    std::vector<OptionRow<W>> all = rows_within<W>(wall_map_option_rows(), [](auto& w) -> auto& { return w.map; });
    for (OptionRow<W>& row : rows_within<W>(labeling_option_rows(), [](auto& w) -> auto& { return w.extraction.labeling; }))
      all.push_back(std::move(row));
    return all;
  }();
  return rows;
}

}  // namespace topocut
