#include "topocut/lines/lines_format.h"

#include <charconv>

#include <nlohmann/json.hpp>

namespace topocut {

namespace {

void append_number(std::string& out, double value) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, r.ptr);
}

}  // namespace

std::string format_lines_json(const std::vector<Line>& lines) {
  // ordered_json keeps the keys in the order DESIGN.md lists them.
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const Line& line : lines) {
    array.push_back({{"rho", line.rho},
                     {"alpha", line.alpha},
                     {"start", {line.start.x, line.start.y}},
                     {"end", {line.end.x, line.end.y}},
                     {"support", line.support}});
  }
  return array.dump() + "\n";
}

std::string format_lines_csv(const std::vector<Line>& lines) {
  std::string out = "rho,alpha,start_x,start_y,end_x,end_y,support\n";
  for (const Line& line : lines) {
    for (const double v : {line.rho, line.alpha, line.start.x, line.start.y, line.end.x, line.end.y}) {
      append_number(out, v);
      out.push_back(',');
    }
    for (std::size_t k = 0; k < line.support.size(); ++k) {
      if (k > 0) out.push_back(' ');
      out += std::to_string(line.support[k]);
    }
    out.push_back('\n');
  }
  return out;
}

}  // namespace topocut
