#include "python/options.h"

#include <cmath>
#include <functional>
#include <map>

#include <pybind11/stl.h>

#include "topocut/core/error.h"
#include "topocut/segmentation/segment_switches.h"

namespace topocut::python {
namespace {

struct Settings {
  SegmentOptions options;
  SegmentSwitches switches;
};

enum class Check { kPositive, kNonNegative, kNone };

struct NumberOption {
  Check check;
  std::function<double&(Settings&)> field;
};

// The segment command's numeric options (src/cli/cmd_segment.cpp), same names, same checks.
const std::map<std::string, NumberOption>& number_options() {
  static const std::map<std::string, NumberOption> table = {
      {"concavity", {Check::kPositive, [](Settings& s) -> double& { return s.options.concavity; }}},
      {"door_width", {Check::kPositive, [](Settings& s) -> double& { return s.options.doors.max_width; }}},
      {"fold_area", {Check::kNonNegative, [](Settings& s) -> double& { return s.options.merge.min_room_area; }}},
      {"robot_radius", {Check::kNonNegative, [](Settings& s) -> double& { return s.options.binarize.robot_radius; }}},
      {"min_room_area", {Check::kNonNegative, [](Settings& s) -> double& { return s.options.contours.min_component_area; }}},
      {"min_hole_area", {Check::kNonNegative, [](Settings& s) -> double& { return s.options.contours.min_hole_area; }}},
  };
  return table;
}

const std::map<std::string, std::function<bool&(Settings&)>>& switch_options() {
  static const std::map<std::string, std::function<bool&(Settings&)>> table = {
      {"trivial", [](Settings& s) -> bool& { return s.switches.trivial; }},
      {"parity", [](Settings& s) -> bool& { return s.switches.parity; }},
      {"no_doors", [](Settings& s) -> bool& { return s.switches.no_doors; }},
      {"no_wall_openings", [](Settings& s) -> bool& { return s.switches.no_wall_openings; }},
      {"no_merge", [](Settings& s) -> bool& { return s.switches.no_merge; }},
      {"no_simplify", [](Settings& s) -> bool& { return s.switches.no_simplify; }},
      {"no_clean", [](Settings& s) -> bool& { return s.switches.no_clean; }},
      {"no_width_steps", [](Settings& s) -> bool& { return s.switches.no_width_steps; }},
      {"no_furniture_rule", [](Settings& s) -> bool& { return s.switches.no_furniture_rule; }},
      {"cover_obstacles", [](Settings& s) -> bool& { return s.options.labels.cover_absorbed_obstacles; }},
  };
  return table;
}

double number(const py::handle& value, const std::string& name, Check check) {
  double v = 0.0;
  try {
    v = value.cast<double>();
  } catch (const py::cast_error&) {
    throw Error(name + " must be a number");
  }
  if (check == Check::kPositive && (!std::isfinite(v) || v <= 0.0)) throw Error(name + " must be a positive number");
  if (check == Check::kNonNegative && (!std::isfinite(v) || v < 0.0)) throw Error(name + " must be a non-negative number");
  return v;
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

Settings settings_from(const py::dict& kwargs, Settings s) {
  for (const auto& [key, value] : kwargs) {
    const std::string name = key.cast<std::string>();
    if (const auto n = number_options().find(name); n != number_options().end()) {
      n->second.field(s) = number(value, name, n->second.check);
      if (name == "min_room_area") s.switches.min_room_area_given = true;
    } else if (const auto b = switch_options().find(name); b != switch_options().end()) {
      b->second(s) = py::reinterpret_borrow<py::object>(value).cast<bool>();
    } else {
      throw py::type_error("unexpected keyword argument '" + name + "'; options are: " + segment_option_names());
    }
  }
  apply(s.switches, s.options);
  validate(s.options);
  return s;
}

}  // namespace

GridReading take_grid_reading(py::dict& kwargs) {
  GridReading r;
  r.row_order = pop<std::string>(kwargs, "row_order", r.row_order);
  r.free_thresh = pop<double>(kwargs, "free_thresh", r.free_thresh);
  r.occupied_thresh = pop<double>(kwargs, "occupied_thresh", r.occupied_thresh);
  const bool free_given = kwargs.contains("free_threshold"), occupied_given = kwargs.contains("occupied_threshold");
  r.free_threshold = pop<int>(kwargs, "free_threshold", r.free_threshold);
  r.occupied_threshold = pop<int>(kwargs, "occupied_threshold", r.occupied_threshold);
  // As the command: giving a threshold means fixed thresholds.
  r.fixed_thresholds = pop<bool>(kwargs, "fixed_thresholds", false) || free_given || occupied_given;
  if (!r.row_order.empty() && r.row_order != "bottom-up" && r.row_order != "top-down")
    throw Error("row_order must be 'bottom-up' or 'top-down', got '" + r.row_order + "'");
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
  array.resolution = resolution;
  const bool bottom_up = reading.row_order.empty() ? array.encoding == CellEncoding::kOccupancy : reading.row_order == "bottom-up";
  array.row_order = bottom_up ? RowOrder::kBottomUp : RowOrder::kTopDown;
  array.free_thresh = reading.free_thresh;
  array.occupied_thresh = reading.occupied_thresh;
  array.detect_palette = !reading.fixed_thresholds;
  array.free_min = reading.free_threshold;
  array.occupied_max = reading.occupied_threshold;
}

SegmentOptions segment_options(const py::dict& kwargs) { return settings_from(kwargs, Settings{}).options; }

IncrementalOptions incremental_options(py::dict kwargs) {
  IncrementalOptions o;
  o.absorb_area = pop<double>(kwargs, "absorb_area", o.absorb_area);
  o.absorb_fraction = pop<double>(kwargs, "absorb_fraction", o.absorb_fraction);
  o.batch_fraction = pop<double>(kwargs, "batch_fraction", o.batch_fraction);
  o.neighbours_across_doors = pop<bool>(kwargs, "neighbours_across_doors", o.neighbours_across_doors);
  Settings s;
  s.options = o.segment;
  s.switches.no_clean = true;
  o.segment = settings_from(kwargs, s).options;
  return o;
}

std::string segment_option_names() {
  std::string names;
  for (const auto& [name, option] : number_options()) names += (names.empty() ? "" : ", ") + name;
  for (const auto& [name, option] : switch_options()) names += ", " + name;
  return names + ", row_order, free_thresh, occupied_thresh, fixed_thresholds, free_threshold, occupied_threshold";
}

}  // namespace topocut::python
