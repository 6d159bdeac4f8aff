#pragma once
// Hand-made label images for the id tests, drawn as text.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace topocut::testing {

// A label image (CV_32SC1) of one row per string, one cell per character ('0' = no room).
inline cv::Mat labels_of(const std::vector<std::string>& rows) {
  cv::Mat out(static_cast<int>(rows.size()), static_cast<int>(rows[0].size()), CV_32SC1);
  for (int r = 0; r < out.rows; ++r)
    for (int c = 0; c < out.cols; ++c) out.at<int>(r, c) = rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] - '0';
  return out;
}

}  // namespace topocut::testing
