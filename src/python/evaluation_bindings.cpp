// evaluate(): every score of a segmentation against a ground truth, as `topocut evaluate` reports it.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/bindings.h"
#include "topocut/core/error.h"
#include "topocut/evaluation/region_labels.h"
#include "topocut/evaluation/segmentation_scores.h"
#include "topocut/io/map_loader.h"

namespace topocut::python {
namespace {

namespace py = pybind11;

std::string dtype_name(const py::array& a) { return py::str(static_cast<py::object>(a.dtype())).cast<std::string>(); }

// A 2-D array of integers or booleans as CV_32SC1 (a copy); name is the argument's name for errors.
cv::Mat int_image(const py::array& a, const std::string& name) {
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'b') throw Error(name + " must hold integers, got dtype " + dtype_name(a));
  if (a.ndim() != 2) throw Error(name + " must be a 2-D array (rows, columns), got " + std::to_string(a.ndim()) + " dimensions");
  if (a.shape(0) == 0 || a.shape(1) == 0) throw Error(name + " is empty");
  if (a.shape(0) > (1 << 30) || a.shape(1) > (1 << 30)) throw Error(name + " is too large");
  const auto values = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!values) throw Error(name + " cannot be read as integers");
  cv::Mat image(static_cast<int>(a.shape(0)), static_cast<int>(a.shape(1)), CV_32SC1);
  const std::int64_t* in = values.data();
  for (int r = 0; r < image.rows; ++r) {
    int* out = image.ptr<int>(r);
    for (int c = 0; c < image.cols; ++c, ++in) {
      if (*in < 0 || *in > std::numeric_limits<int>::max()) throw Error(name + " holds a value outside 0..2^31-1");
      out[c] = static_cast<int>(*in);
    }
  }
  return image;
}

cv::Mat labels_from(const py::object& labels) {
  if (py::isinstance<py::str>(labels)) return read_region_labels(labels.cast<std::string>());
  if (std::optional<cv::Mat> own = segment_labels_top_down(labels)) return *own;  // segment()'s: its row order known
  return int_image(py::array::ensure(labels), "labels");
}

cv::Mat ground_truth_from(const py::object& ground_truth) {
  if (py::isinstance<py::str>(ground_truth)) return load_ground_truth(ground_truth.cast<std::string>());
  const py::array a = py::array::ensure(ground_truth);
  if (!a || a.dtype().kind() != 'u' || a.dtype().itemsize() != 1)
    throw Error("ground_truth must be a path or a uint8 grey image (pixels above 250 are free)");
  cv::Mat grey;
  int_image(a, "ground_truth").convertTo(grey, CV_8U);
  return grey;
}

// The free-pixel mask (empty: every pixel) and the resolution to score at.
std::pair<cv::Mat, double> free_from(const py::object& free, double resolution) {
  if (free.is_none()) return {cv::Mat(), resolution};
  if (py::isinstance<py::str>(free)) {
    MapLoadOptions load;
    load.resolution = resolution;
    const OccupancyGrid grid = load_map(free.cast<std::string>(), load);
    return {grid.cells == kFree, grid.resolution};  // a YAML's own resolution wins, as in the CLI
  }
  return {int_image(py::array::ensure(free), "free") != 0, resolution};
}

SegmentationScores evaluate_py(const py::object& labels, const py::object& ground_truth, const py::object& free,
                               double resolution, bool clip_to_free) {
  cv::Mat segments = labels_from(labels);
  const cv::Mat rooms = ground_truth_rooms(ground_truth_from(ground_truth));
  const auto [mask, scale] = free_from(free, resolution);
  py::gil_scoped_release release;
  if (clip_to_free && !mask.empty()) {
    if (mask.size() != segments.size()) throw Error("free and labels differ in shape");
    segments.setTo(0, mask == 0);
  }
  return score_segmentation(segments, rooms, mask, scale);
}

// Pickle state of Scores: every field, in declaration order.
py::tuple scores_state(const SegmentationScores& s) {
  const PrecisionRecall& o = s.overlap;
  const MatchedRooms& m = s.matched;
  return py::make_tuple(py::make_tuple(o.precision, o.recall, o.segments, o.rooms, o.segment_precision, o.room_recall),
                        py::make_tuple(m.segments, m.rooms, m.matches, m.false_positives, m.false_negatives, m.iou_sum, m.f1,
                                       m.pq, m.segments_per_room),
                        s.precision_inside, s.far_share);
}

SegmentationScores scores_from(const py::tuple& t) {
  if (t.size() != 4) throw std::runtime_error("not a topocut.Scores state");
  const auto o = t[0].cast<py::tuple>();
  const auto m = t[1].cast<py::tuple>();
  SegmentationScores s;
  s.overlap = {o[0].cast<double>(), o[1].cast<double>(), o[2].cast<int>(), o[3].cast<int>(),
               o[4].cast<std::vector<double>>(), o[5].cast<std::vector<double>>()};
  s.matched = {m[0].cast<int>(), m[1].cast<int>(), m[2].cast<int>(), m[3].cast<int>(), m[4].cast<int>(),
               m[5].cast<double>(), m[6].cast<double>(), m[7].cast<double>(), m[8].cast<double>()};
  s.precision_inside = t[2].cast<double>();
  s.far_share = t[3].cast<double>();
  return s;
}

}  // namespace

void bind_evaluation(py::module_& m) {
  py::class_<SegmentationScores>(m, "Scores", "A segmentation scored against a ground truth (fractions in [0, 1]).")
      .def_property_readonly("recall", [](const SegmentationScores& s) { return s.overlap.recall; },
                             "Bormann's recall: mean over rooms R of max_S |S ∩ R| / |R|")
      .def_property_readonly("precision", [](const SegmentationScores& s) { return s.overlap.precision; },
                             "Bormann's precision: mean over segments S of max_R |S ∩ R| / |S|")
      .def_property_readonly("segments", [](const SegmentationScores& s) { return s.overlap.segments; },
                             "segments of more than 100 px (precision's)")
      .def_property_readonly("rooms", [](const SegmentationScores& s) { return s.overlap.rooms; },
                             "ground-truth rooms of more than 100 px (recall's)")
      .def_property_readonly("f1", [](const SegmentationScores& s) { return s.matched.f1; },
                             "matched rooms: TP / (TP + (FP + FN) / 2)")
      .def_property_readonly("pq", [](const SegmentationScores& s) { return s.matched.pq; },
                             "panoptic quality: sum of the matches' IoU / (TP + (FP + FN) / 2)")
      .def_property_readonly("matches", [](const SegmentationScores& s) { return s.matched.matches; },
                             "TP: segment-room pairs with IoU above 0.5 over the free pixels")
      .def_property_readonly("false_positives", [](const SegmentationScores& s) { return s.matched.false_positives; })
      .def_property_readonly("false_negatives", [](const SegmentationScores& s) { return s.matched.false_negatives; })
      .def_property_readonly("free_segments", [](const SegmentationScores& s) { return s.matched.segments; },
                             "segments of more than 100 free pixels")
      .def_property_readonly("free_rooms", [](const SegmentationScores& s) { return s.matched.rooms; },
                             "ground-truth rooms of more than 100 free pixels")
      .def_property_readonly("segments_per_room", [](const SegmentationScores& s) { return s.matched.segments_per_room; },
                             "free_segments / free_rooms")
      .def_property_readonly("precision_inside", [](const SegmentationScores& s) { return s.precision_inside; },
                             "precision with every segment clipped to the ground truth's rooms")
      .def_property_readonly("far_share", [](const SegmentationScores& s) { return s.far_share; },
                             "share of labelled pixels more than 0.5 m from every ground-truth room")
      .def("__repr__", [](const SegmentationScores& s) {
        return "<topocut.Scores recall " + std::to_string(s.overlap.recall) + ", precision " +
               std::to_string(s.overlap.precision) + ", f1 " + std::to_string(s.matched.f1) + ", pq " +
               std::to_string(s.matched.pq) + ">";
      })
      .def(py::pickle(&scores_state, &scores_from));
  m.def("evaluate", &evaluate_py, py::arg("labels"), py::arg("ground_truth"), py::arg("free") = py::none(),
        py::arg("resolution") = 0.05, py::arg("clip_to_free") = true,
        "Scores a segmentation against a ground truth as `topocut evaluate` does; returns Scores.\n\n"
        "labels: 2-D integer array (0 no room, else a region) or the path of a label image (one grey or\n"
        "16-bit value a region, or one colour a region, black none). ground_truth: the path of a\n"
        "Bormann-style ground truth (X_gt_segmentation.png) or its uint8 grey image: pixels above 250\n"
        "are free and split into rooms by 8-connected flood fill. free: None (every pixel counts), a 2-D\n"
        "array (non-zero = free) or the path of the map image, loaded as the topocut command loads it\n"
        "(its free cells; a YAML's resolution wins). Matched rooms count only free pixels. clip_to_free:\n"
        "clear the labels off the non-free pixels first, for every score, as `topocut evaluate --labels`\n"
        "does with another tool's images; False scores them as given, as `topocut evaluate` scores its\n"
        "own segmentation (whose rooms also cover the small obstacles they absorb) for recall and\n"
        "precision. resolution: metres per pixel, for the far share. All images share one shape and\n"
        "are read with row 0 on top, as image files hold them, except a Segmentation or its labels array\n"
        "exactly as segment() returned it: that knows its row order (a ROS grid's is bottom-up) and is\n"
        "turned top-down here (a copy, slice or flip of it is an ordinary array). Raises ValueError on bad\n"
        "input. The GIL is released while scoring.");
}

}  // namespace topocut::python
