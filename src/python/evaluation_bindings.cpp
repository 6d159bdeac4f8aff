// evaluate(): every score of a segmentation against a ground truth, as `topocut evaluate` reports it.
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/bindings.h"
#include "python/state.h"
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

// A label image given as an array: segment()'s own (a Segmentation or its labels as returned) in its
// known row order, anything else as it is.
cv::Mat labels_array(const py::object& labels) {
  if (std::optional<cv::Mat> own = segment_labels_top_down(labels)) return *own;  // segment()'s: its row order known
  return int_image(py::array::ensure(labels), "labels");
}

ExpectedSize size_of(const cv::Mat& image, const char* of) {
  return {static_cast<std::uint64_t>(image.cols), static_cast<std::uint64_t>(image.rows), of};
}

cv::Mat ground_truth_array(const py::object& ground_truth) {
  const py::array a = py::array::ensure(ground_truth);
  if (!a || a.dtype().kind() != 'u' || a.dtype().itemsize() != 1)
    throw Error("ground_truth must be a path or a uint8 grey image (pixels above 250 are free)");
  cv::Mat grey;
  int_image(a, "ground_truth").convertTo(grey, CV_8U);
  return grey;
}

// The label image and the ground truth, each an array or an image file: a file is read after the
// other input fixed its size, so that a header declaring another size is refused before decoding.
std::pair<cv::Mat, cv::Mat> labels_and_ground_truth(const py::object& labels, const py::object& ground_truth) {
  const bool labels_file = py::isinstance<py::str>(labels), truth_file = py::isinstance<py::str>(ground_truth);
  cv::Mat segments, truth;
  if (!labels_file) segments = labels_array(labels);
  if (!truth_file) truth = ground_truth_array(ground_truth);
  if (truth_file) {
    const std::optional<ExpectedSize> size = segments.empty() ? std::nullopt : std::optional(size_of(segments, "the labels array"));
    truth = load_ground_truth(ground_truth.cast<std::string>(), {}, size ? &*size : nullptr);
  }
  if (labels_file) {
    const ExpectedSize size = size_of(truth, "the ground truth");
    segments = read_region_labels(labels.cast<std::string>(), {}, &size);
  }
  return {segments, truth};
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
  auto [segments, truth] = labels_and_ground_truth(labels, ground_truth);
  const cv::Mat rooms = ground_truth_rooms(truth);
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

// A fraction of a state: a finite number in [0, 1] (a share or a mean of shares).
double fraction(const py::handle& value, const char* field) {
  double v = 0.0;
  try {
    v = value.cast<double>();
  } catch (const py::cast_error&) {
    throw pickle_error("Scores", std::string(field) + " must be a number");
  }
  if (!(v >= 0.0 && v <= 1.0)) throw pickle_error("Scores", std::string(field) + " must lie in [0, 1]");
  return v;
}

// A count of a state: a whole number, not negative.
int count(const py::handle& value, const char* field) {
  long long v = -1;
  try {
    v = value.cast<long long>();
  } catch (const py::cast_error&) {
  }
  if (v < 0 || v > std::numeric_limits<int>::max()) throw pickle_error("Scores", std::string(field) + " must be a count");
  return static_cast<int>(v);
}

std::vector<double> fractions(const py::handle& values, const char* field) {
  std::vector<double> out;
  try {
    for (const py::handle& v : values.cast<py::list>()) out.push_back(fraction(v, field));
  } catch (const py::cast_error&) {
    throw pickle_error("Scores", std::string(field) + " must be a list of numbers");
  }
  return out;
}

py::tuple tuple_of(const py::handle& value, std::size_t size, const char* field) {
  if (!py::isinstance<py::tuple>(value) || py::len(value) != size)
    throw pickle_error("Scores", std::string(field) + " must be a tuple of " + std::to_string(size));
  return py::reinterpret_borrow<py::tuple>(value);
}

SegmentationScores scores_from(const py::handle& state) {
  const py::tuple t = tuple_of(state, 4, "the state");
  const py::tuple o = tuple_of(t[0], 6, "the overlap scores");
  const py::tuple m = tuple_of(t[1], 9, "the matched rooms");
  SegmentationScores s;
  s.overlap = {fraction(o[0], "precision"), fraction(o[1], "recall"), count(o[2], "segments"), count(o[3], "rooms"),
               fractions(o[4], "a segment's precision"), fractions(o[5], "a room's recall")};
  double iou_sum = 0.0, ratio = 0.0;
  try {
    iou_sum = m[5].cast<double>();
    ratio = m[8].cast<double>();
  } catch (const py::cast_error&) {
    throw pickle_error("Scores", "the matched rooms' IoU sum and ratio must be numbers");
  }
  if (!(iou_sum >= 0.0 && std::isfinite(iou_sum)) || !(ratio >= 0.0 && std::isfinite(ratio)))
    throw pickle_error("Scores", "the matched rooms' IoU sum and ratio must be finite and not negative");
  s.matched = {count(m[0], "free segments"), count(m[1], "free rooms"), count(m[2], "matches"), count(m[3], "false positives"),
               count(m[4], "false negatives"), iou_sum, fraction(m[6], "f1"), fraction(m[7], "pq"), ratio};
  s.precision_inside = fraction(t[2], "the precision inside");
  s.far_share = fraction(t[3], "the far share");
  return s;
}

}  // namespace

void bind_evaluation(py::module_& m) {
  py::class_<SegmentationScores>(m, "Scores", "A segmentation scored against a ground truth (fractions in [0, 1]).")
      .def_property_readonly("recall", getter<SegmentationScores>([](const SegmentationScores& s) { return s.overlap.recall; }),
                             "Bormann's recall: mean over rooms R of max_S |S ∩ R| / |R|")
      .def_property_readonly("precision", getter<SegmentationScores>([](const SegmentationScores& s) { return s.overlap.precision; }),
                             "Bormann's precision: mean over segments S of max_R |S ∩ R| / |S|")
      .def_property_readonly("segments", getter<SegmentationScores>([](const SegmentationScores& s) { return s.overlap.segments; }),
                             "segments of more than 100 px (precision's)")
      .def_property_readonly("rooms", getter<SegmentationScores>([](const SegmentationScores& s) { return s.overlap.rooms; }),
                             "ground-truth rooms of more than 100 px (recall's)")
      .def_property_readonly("f1", getter<SegmentationScores>([](const SegmentationScores& s) { return s.matched.f1; }),
                             "matched rooms: TP / (TP + (FP + FN) / 2)")
      .def_property_readonly("pq", getter<SegmentationScores>([](const SegmentationScores& s) { return s.matched.pq; }),
                             "panoptic quality: sum of the matches' IoU / (TP + (FP + FN) / 2)")
      .def_property_readonly("matches", getter<SegmentationScores>([](const SegmentationScores& s) { return s.matched.matches; }),
                             "TP: segment-room pairs with IoU above 0.5 over the free pixels")
      .def_property_readonly("false_positives", getter<SegmentationScores>([](const SegmentationScores& s) { return s.matched.false_positives; }))
      .def_property_readonly("false_negatives", getter<SegmentationScores>([](const SegmentationScores& s) { return s.matched.false_negatives; }))
      .def_property_readonly("free_segments", getter<SegmentationScores>([](const SegmentationScores& s) { return s.matched.segments; }),
                             "segments of more than 100 free pixels")
      .def_property_readonly("free_rooms", getter<SegmentationScores>([](const SegmentationScores& s) { return s.matched.rooms; }),
                             "ground-truth rooms of more than 100 free pixels")
      .def_property_readonly("segments_per_room", getter<SegmentationScores>([](const SegmentationScores& s) { return s.matched.segments_per_room; }),
                             "free_segments / free_rooms")
      .def_property_readonly("precision_inside", getter<SegmentationScores>([](const SegmentationScores& s) { return s.precision_inside; }),
                             "precision with every segment clipped to the ground truth's rooms")
      .def_property_readonly("far_share", getter<SegmentationScores>([](const SegmentationScores& s) { return s.far_share; }),
                             "share of labelled pixels more than 0.5 m from every ground-truth room")
      .def("__repr__", [](const py::object& self) {
        const SegmentationScores& s = state_of<SegmentationScores>(self);
        return "<topocut.Scores recall " + std::to_string(s.overlap.recall) + ", precision " +
               std::to_string(s.overlap.precision) + ", f1 " + std::to_string(s.matched.f1) + ", pq " +
               std::to_string(s.matched.pq) + ">";
      })
      .def(py::pickle([](const py::object& self) { return scores_state(state_of<SegmentationScores>(self)); },
                      [](const py::tuple& t) { return scores_from(t); }));
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
