#pragma once
// Polygons -> labels: pieces (grid coordinates) become a label image, then every free cell that no
// piece covers takes the label of the nearest piece, so the whole free space is labelled.
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"

namespace topocut {

// Labels each cell whose centre (grid coordinates: x = column, y = rows-1-row) lies inside polygon
// i with i + 1 (CV_32SC1 of the given size, 0 elsewhere). Inside is even-odd over the outer ring
// and the holes, so keyhole rings work too. Centres on an edge follow a half-open rule (a centre on
// an edge belongs to the polygon to its right, or above it for a horizontal edge), so pieces that
// share a cut never both claim a cell; where polygons overlap anyway, the earlier one keeps it.
cv::Mat rasterize_polygons(const std::vector<PolygonWithHoles>& polygons, cv::Size size);

// A run of cells [first, end) of one image row whose centres polygon `index` contains.
struct CellSpan {
  int row = 0;
  int first = 0, end = 0;
  int index = 0;
};

// The spans rasterize_polygons() fills, polygon by polygon (each polygon's spans by row from the
// bottom up, then by column), clipped to the image; overlaps between polygons are not resolved.
std::vector<CellSpan> polygon_spans(const std::vector<PolygonWithHoles>& polygons, cv::Size size);

// The spans of some of the polygons, from polygon_spans() of them all: polygon i is kept as polygon
// new_index[i] (new_index ascending over the kept ones), or left out where new_index[i] < 0. The same
// as polygon_spans() of the kept polygons, without rasterizing them again.
std::vector<CellSpan> kept_spans(const std::vector<CellSpan>& spans, const std::vector<int>& new_index);

// Completes labels over the free space (free_mask CV_8UC1, nonzero = free): each unlabelled free cell
// takes the nearest label along free space (4-connected, so never through walls), or in a straight
// line where free space reaches no label; non-free cells become 0 unless keep_non_free (absorbed
// furniture keeps its room). changes, if given, receives every cell whose label changed (any order).
struct LabelChange {
  int index = 0;  // row * cols + column
  int before = 0, after = 0;
};
void fill_free_space_labels(cv::Mat& labels, const cv::Mat& free_mask, bool keep_non_free = false,
                            std::vector<LabelChange>* changes = nullptr);

// The second half of fill_free_space_labels, for callers that found the unlabelled free cells
// themselves: unlabelled lists them (row * cols + column, in raster order); each gets the label
// of the nearest labelled free cell along free space, or else in a straight line.
void complete_unlabelled_cells(cv::Mat& labels, const cv::Mat& free_mask, const std::vector<int>& unlabelled,
                               std::vector<LabelChange>* changes = nullptr);

}  // namespace topocut
