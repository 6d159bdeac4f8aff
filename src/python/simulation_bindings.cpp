// simulate_map(): the robot-made map of a plan with people's rooms, as `topocut simulate-map` writes it.
#include <cstdint>
#include <string>

#include <pybind11/numpy.h>

#include "python/bindings.h"
#include "python/options.h"
#include "topocut/core/error.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/evaluation/robot_made_dataset.h"
#include "topocut/exploration/simulated_map.h"
#include "topocut/io/grid_from_array.h"
#include "topocut/io/image_input.h"
#include "topocut/io/map_loader.h"

namespace topocut::python {
namespace {

namespace py = pybind11;

// A 2-D uint8 image array as a CV_8UC1 copy; name is the argument's name for errors.
cv::Mat grey_image(const py::handle& value, const std::string& name) {
  const py::array a = py::array::ensure(value);
  if (!a || a.dtype().kind() != 'u' || a.dtype().itemsize() != 1 || a.ndim() != 2)
    throw Error(name + " must be a path or a 2-D uint8 grey image");
  if (a.shape(0) == 0 || a.shape(1) == 0 || a.shape(0) > (1 << 30) || a.shape(1) > (1 << 30))
    throw Error(name + " must not be empty or larger than 2^30 rows or columns");
  const auto c = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(a);
  cv::Mat image(static_cast<int>(a.shape(0)), static_cast<int>(a.shape(1)), CV_8UC1);
  std::copy(c.data(), c.data() + image.total(), image.data);
  return image;
}

// The plan as the command loads it: a file (image or ROS YAML) or a grey image whose palette is
// read from its values, as for an image file.
OccupancyGrid plan_from(const py::object& plan, double resolution) {
  MapLoadOptions load;
  load.resolution = resolution;
  if (py::isinstance<py::str>(plan)) return load_map(plan.cast<std::string>(), load);
  const cv::Mat image = grey_image(plan, "plan");
  GridArray array;
  array.data = image.data;
  array.width = image.cols;
  array.height = image.rows;
  array.encoding = CellEncoding::kGrey;
  array.row_order = RowOrder::kTopDown;
  array.resolution = resolution;
  array.detect_palette = true;
  return grid_from_array(array);
}

// People's rooms, of the plan's size: a file's header is checked against it before it is decoded, as
// the command checks it.
cv::Mat rooms_from(const py::object& ground_truth, const OccupancyGrid& plan) {
  if (py::isinstance<py::str>(ground_truth)) {
    const ExpectedSize size{static_cast<std::uint64_t>(plan.width()), static_cast<std::uint64_t>(plan.height()), "the plan"};
    return ground_truth_rooms(load_ground_truth(ground_truth.cast<std::string>(), {}, &size));
  }
  cv::Mat rooms = ground_truth_rooms(grey_image(ground_truth, "ground_truth"));
  if (rooms.size() != plan.cells.size()) throw Error("the ground truth and the plan differ in size");
  return rooms;
}

// The seed's row: simulate-map's --seed (the first seed of a dataset's maps, a plan's only one).
const OptionRow<RobotMadeDatasetOptions>& seed_row() { return robot_made_seed_rows().front(); }

std::uint32_t seed_from(const py::object& seed) {
  const std::string& name = seed_row().name;
  if (!py::isinstance<py::int_>(seed) || py::isinstance<py::bool_>(seed)) throw Error(name + " must be a whole number in 0..4294967295");
  RobotMadeDatasetOptions options;
  const auto value = seed.cast<long long>();  // beyond long long: OverflowError
  set_option(seed_row(), options, static_cast<double>(value), name);
  return options.first_seed;
}

py::array_t<std::uint8_t> image_array(const cv::Mat& image) {
  py::array_t<std::uint8_t> out({static_cast<py::ssize_t>(image.rows), static_cast<py::ssize_t>(image.cols)});
  std::copy(image.data, image.data + image.total(), out.mutable_data());
  return out;
}

py::tuple simulate_map_py(const py::object& plan, const py::object& ground_truth, const py::object& seed, double resolution,
                          py::kwargs kwargs) {
  const SimulatedMapOptions options = simulated_map_options(kwargs);
  const std::uint32_t s = seed_from(seed);
  const OccupancyGrid grid = plan_from(plan, resolution);
  const cv::Mat rooms = rooms_from(ground_truth, grid);
  cv::Mat map, truth;
  {
    py::gil_scoped_release release;
    const SimulatedMap simulated = simulate_map(grid, rooms, options, s);
    map = map_image(simulated);
    truth = rooms_image(simulated);
  }
  return py::make_tuple(image_array(map), image_array(truth));
}

}  // namespace

void bind_simulation(py::module_& m) {
  m.def("simulate_map", &simulate_map_py, py::arg("plan"), py::arg("ground_truth"), py::arg(seed_row().name.c_str()) = static_cast<long long>(seed_row().get(RobotMadeDatasetOptions{})),
        py::arg("resolution") = 0.05,
        ("simulate_map(plan, ground_truth, seed=1, resolution=0.05, **options) -> (map, ground_truth)\n\n"
         "The map a robot would build of a plan with people's rooms, as `topocut simulate-map` writes it: map\n"
         "(uint8, rows top-down: 0 occupied, 255 free, 205 never seen) and people's rooms in its frame\n"
         "(uint8: 255 in a room, 0 elsewhere; an 8-connected flood fill gives the rooms). plan: the path of a\n"
         "map image or ROS YAML, or a uint8 grey image read as the command reads an image file; ground_truth:\n"
         "the path of a Bormann-style ground truth (white rooms) or its uint8 grey image, the plan's size.\n"
         "The same inputs, options and seed (0..4294967295) give the same arrays. Keywords: the command's\n"
         "options with '_' for '-' (" + simulated_map_option_names() + "), angles in degrees, checked as\n"
         "there. Raises ValueError on bad input. The GIL is released while simulating.").c_str());
}

}  // namespace topocut::python
