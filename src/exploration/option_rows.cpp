// The exploration's option table (explorer.h): each field's name, unit, range and help once; the
// defaults are ExplorationOptions'. The start (a point) and the seed (32 bits) are the explore
// command's own.
#include "topocut/core/option_table.h"
#include "topocut/exploration/explorer.h"

namespace topocut {

const std::vector<OptionRow<ExplorationOptions>>& exploration_option_rows() {
  using E = ExplorationOptions;
  static const std::vector<OptionRow<E>> rows = {
      field_row("range", "M", OptionRange::kLength, &E::range, "laser range in metres (360°, 1° beams)"),
      field_row("step", "M", OptionRange::kLength, &E::step, "metres walked between scans"),
      field_row("max-scans", "N", OptionRange::kCount, &E::max_scans, "stop after this many scans"),
      field_row("min-frontier", "M", OptionRange::kLengthOrZero, &E::min_frontier, "ignore frontiers shorter than this (metres)"),
      switch_row("grow", &E::growing_map, "publish a map that grows with what was seen (new size and origin), as ROS does"),
      field_row("growth-margin", "M", OptionRange::kLength, &E::growth_margin,
                "with --grow: metres of unknown kept around the seen cells"),
  };
  return rows;
}

}  // namespace topocut
