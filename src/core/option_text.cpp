#include "topocut/core/option_text.h"

#include <cmath>

#include "topocut/core/option_table.h"

namespace topocut {

Point2 parse_option_point(const std::string& text, const std::string& shown) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    throw Error(shown + " needs a point X,Y in metres, not '" + text + "'");
  const Point2 point{parse_option_number(text.substr(0, comma), shown + "'s X"),
                     parse_option_number(text.substr(comma + 1), shown + "'s Y")};
  if (!std::isfinite(point.x) || !std::isfinite(point.y)) throw Error(shown + " needs finite coordinates, not '" + text + "'");
  return point;
}

}  // namespace topocut
