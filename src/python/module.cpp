// The Python module `topocut`: thin adapters over the library (DESIGN.md: python row), like the CLI.
#include <pybind11/pybind11.h>

#include "python/bindings.h"
#include "topocut/core/error.h"

PYBIND11_MODULE(topocut, m) {
  m.doc() =
      "topocut: segment 2-D robot maps into rooms.\n\n"
      "    import topocut\n"
      "    m = topocut.load_map('maps/floorplan.yaml')      # int8 grid, ROS row order\n"
      "    r = topocut.segment(m.grid, m.resolution, m.origin)\n"
      "    r.labels, r.rooms, r.passages, r.to_json(), r.to_geojson()\n"
      "    s = topocut.evaluate('X_labels.png', 'X_gt_segmentation.png', free='X.png')\n"
      "    s.recall, s.precision, s.f1, s.pq, s.segments_per_room\n\n"
      "Bad input raises ValueError with the message the topocut command prints.";
  m.attr("__version__") = TOPOCUT_VERSION;
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const topocut::Error& e) {
      PyErr_SetString(PyExc_ValueError, topocut::one_line_message(e.what()).c_str());
    }
  });
  topocut::python::bind_segmentation(m);
  topocut::python::bind_geometry(m);
  topocut::python::bind_evaluation(m);
  topocut::python::bind_training(m);
}
