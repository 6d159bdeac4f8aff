#pragma once
// The connected parts of a mask, found on its row runs: what cv::connectedComponentsWithStats gives as
// labels and areas, for a cost in the mask's runs rather than its cells (on a small robot-made home,
// OpenCV's labelling of one room's box cost more than the rest of the row that asked for it).
#include <vector>

#include <opencv2/core.hpp>

namespace topocut {

// The 8-connected (else 4-connected) parts of mask's nonzero cells (CV_8UC1) as labels (CV_32SC1, of
// mask's size) numbering them 1.. in the raster order of their first cell, 0 elsewhere; sizes receives
// each part's cell count (index: its label - 1). Throws Error on an empty or non-8-bit mask.
cv::Mat cell_components(const cv::Mat& mask, bool eight_connected, std::vector<long long>& sizes);

}  // namespace topocut
