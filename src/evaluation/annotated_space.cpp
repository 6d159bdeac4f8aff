#include "topocut/evaluation/annotated_space.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "evaluation/contingency.h"
#include "topocut/core/error.h"

namespace topocut {

double precision_inside_annotated(const cv::Mat& segment_labels, const cv::Mat& room_labels,
                                  const EvaluationOptions& options) {
  const cv::Mat rooms = detail::to_int_labels(room_labels, "ground-truth room label");
  cv::Mat clipped = detail::to_int_labels(segment_labels, "segmentation label").clone();
  if (clipped.size() == rooms.size()) clipped.setTo(0, rooms == 0);  // else precision_recall names the mismatch
  return precision_recall(clipped, rooms, options).precision;
}

double far_from_rooms_share(const cv::Mat& segment_labels, const cv::Mat& room_labels, double resolution,
                            const EvaluationOptions& options) {
  if (!std::isfinite(resolution) || resolution <= 0.0) throw Error("the resolution must be a positive number of metres");
  const cv::Mat segments = detail::to_int_labels(segment_labels, "segmentation label");
  const cv::Mat rooms = detail::to_int_labels(room_labels, "ground-truth room label");
  if (segments.size() != rooms.size()) throw Error("the segmentation and the ground truth differ in size");
  const cv::Mat labelled = segments > 0;
  const int total = cv::countNonZero(labelled);
  if (total == 0) return 0.0;
  const cv::Mat outside = rooms == 0;
  if (cv::countNonZero(rooms) == 0) return 1.0;  // no room at all: everything is far
  cv::Mat distance;  // pixels to the nearest room pixel
  cv::distanceTransform(outside, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const cv::Mat far = (distance > options.far_distance / resolution) & labelled;
  return static_cast<double>(cv::countNonZero(far)) / total;
}

}  // namespace topocut
