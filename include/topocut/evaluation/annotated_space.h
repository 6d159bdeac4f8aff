#pragma once
// Scores for maps registered onto another map's ground truth (DESIGN.md, Evaluation): a raw SLAM map
// resampled into the frame of a cleaned map sees free cells that no annotator covered (a band along
// the walls, local misregistration), which pull the plain precision down whatever the rooms. Clipping
// the segments to the annotated space measures the rooms themselves; the far share says how much of
// the labelled space the annotation does not reach at all. On a map drawn with its own ground truth
// both are about the plain figures, so every set reports them.
#include <opencv2/core.hpp>

#include "topocut/evaluation/precision_recall.h"

namespace topocut {

// Bormann's precision with every segment first clipped to the union of the ground-truth rooms (all
// room pixels, room_labels > 0): segments of at most max_ignored_pixels after clipping are ignored.
// Inputs as for precision_recall(); throws Error as it does.
double precision_inside_annotated(const cv::Mat& segment_labels, const cv::Mat& room_labels,
                                  const EvaluationOptions& options = {});

// The share of labelled pixels (segment label > 0) farther than options.far_distance metres from every
// ground-truth room pixel (Euclidean distance between pixel centres at resolution metres per pixel);
// 0 when nothing is labelled. Throws Error on a bad image, a size mismatch or a resolution <= 0.
double far_from_rooms_share(const cv::Mat& segment_labels, const cv::Mat& room_labels, double resolution,
                            const EvaluationOptions& options = {});

}  // namespace topocut
