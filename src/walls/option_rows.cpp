// The walls module's option table (walls_pipeline.h): each field's name, unit, range and help once;
// defaults are the structs' own.
#include "topocut/labeling/sparse_labeling.h"
#include "topocut/walls/walls_pipeline.h"

namespace topocut {

const std::vector<OptionRow<WallsOptions>>& walls_option_rows() {
  using W = WallsOptions;
  static const std::vector<OptionRow<W>> rows = [] {
    std::vector<OptionRow<W>> all = {
        field_row("resolution", "M", OptionRange::kResolution, &W::map, &WallMapOptions::resolution,
                  "grid resolution in metres per cell"),
        field_row("thickness", "M", OptionRange::kLengthOrZero, &W::map, &WallMapOptions::wall_thickness,
                  "wall thickness in metres"),
    };
    for (OptionRow<W>& row : rows_within<W>(labeling_option_rows(), [](auto& w) -> auto& { return w.extraction.labeling; }))
      all.push_back(std::move(row));
    return all;
  }();
  return rows;
}

}  // namespace topocut
