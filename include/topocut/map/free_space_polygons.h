#pragma once
// Contours -> polygons: every connected component of free space becomes one polygon with holes
// whose rings follow the pixel edges exactly (so its area is its pixel count), in grid coordinates
// (x = column, y = height-1-row, cell centres at integers: vertices lie on half-integers).
#include <functional>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"
#include "topocut/core/option_table.h"

namespace topocut {

struct ContourOptions {
  // Components smaller than this (m²) are not traced; their cells are labelled later with the
  // nearest room. If no component reaches it, the largest one is kept so free space always yields
  // a room. The default, 0.25 m² (100 cells at 0.05 m), matches the evaluation's 100-pixel floor.
  double min_component_area = 0.25;
  // Holes (obstacles inside free space) smaller than this (m²) are filled in: the polygon covers
  // them (their cells stay unlabelled, being no free space). The reference wrapper drops holes of
  // at most 5 px²; 0.0125 m² is 5 cells at 0.05 m. Holes that contain free islands are kept.
  double min_hole_area = 0.0125;
};

// The fields of ContourOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<ContourOptions>>& contour_option_rows();

struct FreeSpaceComponent {
  PolygonWithHoles polygon;  // grid coordinates; outer ring CCW, holes CW; no collinear vertices
  int pixel_count = 0;       // free cells of the component
  std::vector<int> hole_cells;  // per hole: its non-free cells (its ring encloses more if free islands lie inside)
  cv::Point first_pixel;     // (column, row) of its first cell in raster order
};

struct FreeSpacePolygons {
  std::vector<FreeSpaceComponent> components;  // kept components, in raster order of first_pixel
  long kept_cells = 0;     // free cells of the kept components
  int pinch_cells = 0;     // free cells removed to break diagonal pinch points
  int dropped_components = 0;
  int dropped_holes = 0;
};

// Removes free cells until no 2x2 block is a checkerboard (two free cells touching only at a
// corner). Such corners make pixel-edge rings touch themselves; after this, 4- and 8-connectivity
// agree and every ring is simple. Deterministic: of the two free cells the one with fewer free
// 8-neighbours goes (ties: the upper one). Returns the new mask (CV_8UC1, 255 free).
cv::Mat remove_diagonal_pinches(const cv::Mat& free_mask, int* removed = nullptr);

// Traces every connected component of a pinch-free mask (CV_8UC1, nonzero = free) as an exact
// pixel-edge polygon with all its holes, in raster order of the components' first cells. The ring
// of a one-cell component is that cell's square.
std::vector<FreeSpaceComponent> trace_components(const cv::Mat& pinch_free_mask);

// Free-space mask -> polygons: removes pinches, traces, drops small components and holes (areas in
// m² at the given resolution). Throws Error on an empty or non-8-bit mask or a bad resolution.
FreeSpacePolygons free_space_polygons(const cv::Mat& free_mask, double resolution, const ContourOptions& options = {});

// Drops vertices where the ring goes straight on (and repeated vertices); exact comparisons. A
// vertex for which keep returns true stays even there (e.g. where a cut ends on a straight wall).
Ring remove_collinear_vertices(const Ring& ring, const std::function<bool(const Point2&)>& keep = nullptr);

}  // namespace topocut
