#pragma once
// Sparse connected-component labeling of 2-D points (Ravankar et al., "A connected component
// labeling algorithm for sparse lidar data segmentation", ICARA 2015): points are rasterized at a
// cell size, the occupied cells are dilated with a structuring element, the dilated image is
// labelled by connected components, and each point takes the label of its cell. Points never move
// and cells that hold no point never become points: dilation only decides which points belong
// together.
#include <span>
#include <string>
#include <vector>

#include "topocut/core/geometry.h"
#include "topocut/core/option_choice.h"
#include "topocut/core/option_table.h"
#include "topocut/scan/scan.h"

namespace topocut {

// The 3×3 element applied `dilation` times: a cross grows an L1 diamond, a square an L∞ square.
enum class StructuringElement { kCross, kSquare };

// Two ways to the same answer. kRaster is the paper's method literally (a binary image of the
// points' bounding box, cv::dilate, cv::connectedComponents). kSparse touches only occupied cells:
// it joins two cells exactly when their dilated footprints overlap or touch under the chosen
// connectivity, which is what the raster labeling decides, without the image.
enum class LabelingMethod { kSparse, kRaster };

struct LabelingOptions {
  double cell_size = 0.05;  // metres per raster cell
  int dilation = 1;         // iterations of the 3×3 structuring element (0: no dilation)
  StructuringElement element = StructuringElement::kCross;
  int connectivity = 8;     // 4 or 8, as cv::connectedComponents
  LabelingMethod method = LabelingMethod::kSparse;
};

struct Labeling {
  // Per input point: its segment index (0-based), or -1 for a point with a non-finite coordinate.
  std::vector<int> labels;
  // Per segment: the indices of its points, ascending. Segments are ordered by their first point,
  // so a scan's segments come in beam order.
  std::vector<std::vector<int>> segments;
};

// Labels the points into segments as described above; every finite point is in exactly one
// segment. The result does not depend on options.method. Throws Error on invalid options
// (cell size not positive and finite, negative dilation, connectivity other than 4 or 8) or when
// the points span more cells than can be indexed (raster: more than 2^28 cells in the box).
Labeling label_points(std::span<const Point2> points, const LabelingOptions& options = {});

// Labels the valid beams of a scan as sensor-frame points; labels are per beam (row of the scan),
// -1 for invalid beams (Scan::is_valid). Throws Error as label_points and on an invalid scan.
Labeling label_scan(const Scan& scan, const LabelingOptions& options = {});

// The labeling options as people give them (the label and walls commands): cell, dilate,
// connectivity; the element is chosen by name (labeling_choice_rows()). Defined in option_rows.cpp.
const std::vector<OptionRow<LabelingOptions>>& labeling_option_rows();

// The labeling option chosen by name: --element cross|square (option_choice.h).
const std::vector<ChoiceRow<LabelingOptions>>& labeling_choice_rows();

}  // namespace topocut
