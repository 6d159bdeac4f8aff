// The exploration's option table (explorer.h): each field's name, unit, range and help once; the
// defaults are ExplorationOptions'. The start is a point given as text (exploration_text_rows()).
#include "topocut/core/option_table.h"
#include "topocut/core/option_text.h"
#include "topocut/exploration/exploration_run.h"
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
      field_row("seed", "N", OptionRange::kSeed, &E::seed, "start choice: 0 = the most open cell, else a random free cell"),
  };
  return rows;
}

const std::vector<TextRow<ExplorationOptions>>& exploration_text_rows() {
  static const std::vector<TextRow<ExplorationOptions>> rows = {
      text_row<ExplorationOptions>(
          "start", "X,Y", [](ExplorationOptions& e, const std::string& text) { e.start = parse_option_point(text, "--start"); },
          "start position X,Y in metres (overrides the seed)"),
  };
  return rows;
}

const std::vector<OptionRow<ExplorationRunOptions>>& exploration_run_option_rows() {
  static const std::vector<OptionRow<ExplorationRunOptions>> rows = {
      inverted_switch_row("no-hint", &ExplorationRunOptions::use_hint, "do not tell the segmenter which rectangle changed"),
  };
  return rows;
}

}  // namespace topocut
