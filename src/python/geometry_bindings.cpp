// decompose() and the five line extractors.
#include <cmath>
#include <limits>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/arrays.h"
#include "python/bindings.h"
#include "topocut/core/error.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/lines/extract.h"

namespace topocut::python {
namespace {

Ring ring_from(const py::handle& points, const std::string& name) {
  Ring ring = points_from(points, name);
  if (ring.size() < 3) throw Error(name + " needs at least 3 points, got " + std::to_string(ring.size()));
  return ring;
}

// The row of decompose()'s tau and of extract_lines()' method: the decompose and lines commands' rows.
const OptionRow<DecompositionOptions>& tau_row() { return decomposition_tau_rows().front(); }
const ChoiceRow<LineExtractionOptions>& method_row() { return line_choice_rows().front(); }

py::dict decompose_py(const py::handle& outer, const py::handle& holes, double tau) {
  PolygonWithHoles polygon;
  polygon.outer = ring_from(outer, "outer");
  for (const py::handle& hole : holes) polygon.holes.push_back(ring_from(hole, "a hole"));
  DecompositionOptions options;
  set_option(tau_row(), options, tau, "--" + tau_row().name);
  Decomposition d;
  {
    py::gil_scoped_release release;
    d = decompose(normalized_orientation(polygon), options);
  }
  py::list pieces, cuts;
  for (const PolygonWithHoles& piece : d.pieces) {
    py::list piece_holes;
    for (const Ring& h : piece.holes) piece_holes.append(points_array(h));
    pieces.append(py::dict(py::arg("outer") = points_array(piece.outer), py::arg("holes") = piece_holes, py::arg("area") = area(piece)));
  }
  for (const Cut& cut : d.cuts) cuts.append(points_array({cut.segment.a, cut.segment.b}));
  return py::dict(py::arg("pieces") = pieces, py::arg("cuts") = cuts);
}

py::list lines_py(const py::handle& angles, const py::handle& ranges, const std::string& method, double range_min, double range_max) {
  Scan scan;
  scan.angles = values_from(angles, "angles");
  scan.ranges = values_from(ranges, "ranges");
  scan.range_min = range_min;
  scan.range_max = range_max;
  LineExtractionOptions options;
  set_choice(method_row(), options, method, "--" + method_row().name);
  std::vector<Line> lines;
  {
    py::gil_scoped_release release;
    validate(scan);
    lines = extract_lines(scan, options);
  }
  py::list out;
  for (const Line& line : lines) {
    py::array_t<std::int64_t> support(static_cast<py::ssize_t>(line.support.size()));
    for (std::size_t i = 0; i < line.support.size(); ++i) support.mutable_at(static_cast<py::ssize_t>(i)) = static_cast<std::int64_t>(line.support[i]);
    out.append(py::dict(py::arg("rho") = line.rho, py::arg("alpha") = line.alpha, py::arg("start") = py::make_tuple(line.start.x, line.start.y),
                        py::arg("end") = py::make_tuple(line.end.x, line.end.y), py::arg("support") = support));
  }
  return out;
}

}  // namespace

void bind_geometry(py::module_& m) {
  m.def("decompose", &decompose_py, py::arg("outer"), py::arg("holes") = py::list(),
        py::arg(tau_row().name.c_str()) = tau_row().get(DecompositionOptions{}),
        "Dual-space decomposition (DuDe) of a polygon with holes into nearly convex pieces: cuts wherever a\n"
        "pocket or hole is deeper than tau (polygon units). outer: (n, 2) array; holes: list of (n, 2) arrays;\n"
        "any orientation. Returns {'pieces': [{'outer', 'holes', 'area'}], 'cuts': [(2, 2) arrays]}.\n"
        "Raises ValueError on a ring with fewer than 3 points or a polygon that is not simple.");
  m.def("extract_lines", &lines_py, py::arg("angles"), py::arg("ranges"),
        py::arg(method_row().name.c_str()) = method_row().get(LineExtractionOptions{}), py::arg("range_min") = 0.0,
        py::arg("range_max") = std::numeric_limits<double>::infinity(),
        "Wall lines of one laser scan: angles (radians) and ranges (metres), one per beam; invalid ranges\n"
        "(0, nan, inf, outside [range_min, range_max]) are skipped. method: sef, lt, iepf, smf or ale (defaults\n"
        "from the literature). Returns a list of {'rho', 'alpha', 'start', 'end', 'support'} (support: beam indices).");
  for (const std::string& name : method_row().names) {
    m.def(name.c_str(), [name](const py::handle& angles, const py::handle& ranges, double range_min, double range_max) {
      return lines_py(angles, ranges, name, range_min, range_max);
    }, py::arg("angles"), py::arg("ranges"), py::arg("range_min") = 0.0, py::arg("range_max") = std::numeric_limits<double>::infinity(),
          ("extract_lines(angles, ranges, method='" + name + "')").c_str());
  }
}

}  // namespace topocut::python
