#pragma once
// Lines as text (DESIGN.md "Data formats"): JSON
// [{"rho":…, "alpha":…, "start":[x,y], "end":[x,y], "support":[i,…]}, …] and a CSV with one line per
// row, `rho,alpha,start_x,start_y,end_x,end_y,support` (support rows separated by spaces).
#include <string>
#include <vector>

#include "topocut/lines/line.h"

namespace topocut {

// JSON array of the lines (numbers with round-trip precision), ending in a newline.
std::string format_lines_json(const std::vector<Line>& lines);

// CSV with a header row, one line per row.
std::string format_lines_csv(const std::vector<Line>& lines);

}  // namespace topocut
