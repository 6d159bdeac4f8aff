#pragma once
// The parts of the Python module, each adding its functions and classes to the module.
#include <optional>

#include <opencv2/core.hpp>
#include <pybind11/pybind11.h>

namespace topocut::python {

void bind_segmentation(pybind11::module_& m);  // segment, load_map, IncrementalSegmenter, results
void bind_geometry(pybind11::module_& m);      // decompose, line extractors
void bind_evaluation(pybind11::module_& m);    // evaluate and its Scores
void bind_training(pybind11::module_& m);      // merge_feature_names, merge_training_rows
void bind_simulation(pybind11::module_& m);    // simulate_map
void bind_keywords(pybind11::module_& m);      // _keywords: the keyword arguments as data

// The labels of a Segmentation, rows top-down (as image files hold them), when labels is a
// Segmentation or exactly the labels array segment() returned (not a copy, slice or flip of it):
// those know their grid's row order. nullopt for anything else.
std::optional<cv::Mat> segment_labels_top_down(const pybind11::handle& labels);

}  // namespace topocut::python
