#include "topocut/evaluation/comparison_pictures.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "evaluation/contingency.h"
#include "topocut/core/error.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/io/overlay.h"

namespace topocut {
namespace {

const cv::Vec3b kMissed(40, 40, 220);   // red (BGR)
const cv::Vec3b kMerged(0, 140, 255);   // orange
const cv::Vec3b kSmall(225, 215, 205);  // regions too small to count

cv::Vec3b mixed(const cv::Vec3b& a, const cv::Vec3b& b, double share_of_b) {
  cv::Vec3b out;
  for (int k = 0; k < 3; ++k) out[k] = cv::saturate_cast<unsigned char>((1.0 - share_of_b) * a[k] + share_of_b * b[k]);
  return out;
}

// The map in greys: free light, unknown mid, occupied dark.
cv::Mat background(const cv::Mat& cells) {
  cv::Mat out(cells.size(), CV_8UC3);
  for (int r = 0; r < cells.rows; ++r)
    for (int c = 0; c < cells.cols; ++c) {
      const unsigned char v = cells.at<unsigned char>(r, c);
      const unsigned char grey = v == kFree ? 248 : v == kOccupied ? 45 : 185;
      out.at<cv::Vec3b>(r, c) = {grey, grey, grey};
    }
  return out;
}

// Fills every labelled pixel with colour(label); hatch(label) adds diagonal stripes of that colour
// and a border of it (two pixels wide after scaling) where the label ends.
template <typename Colour, typename Hatch>
void paint(cv::Mat& picture, const cv::Mat& labels, int scale, Colour colour, Hatch hatch) {
  const auto label = [&](int r, int c) { return labels.at<int>(r / scale, c / scale); };
  for (int r = 0; r < picture.rows; ++r)
    for (int c = 0; c < picture.cols; ++c) {
      const int id = label(r, c);
      if (id <= 0) continue;
      cv::Vec3b& pixel = picture.at<cv::Vec3b>(r, c);
      pixel = colour(id);
      bool edge = false;
      for (int dr = -2; dr <= 2 && !edge; ++dr)
        for (int dc = -2; dc <= 2 && !edge; ++dc) {
          const int rr = r + dr, cc = c + dc;
          edge = rr < 0 || cc < 0 || rr >= picture.rows || cc >= picture.cols || label(rr, cc) != id;
        }
      const bool thin_edge = edge && (r == 0 || c == 0 || label(r - 1, c) != id || label(r, c - 1) != id ||
                                      r + 1 == picture.rows || c + 1 == picture.cols || label(r + 1, c) != id || label(r, c + 1) != id);
      const cv::Vec3b* mark = hatch(id);
      if (mark && (edge || (r + c) % 10 < 2)) {
        pixel = *mark;
      } else if (thin_edge) {
        pixel = mixed(pixel, {0, 0, 0}, 0.45);
      }
    }
}

cv::Mat scaled(const cv::Mat& image, int scale) {
  if (scale == 1) return image;
  cv::Mat out;
  cv::resize(image, out, cv::Size(), scale, scale, cv::INTER_NEAREST);
  return out;
}

}  // namespace

ComparisonPictures comparison_pictures(const cv::Mat& segment_labels, const cv::Mat& room_labels, const cv::Mat& map_cells,
                                       const EvaluationOptions& options, int min_side) {
  if (map_cells.type() != CV_8UC1 || map_cells.size() != segment_labels.size())
    throw Error("the map for the comparison pictures must be one 8-bit channel of the labels' size");
  ComparisonPictures out;
  out.outcomes = room_outcomes(segment_labels, room_labels, map_cells == kFree, options);
  const RoomOutcomes& o = out.outcomes;
  const int longer = std::max(map_cells.cols, map_cells.rows);
  const int scale = std::clamp((min_side + longer - 1) / longer, 1, 4);
  const cv::Mat segments = detail::to_int_labels(segment_labels, "segmentation label");
  const cv::Mat rooms = detail::to_int_labels(room_labels, "ground-truth room label");
  const cv::Mat map = scaled(background(map_cells), scale);

  // A matched pair shares its room's colour; unmatched segments get paler colours of their own.
  out.truth = map.clone();
  paint(out.truth, rooms, scale,
        [&](int id) {
          const auto found = o.room_match.find(id);
          if (found == o.room_match.end()) return kSmall;
          return found->second > 0 ? room_colour(id) : cv::Vec3b(255, 255, 255);
        },
        [&](int id) -> const cv::Vec3b* {
          const auto found = o.room_match.find(id);
          return found != o.room_match.end() && found->second == 0 ? &kMissed : nullptr;
        });
  out.segments = map.clone();
  paint(out.segments, segments, scale,
        [&](int id) {
          const auto found = o.segment_match.find(id);
          if (found == o.segment_match.end()) return kSmall;
          return found->second > 0 ? room_colour(found->second) : mixed(room_colour(id + 7919), {235, 235, 235}, 0.6);
        },
        [&](int id) -> const cv::Vec3b* { return o.merges.count(id) ? &kMerged : nullptr; });
  return out;
}

}  // namespace topocut
