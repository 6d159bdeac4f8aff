#include "topocut/core/grid_array_options.h"

namespace topocut {

const std::vector<OptionRow<GridArray>>& occupancy_threshold_rows() {
  using G = GridArray;
  static const std::vector<OptionRow<G>> rows = {
      field_row("free-thresh", "P", OptionRange::kShare, &G::free_thresh,
                "occupancy grids (map_server's rule): a cell is free below this occupancy"),
      field_row("occupied-thresh", "P", OptionRange::kShare, &G::occupied_thresh,
                "occupancy grids: a cell is occupied above this occupancy (between the two: unknown)"),
  };
  return rows;
}

const std::vector<OptionRow<GridArray>>& grid_array_option_rows() {
  static const std::vector<OptionRow<GridArray>> rows = [] {
    std::vector<OptionRow<GridArray>> all = occupancy_threshold_rows();
    for (OptionRow<GridArray>& row : grey_threshold_rows<GridArray>()) all.push_back(std::move(row));
    return all;
  }();
  return rows;
}

}  // namespace topocut
