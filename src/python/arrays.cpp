#include "python/arrays.h"

#include <cmath>
#include <cstring>

#include "topocut/core/error.h"

namespace topocut::python {

GridArray grid_view(const py::array& grid) {
  const py::dtype dtype = grid.dtype();
  const bool int8 = dtype.kind() == 'i' && dtype.itemsize() == 1;
  const bool uint8 = dtype.kind() == 'u' && dtype.itemsize() == 1;
  if (!int8 && !uint8)
    throw Error("the grid must be an int8 (occupancy -1/0..100) or uint8 (grey) array, got dtype " +
                py::str(static_cast<py::object>(dtype)).cast<std::string>());
  if (grid.ndim() != 2) throw Error("the grid must be a 2-D array (rows, columns), got " + std::to_string(grid.ndim()) + " dimensions");
  if (grid.shape(0) == 0 || grid.shape(1) == 0) throw Error("the grid is empty (" + std::to_string(grid.shape(0)) + " x " + std::to_string(grid.shape(1)) + " cells)");
  if (grid.shape(1) > 1 && grid.strides(1) != 1)
    throw Error("the grid's columns must be adjacent in memory (stride 1 byte, got " + std::to_string(grid.strides(1)) +
                "): pass numpy.ascontiguousarray(grid)");
  if (grid.shape(0) > (1 << 30) || grid.shape(1) > (1 << 30)) throw Error("the grid is too large");
  GridArray a;
  a.data = grid.data();
  a.height = static_cast<int>(grid.shape(0));
  a.width = static_cast<int>(grid.shape(1));
  a.row_stride = grid.shape(0) > 1 ? grid.strides(0) : a.width;
  a.encoding = int8 ? CellEncoding::kOccupancy : CellEncoding::kGrey;
  return a;
}

GridArray grid_copy(const py::array& grid, std::vector<unsigned char>& storage) {
  GridArray a = grid_view(grid);
  const std::size_t width = static_cast<std::size_t>(a.width);
  storage.resize(width * static_cast<std::size_t>(a.height));
  for (int r = 0; r < a.height; ++r)
    std::memcpy(storage.data() + width * r, static_cast<const unsigned char*>(a.data) + a.row_stride * r, width);
  a.data = storage.data();
  a.row_stride = a.width;
  return a;
}

py::array_t<double> points_array(const std::vector<Point2>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), static_cast<py::ssize_t>(2)});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    view(static_cast<py::ssize_t>(i), 0) = points[i].x;
    view(static_cast<py::ssize_t>(i), 1) = points[i].y;
  }
  return out;
}

namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// values as a contiguous float array, or an empty one if numpy cannot convert them (ensure() clears
// numpy's error, so the caller raises its own message).
Doubles as_doubles(const py::handle& values) { return Doubles::ensure(values); }

}  // namespace

std::vector<Point2> points_from(const py::handle& points, const std::string& name) {
  const Doubles a = as_doubles(points);
  if (!a || a.ndim() != 2 || (a.shape(0) > 0 && a.shape(1) != 2))
    throw Error(name + " must be an (n, 2) array of x, y coordinates");
  std::vector<Point2> out;
  out.reserve(static_cast<std::size_t>(a.shape(0)));
  const auto view = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    if (!std::isfinite(view(i, 0)) || !std::isfinite(view(i, 1))) throw Error(name + " has a coordinate that is not a finite number");
    out.push_back({view(i, 0), view(i, 1)});
  }
  return out;
}

std::vector<double> values_from(const py::handle& values, const std::string& name) {
  const Doubles a = as_doubles(values);
  if (!a || a.ndim() != 1) throw Error(name + " must be a one-dimensional array of numbers");
  return std::vector<double>(a.data(), a.data() + a.shape(0));
}

}  // namespace topocut::python
