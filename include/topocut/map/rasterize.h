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

// Completes labels over the free space (free_mask CV_8UC1, nonzero = free): non-free cells become
// 0; each unlabelled free cell takes the label of the nearest labelled cell measured along the free
// space (4-connected breadth-first search, so labels never leak through walls), and cells that
// free space does not connect to any label take the label of the nearest labelled cell in a
// straight line. Cells stay 0 only when there is no label at all.
void fill_free_space_labels(cv::Mat& labels, const cv::Mat& free_mask);

}  // namespace topocut
