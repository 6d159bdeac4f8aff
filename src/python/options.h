#pragma once
// Keyword arguments -> the library's option structs, with the segment command's option names
// (dashes become underscores) and the structs' own defaults.
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "topocut/core/grid_array.h"
#include "topocut/exploration/simulated_map.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut::python {

namespace py = pybind11;

// How the cells of an array are read: the row order (kwargs row_order) and the thresholds, by the rows
// of core/grid_array_options.h (free_thresh, occupied_thresh, fixed_thresholds, free_threshold,
// occupied_threshold). A uint8 image's palette is read from its values unless fixed_thresholds.
struct GridReading {
  std::string row_order;  // "", "bottom-up" or "top-down"; "" = bottom-up for int8, top-down for uint8
  GridArray thresholds = [] {
    GridArray a;
    a.detect_palette = true;
    return a;
  }();
};

// Takes the grid-reading keywords out of kwargs (the rest stay).
GridReading take_grid_reading(py::dict& kwargs);

// Fills array's frame and thresholds from resolution, origin (x, y[, yaw]) and reading.
void apply(const GridReading& reading, double resolution, const py::handle& origin, GridArray& array);

// Segment options from the segment command's keywords; an unknown keyword raises TypeError, a bad
// value ValueError with the command's message.
SegmentOptions segment_options(const py::dict& kwargs);

// Incremental options: the incremental segmenter's table (incremental_option_rows()) and every segment
// option, by keyword, each checked and named as on the command line.
IncrementalOptions incremental_options(py::dict kwargs);

// The names segment() accepts, for docstrings.
std::string segment_option_names();

// load_map()'s options: the map-loading rows of every command (map_load_option_rows()) by keyword
// (resolution, fixed_thresholds, free_threshold, occupied_threshold, max_megapixels), each checked
// and named as there; giving a threshold means fixed thresholds, as on the command line.
MapLoadOptions map_load_options(const py::dict& kwargs);

// Their names, for docstrings and errors.
std::string map_load_option_names();

// simulate_map()'s options: simulate-map's rows (simulated_map_option_rows()) by keyword, each
// checked and named as there, then validated together.
SimulatedMapOptions simulated_map_options(const py::dict& kwargs);

// Their names, for docstrings and errors.
std::string simulated_map_option_names();

}  // namespace topocut::python
