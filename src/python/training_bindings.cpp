// Python: the rows the merge model is fitted on (scripts/train_merge_model.py).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/bindings.h"
#include "python/options.h"
#include "topocut/core/error.h"
#include "topocut/evaluation/merge_training.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/merge_features.h"

namespace topocut::python {
namespace {

py::tuple training_rows_py(const std::string& image, const std::string& ground_truth, double resolution, py::kwargs kwargs) {
  const SegmentOptions options = segment_options(kwargs);
  std::vector<MergeTrainingRow> rows;
  {
    py::gil_scoped_release release;
    MapLoadOptions load;
    load.resolution = resolution;
    const OccupancyGrid grid = load_map(image, load);
    // Its header is checked against the map's size before it is decoded.
    const ExpectedSize size{static_cast<std::uint64_t>(grid.width()), static_cast<std::uint64_t>(grid.height()), "the map"};
    const cv::Mat rooms = ground_truth_rooms(load_ground_truth(ground_truth, {}, &size));
    rows = merge_training_rows(grid, rooms, options);
  }
  const std::size_t n = rows.size(), f = merge_feature_names().size();
  py::array_t<double> features({n, f});
  py::array_t<bool> same(n);
  py::array_t<double> weight(n), probability(n);
  auto x = features.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < f; ++j) x(i, j) = rows[i].features[j];
    same.mutable_at(i) = rows[i].same_room;
    weight.mutable_at(i) = rows[i].weight;
    probability.mutable_at(i) = rows[i].probability;
  }
  return py::make_tuple(features, same, weight, probability);
}

}  // namespace

void bind_training(py::module_& m) {
  m.def("merge_feature_names", &merge_feature_names, "The merge model's feature names, in the order of merge_training_rows' columns.");
  m.def("merge_training_rows", &training_rows_py, py::arg("image"), py::arg("ground_truth"), py::arg("resolution") = 0.05,
        "merge_training_rows(image, ground_truth, resolution=0.05, **segment options) -> (features, same_room, weight, "
        "probability)\n\n"
        "Every candidate merge the segmenter weighs on the map image, labelled by the Bormann-format ground truth\n"
        "beside it: features (n x len(merge_feature_names())), same_room (both rooms mostly in one room of\n"
        "people's), weight (the two sides' shares of their main rooms multiplied) and the probability the\n"
        "merging model gave. merge_model='...' (a model's text) drives the merging; a threshold above 1 records\n"
        "the first candidates only. Used by scripts/train_merge_model.py.");
}

}  // namespace topocut::python
