// The keyword arguments of segment(), IncrementalSegmenter() and merge_training_rows() as data: name,
// type, default and help, from the option table (segment_option_rows()) and the option structs'
// defaults. The package gives its functions signatures from them (help(), inspect) and the build
// writes the type stubs from them, so that neither can drift from what options.cpp accepts.
#include <pybind11/pybind11.h>

#include "python/bindings.h"
#include "python/options.h"
#include "topocut/core/grid_array_options.h"
#include "topocut/core/option_names.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/evaluation/robot_made_dataset.h"
#include "topocut/exploration/simulated_map.h"
#include "topocut/lines/extract.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segment_switches.h"

namespace topocut::python {
namespace {

namespace py = pybind11;

// One keyword: (name, type name, default, help).
py::tuple keyword(const std::string& name, const char* type, const py::object& value, const std::string& help) {
  return py::make_tuple(name, type, value, help);
}

// A table's rows with '_' for '-', defaults taken from defaults: switches as bool, whole numbers as
// int, other numbers as float.
template <typename Target>
void add_rows(py::list& out, const std::vector<OptionRow<Target>>& rows, const Target& defaults) {
  for (const OptionRow<Target>& row : rows) {
    const std::string name = underscored_option_name(row.name);
    const double value = row.get(defaults);
    if (row.is_switch()) {
      out.append(keyword(name, "bool", py::bool_(value != 0.0), row.help));
    } else if (is_whole_number(row.range)) {
      out.append(keyword(name, "int", py::int_(static_cast<long long>(value)), row.help));
    } else {
      out.append(keyword(name, "float", py::float_(value), row.help));
    }
  }
}

// The segment command's table and its merge model (as a model's text, not a file).
void add_segment_rows(py::list& out, const SegmentSettings& settings) {
  add_rows(out, segment_option_rows(), settings);
  out.append(keyword(underscored_option_name(kMergeModelOption.name), "str | None", py::none(),
                     std::string("the text of ") + kMergeModelOption.help + "; None: the shipped one"));
}

// How the grid's cells are read (take_grid_reading()): the row order, then the thresholds' rows.
void add_grid_reading(py::list& out) {
  const GridReading r;
  out.append(keyword("row_order", "str", py::str(r.row_order),
                     "'bottom-up' or 'top-down'; '': bottom-up for int8 grids, top-down for uint8 images"));
  add_rows(out, grid_array_option_rows(), r.thresholds);
}

// simulate_map()'s keywords: simulate-map's table with '_' for '-'; the whole-number rows (cells,
// scans) as int.
void add_simulation_rows(py::list& out) {
  const SimulatedMapOptions defaults;
  for (const OptionRow<SimulatedMapOptions>& row : simulated_map_option_rows()) {
    const double value = row.get(defaults);
    const bool whole = row.value_name == "CELLS" || row.value_name == "SCANS";
    out.append(keyword(underscored_option_name(row.name), whole ? "int" : "float",
                       whole ? py::object(py::int_(static_cast<int>(value))) : py::object(py::float_(value)), row.help));
  }
}

// The keywords of the functions without an options struct, from their commands' rows: decompose()'s
// tau, extract_lines()' method, simulate_map()'s seed.
bool add_function_rows(py::list& out, const std::string& kind) {
  if (kind == "decompose") {
    add_rows(out, decomposition_tau_rows(), DecompositionOptions{});
  } else if (kind == "lines") {
    for (const ChoiceRow<LineExtractionOptions>& row : line_choice_rows())
      out.append(keyword(underscored_option_name(row.name), "str", py::str(row.get(LineExtractionOptions{})), row.help));
  } else if (kind == "seed") {
    add_rows(out, std::vector<OptionRow<RobotMadeDatasetOptions>>{robot_made_seed_rows().front()}, RobotMadeDatasetOptions{});
  } else {
    return false;
  }
  return true;
}

// kind: "options" (merge_training_rows()), "segment" (segment(): the options and the grid reading),
// "grid" (update()), "incremental" (IncrementalSegmenter()), "simulate" (simulate_map()'s options),
// or "decompose", "lines", "seed" (add_function_rows()).
py::list keywords(const std::string& kind) {
  if (kind == "simulate") {
    py::list out;
    add_simulation_rows(out);
    return out;
  }
  if (py::list out; add_function_rows(out, kind)) return out;
  if (kind != "options" && kind != "segment" && kind != "grid" && kind != "incremental")
    throw py::value_error("unknown keyword table '" + kind + "'");
  py::list out;
  if (kind == "options" || kind == "segment") add_segment_rows(out, SegmentSettings{});
  if (kind == "segment" || kind == "grid") add_grid_reading(out);
  if (kind == "incremental") {
    add_rows(out, incremental_option_rows(), IncrementalOptions{});
    add_segment_rows(out, SegmentSettings{IncrementalOptions{}.segment, {}});
  }
  return out;
}

}  // namespace

void bind_keywords(py::module_& m) {
  m.def("_keywords", &keywords, py::arg("kind"),
        "The keyword arguments of segment() ('segment'), merge_training_rows() ('options'), update() ('grid'),\n"
        "IncrementalSegmenter() ('incremental'), simulate_map() ('simulate', and its 'seed'), decompose()\n"
        "('decompose') or extract_lines() ('lines'):\n"
        "a list of (name, type name, default, help).");
}

}  // namespace topocut::python
