#include "python/options.h"

#include <algorithm>
#include <cstdint>

#include <pybind11/stl.h>

#include "topocut/core/error.h"
#include "topocut/core/grid_array_options.h"
#include "topocut/core/input_file.h"
#include "topocut/core/option_names.h"
#include "topocut/core/option_table.h"
#include "topocut/io/map_load_flags.h"
#include "topocut/segmentation/merge_model.h"
#include "topocut/segmentation/segment_switches.h"

namespace topocut::python {
namespace {

// Python's keyword for a row of the library's table: the command's flag with '_' for '-'.
template <typename Target>
const OptionRow<Target>* find_keyword(const std::vector<OptionRow<Target>>& rows, const std::string& name) {
  for (const OptionRow<Target>& row : rows)
    if (dashed_option_name(row.name) == dashed_option_name(name)) return &row;  // robot_radius or "robot-radius"
  return nullptr;
}

// The keywords of rows: their names with '_' for '-'.
template <typename Target>
std::vector<std::string> keywords(const std::vector<OptionRow<Target>>& rows) {
  std::vector<std::string> names;
  for (const OptionRow<Target>& row : rows) names.push_back(underscored_option_name(row.name));
  return names;
}

std::string comma_separated(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

// Every keyword segment() takes: the segment command's table and the map's own.
std::vector<std::string> segment_keywords() {
  std::vector<std::string> names = keywords(segment_option_rows());
  for (const char* name : {"merge_model", "row_order"}) names.push_back(name);
  for (const std::string& name : keywords(grid_array_option_rows())) names.push_back(name);
  return names;
}

// Whether value is True or False (Python's or numpy's).
bool is_bool(const py::handle& value) {
  return py::isinstance<py::bool_>(value) || py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>() == "bool_";
}

// A number keyword's value: a number (Python's or numpy's; not a bool, not a text), as the command
// line reads only numbers; the row's range then checks it, with the command's message.
double number(const py::handle& value, const std::string& name) {
  const std::string refused = name + " needs a number, not '" + py::str(value).cast<std::string>() + "'";
  if (is_bool(value) || py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value)) throw Error(refused);
  try {
    return value.cast<double>();
  } catch (const py::cast_error&) {
    throw Error(refused);
  }
}

// A switch keyword's value: True or False (numpy's bool too), as the command line's switches and
// --config's true and false.
bool switch_value(const py::handle& value, const std::string& name) {
  if (!is_bool(value)) throw Error(switch_value_error(name, py::str(value).cast<std::string>()));
  return py::bool_(py::reinterpret_borrow<py::object>(value));
}

template <typename T>
T pop(py::dict& kwargs, const char* name, T fallback) {
  if (!kwargs.contains(name)) return fallback;
  const py::object value = kwargs[name];
  PyDict_DelItemString(kwargs.ptr(), name);
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw Error(std::string(name) + " has the wrong type");
  }
}

// Sets every keyword of kwargs in target through its row of rows: the command's check and message,
// with the keyword's name, in the table's order (as the command line sets them, so that the order of
// the keywords does not matter). An unknown keyword is a TypeError naming the closest of `known` and
// listing them.
template <typename Target>
void set_keywords(const std::vector<OptionRow<Target>>& rows, const py::dict& kwargs, Target& target,
                  const std::vector<std::string>& known) {
  struct Given {
    const OptionRow<Target>* row;
    py::handle value;
    std::string name;  // as given
  };
  std::vector<Given> given;  // robot_radius and **{"robot-radius": ...} name one option
  for (const auto& [key, value] : kwargs) {
    const std::string name = py::str(key);
    const OptionRow<Target>* row = find_keyword(rows, name);
    if (row == nullptr) {
      const std::string meant = closest_option_name(name, known);
      throw py::type_error("unexpected keyword argument '" + name + "'" + (meant.empty() ? "" : " (did you mean " + meant + "?)") +
                           "; options are: " + comma_separated(known));
    }
    for (const Given& earlier : given)
      if (earlier.row == row) throw Error(given_twice_error(name));
    given.push_back({row, value, name});
  }
  for (const OptionRow<Target>& row : rows) {
    for (const Given& g : given) {
      if (g.row != &row) continue;
      if (row.is_switch()) {
        row.set(target, switch_value(g.value, g.name) ? 1.0 : 0.0);
      } else {
        set_option(row, target, number(g.value, g.name), g.name);
      }
    }
  }
}

// The segment options from kwargs (the segment command's table, segment_option_rows()) over s.
SegmentOptions settings_from(const py::dict& kwargs, SegmentSettings s) {
  set_keywords(segment_option_rows(), kwargs, s, segment_keywords());
  return to_segment_options(s);
}

}  // namespace

GridReading take_grid_reading(py::dict& kwargs) {
  GridReading r;
  r.row_order = pop<std::string>(kwargs, "row_order", r.row_order);
  if (!r.row_order.empty() && r.row_order != "bottom-up" && r.row_order != "top-down")
    throw Error("row_order must be 'bottom-up' or 'top-down', got '" + r.row_order + "'");
  py::dict own;  // the thresholds' keywords, taken out of kwargs; the rest are segment()'s
  for (const auto& [key, value] : kwargs)
    if (find_keyword(grid_array_option_rows(), py::str(key)) != nullptr) own[key] = value;
  for (const auto& [key, value] : own) PyDict_DelItem(kwargs.ptr(), key.ptr());
  set_keywords(grid_array_option_rows(), own, r.thresholds, keywords(grid_array_option_rows()));
  return r;
}

void apply(const GridReading& reading, double resolution, const py::handle& origin, GridArray& array) {
  std::vector<double> pose;
  try {
    pose = origin.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
  }
  if (pose.size() != 2 && pose.size() != 3) throw Error("origin must be (x, y) or (x, y, yaw) in metres and radians");
  array.origin = {pose[0], pose[1], pose.size() == 3 ? pose[2] : 0.0};
  check_option_value(find_option(map_load_option_rows(), std::string("resolution"))->range, resolution, "resolution");
  array.resolution = resolution;
  const bool bottom_up = reading.row_order.empty() ? array.encoding == CellEncoding::kOccupancy : reading.row_order == "bottom-up";
  array.row_order = bottom_up ? RowOrder::kBottomUp : RowOrder::kTopDown;
  array.free_thresh = reading.thresholds.free_thresh;
  array.occupied_thresh = reading.thresholds.occupied_thresh;
  array.detect_palette = reading.thresholds.detect_palette;
  array.free_min = reading.thresholds.free_min;
  array.occupied_max = reading.thresholds.occupied_max;
}

namespace {

// merge_model= of kwargs (popped) in settings: None or absent keeps the shipped model; a text is
// parsed (within the limits of every front end) and must not meet learned merging switched off.
void take_merge_model(py::dict& kwargs, SegmentSettings& settings) {
  const std::string name = underscored_option_name(kMergeModelOption.name);  // the segmentation options' row
  if (!kwargs.contains(name)) return;
  const py::object value = kwargs[name.c_str()];
  PyDict_DelItemString(kwargs.ptr(), name.c_str());
  if (value.is_none()) return;
  if (!py::isinstance<py::str>(value)) throw Error(name + " must be a model's text (a str) or None");
  // Measured before it is copied: a 190 MiB text cost 1.5 GB on its way to the parser's limit.
  if (static_cast<std::uint64_t>(PyUnicode_GetLength(value.ptr())) > kMaxMergeModelBytes)
    throw Error("merge model: " + std::to_string(PyUnicode_GetLength(value.ptr())) + " characters, more than the limit of " +
                byte_size_text(kMaxMergeModelBytes));
  const std::string text = value.cast<std::string>();
  if (text.empty()) throw Error(name + " is empty: give a model's text, or None for the shipped model");
  settings.options.merge.model = parse_merge_model(text);
  settings.switches.merge_model_given = true;
}

}  // namespace

SegmentOptions segment_options(const py::dict& kwargs) {
  py::dict rest(kwargs);
  SegmentSettings settings;
  take_merge_model(rest, settings);
  return settings_from(rest, settings);
}

IncrementalOptions incremental_options(py::dict kwargs) {
  IncrementalOptions o;
  py::dict own;  // the incremental table's keywords, taken out of kwargs; the rest are segment()'s
  for (const auto& [key, value] : kwargs)
    if (find_keyword(incremental_option_rows(), py::str(key)) != nullptr) own[key] = value;
  for (const auto& [key, value] : own) PyDict_DelItem(kwargs.ptr(), key.ptr());
  set_keywords(incremental_option_rows(), own, o, keywords(incremental_option_rows()));
  SegmentSettings settings{o.segment, {}};
  take_merge_model(kwargs, settings);
  o.segment = settings_from(kwargs, settings);
  return o;
}

std::string segment_option_names() { return comma_separated(segment_keywords()); }

MapLoadOptions map_load_options(const py::dict& kwargs) {
  MapLoadOptions load;
  set_keywords(map_load_option_rows(), kwargs, load, keywords(map_load_option_rows()));
  validate(load);
  return load;
}

std::string map_load_option_names() { return comma_separated(keywords(map_load_option_rows())); }

SimulatedMapOptions simulated_map_options(const py::dict& kwargs) {
  SimulatedMapOptions options;
  set_keywords(simulated_map_option_rows(), kwargs, options, keywords(simulated_map_option_rows()));
  validate(options);
  return options;
}

std::string simulated_map_option_names() { return comma_separated(keywords(simulated_map_option_rows())); }

}  // namespace topocut::python
