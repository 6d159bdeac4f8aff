#pragma once
// The ranges of numbers the library accepts, chosen so that the geometry stays exact enough in
// doubles and every output finite (docs/limits.md). Values outside are refused with the range in
// the message, never carried on into a JSON null, an infinite SVG or an empty decomposition.
#include <string>

namespace topocut {

// Metres per cell. Below: coordinates would vanish in the outputs' micrometre rounding; above: a
// map of OpenCV's largest width (2^20 cells) would no longer fit in kMaxWorldCoordinate.
inline constexpr double kMinResolution = 1e-4;
inline constexpr double kMaxResolution = 1e3;
// |x|, |y| of a map origin or pose in metres: micrometres of such a coordinate are exact in a double
// (1e9 m · 1e6 < 2^53), with room for a map's extent on top.
inline constexpr double kMaxWorldCoordinate = 1e9;
// Any length option in metres (τ, radii, widths): divided by the finest resolution it stays below
// 2^31 cells, so converting it to an integer number of cells is defined.
inline constexpr double kMaxLength = 1e5;
// decompose's polygons, in their own units: |coordinate| at most 1e12 keeps every product the
// decomposition forms (areas, cross products) far from overflow, and an extent (bounding box width
// or height) of at least 1e-6 keeps its fixed tolerance (1e-8) at most 1 % of the polygon.
inline constexpr double kMaxPolygonCoordinate = 1e12;
inline constexpr double kMinPolygonExtent = 1e-6;

// Each throws Error "<what> must lie in [lo, hi] <unit>, got <value>" for a value out of range (NaN too).
void check_resolution(double metres_per_cell, const std::string& what);
void check_world_coordinate(double metres, const std::string& what);
void check_length(double metres, const std::string& what, bool zero_allowed = true);
void check_area(double square_metres, const std::string& what);

}  // namespace topocut
