// segment(), load_map(), IncrementalSegmenter and their result types (picklable: a state tuple each).
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <type_traits>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/arrays.h"
#include "python/bindings.h"
#include "python/options.h"
#include "python/state.h"
#include "topocut/core/option_names.h"
#include "topocut/core/value_ranges.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/map_loader.h"
#include "topocut/io/rooms_geojson.h"
#include "topocut/io/rooms_json.h"
#include "topocut/segmentation/room_at.h"
#include "topocut/segmentation/segmentation_rules.h"
#include "topocut/topocut.h"

namespace topocut::python {
namespace {

using Shared = std::shared_ptr<const GridSegmentation>;

struct RoomView {
  Room room;
  RoomPlacement placement;
};

struct Result {
  Shared result;
};

struct Map {
  py::array_t<std::int8_t> grid;
  double resolution = 0.0;
  py::tuple origin;
  std::string cells;  // how the cells were read (palette or YAML thresholds)
};

py::tuple xy(const Point2& p) { return py::make_tuple(p.x, p.y); }

// The checks of a pickle state, field by field: a wrong type, a number that is not finite or out of
// range, an array of the wrong shape is a ValueError naming the type and the field, never an object
// whose methods read outside its arrays.
class StateReader {
 public:
  StateReader(const py::handle& state, const char* type, std::size_t fields) : type_(type) {
    if (!py::isinstance<py::tuple>(state)) throw pickle_error(type_, "a tuple expected");
    tuple_ = py::reinterpret_borrow<py::tuple>(state);
    if (tuple_.size() != fields) throw pickle_error(type_, std::to_string(fields) + " fields expected, got " + std::to_string(tuple_.size()));
  }
  py::handle operator[](std::size_t i) const { return tuple_[i]; }
  template <typename T>
  T get(std::size_t i, const char* field) const {
    if constexpr (std::is_base_of_v<py::object, T>) {  // a list, tuple or array: that type itself, not converted
      if (!py::isinstance<T>(tuple_[i])) throw pickle_error(type_, std::string(field) + " has the wrong type");
      return py::reinterpret_borrow<T>(tuple_[i]);
    }
    try {
      return tuple_[i].cast<T>();
    } catch (const py::cast_error&) {
      throw pickle_error(type_, std::string(field) + " has the wrong type");
    }
  }
  double finite(std::size_t i, const char* field) const { return finite_value(tuple_[i], field); }
  double finite_value(const py::handle& value, const char* field) const {
    if (!py::isinstance<py::int_>(value) && !py::isinstance<py::float_>(value)) throw pickle_error(type_, std::string(field) + " must be a number");
    const double v = value.cast<double>();
    if (!std::isfinite(v)) throw pickle_error(type_, std::string(field) + " must be finite");
    return v;
  }
  double non_negative(std::size_t i, const char* field) const {
    const double v = finite(i, field);
    if (v < 0.0) throw pickle_error(type_, std::string(field) + " must not be negative");
    return v;
  }
  int id(std::size_t i, const char* field) const {
    const long long v = get<long long>(i, field);
    if (v < 1 || v > std::numeric_limits<int>::max()) throw pickle_error(type_, std::string(field) + " must be a room id (1 or more)");
    return static_cast<int>(v);
  }
  Point2 point(std::size_t i, const char* field) const {
    const py::tuple pair = get<py::tuple>(i, field);
    if (pair.size() != 2) throw pickle_error(type_, std::string(field) + " must be (x, y)");
    return {finite_value(pair[0], field), finite_value(pair[1], field)};
  }
  std::vector<Point2> points(const py::handle& array, const char* field) const {
    try {
      return points_from(array, field);
    } catch (const Error& e) {
      throw pickle_error(type_, e.what());
    }
  }
  const char* type() const { return type_; }

 private:
  const char* type_;
  py::tuple tuple_;
};

// Pickle states: plain tuples of numbers, arrays and strings, read back field by field.
py::tuple room_state(const RoomView& r) {
  py::list holes;
  for (const Ring& h : r.room.polygon.holes) holes.append(points_array(h));
  return py::make_tuple(r.room.id, points_array(r.room.polygon.outer), holes, r.room.area, r.room.labelled_area,
                        xy(r.room.centroid), xy(r.placement.inside), xy(r.placement.min), xy(r.placement.max),
                        room_kind_name(r.room.kind));
}

RoomView room_from(const py::handle& state) {
  const StateReader t(state, "Room", 10);
  RoomView r;
  r.room.id = t.id(0, "the id");
  r.room.polygon.outer = t.points(t[1], "the outer ring");
  for (const py::handle& h : t.get<py::list>(2, "the holes")) r.room.polygon.holes.push_back(t.points(h, "a hole"));
  r.room.area = t.non_negative(3, "the area");
  r.room.labelled_area = t.non_negative(4, "the labelled area");
  r.room.centroid = t.point(5, "the centroid");
  r.placement = {t.point(6, "the inside point"), t.point(7, "the bounding box"), t.point(8, "the bounding box")};
  const auto kind = t.get<std::string>(9, "the kind");
  if (kind != room_kind_name(RoomKind::kRoom) && kind != room_kind_name(RoomKind::kCorridor))
    throw pickle_error("Room", "the kind must be 'room' or 'corridor'");
  r.room.kind = kind == room_kind_name(RoomKind::kCorridor) ? RoomKind::kCorridor : RoomKind::kRoom;
  return r;
}

py::tuple passage_state(const Passage& p) {
  return py::make_tuple(p.room_a, p.room_b, xy(p.cut.a), xy(p.cut.b), p.width, p.door, static_cast<int>(p.rule));
}

Passage passage_from(const py::handle& state) {
  const StateReader t(state, "Passage", 7);
  Passage p;
  p.room_a = t.id(0, "room a");
  p.room_b = t.id(1, "room b");
  p.cut = {t.point(2, "the cut"), t.point(3, "the cut")};
  p.width = t.non_negative(4, "the width");
  if (!py::isinstance<py::bool_>(t[5])) throw pickle_error("Passage", "the door flag must be True or False");
  p.door = t.get<bool>(5, "the door flag");
  const long long rule = t.get<long long>(6, "the rule");
  if (rule < 0 || rule > static_cast<int>(CutRule::kDecomposition)) throw pickle_error("Passage", "no such rule");
  p.rule = static_cast<CutRule>(rule);
  return p;
}

// A segmentation's state: its labels (a copy), frame, rooms and passages.
py::tuple result_state(const Result& r) {
  const GridSegmentation& g = *r.result;
  py::list rooms, passages;
  for (std::size_t k = 0; k < g.segmentation.rooms.size(); ++k) rooms.append(room_state({g.segmentation.rooms[k], g.placements[k]}));
  for (const Passage& p : g.segmentation.passages) passages.append(passage_state(p));
  const cv::Mat& labels = g.segmentation.labels;
  py::array_t<std::int32_t> copy({labels.rows, labels.cols});
  for (int row = 0; row < labels.rows; ++row)
    std::copy(labels.ptr<std::int32_t>(row), labels.ptr<std::int32_t>(row) + labels.cols, copy.mutable_data(row, 0));
  return py::make_tuple(copy, g.segmentation.resolution, xy(g.segmentation.origin),
                        g.frame.row_order == RowOrder::kBottomUp ? "bottom-up" : "top-down", g.frame.yaw, rooms, passages);
}

// The label image of a state: a 2-D array of 32-bit integers, none negative.
cv::Mat labels_from(const StateReader& t) {
  const py::array given = t.get<py::array>(0, "the labels");
  const char kind = given.dtype().kind();
  if ((kind != 'i' && kind != 'u') || given.ndim() != 2 || given.shape(0) < 1 || given.shape(1) < 1 ||
      given.shape(0) > (1 << 30) || given.shape(1) > (1 << 30) || given.shape(0) * given.shape(1) >= (1ll << 31))
    throw pickle_error(t.type(), "the labels must be a non-empty 2-D array of integers");
  using Labels = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
  const Labels labels = Labels::ensure(given);
  if (!labels) throw pickle_error(t.type(), "the labels must be integers");
  cv::Mat out(static_cast<int>(labels.shape(0)), static_cast<int>(labels.shape(1)), CV_32SC1);
  const std::int64_t* in = labels.data();
  std::int32_t* cell = out.ptr<std::int32_t>();
  for (py::ssize_t i = 0; i < labels.size(); ++i) {
    if (in[i] < 0 || in[i] > std::numeric_limits<std::int32_t>::max()) throw pickle_error(t.type(), "a label is negative or too large");
    cell[i] = static_cast<std::int32_t>(in[i]);
  }
  return out;
}

Result result_from(const py::handle& state) {
  const StateReader t(state, "Segmentation", 7);
  auto out = std::make_shared<GridSegmentation>();
  Segmentation& s = out->segmentation;
  s.labels = labels_from(t);
  s.resolution = t.finite(1, "the resolution");
  s.origin = t.point(2, "the origin");
  try {
    check_resolution(s.resolution, "the resolution");
    check_world_coordinate(s.origin.x, "the origin's x");
    check_world_coordinate(s.origin.y, "the origin's y");
  } catch (const Error& e) {
    throw pickle_error(t.type(), e.what());
  }
  const std::string order = t.get<std::string>(3, "the row order");
  if (order != "bottom-up" && order != "top-down") throw pickle_error(t.type(), "the row order must be 'bottom-up' or 'top-down'");
  out->frame = {order == "bottom-up" ? RowOrder::kBottomUp : RowOrder::kTopDown, t.finite(4, "the yaw")};
  for (const py::handle& room : t.get<py::list>(5, "the rooms")) {
    const RoomView view = room_from(room);
    if (!s.rooms.empty() && view.room.id <= s.rooms.back().id) throw pickle_error(t.type(), "the rooms must be sorted by id, each once");
    s.rooms.push_back(view.room);
    out->placements.push_back(view.placement);
  }
  for (const py::handle& p : t.get<py::list>(6, "the passages")) s.passages.push_back(passage_from(p));
  return {out};
}

py::tuple map_state(const Map& map) { return py::make_tuple(map.grid, map.resolution, map.origin, map.cells); }

Map map_from(const py::handle& state) {
  const StateReader t(state, "Map", 4);
  const py::array given = t.get<py::array>(0, "the grid");
  if (!(given.dtype().kind() == 'i' && given.dtype().itemsize() == 1) || given.ndim() != 2 || given.shape(0) < 1 || given.shape(1) < 1)
    throw pickle_error(t.type(), "the grid must be a non-empty 2-D int8 array");
  const auto grid = py::array_t<std::int8_t, py::array::c_style>::ensure(given);
  for (py::ssize_t i = 0; i < grid.size(); ++i)
    if (grid.data()[i] < -1 || grid.data()[i] > 100) throw pickle_error(t.type(), "a cell is not -1 or 0..100");
  const double resolution = t.finite(1, "the resolution");
  const py::tuple origin = t.get<py::tuple>(2, "the origin");
  if (origin.size() != 3) throw pickle_error(t.type(), "the origin must be (x, y, yaw)");
  for (const py::handle& v : origin) t.finite_value(v, "the origin");
  try {
    check_resolution(resolution, "the resolution");
  } catch (const Error& e) {
    throw pickle_error(t.type(), e.what());
  }
  return Map{grid, resolution, origin, t.get<std::string>(3, "the cells")};
}

// The room holding (x, y) of the map frame, or None: the library's room_at().
py::object room_at_py(const Result& r, double x, double y) {
  const int id = room_at(*r.result, {x, y});
  const std::vector<Room>& rooms = r.result->segmentation.rooms;
  const auto found = std::lower_bound(rooms.begin(), rooms.end(), id, [](const Room& room, int value) { return room.id < value; });
  if (id <= 0 || found == rooms.end() || found->id != id) return py::none();
  const std::size_t k = static_cast<std::size_t>(found - rooms.begin());
  return py::cast(RoomView{rooms[k], r.result->placements[k]});
}

// The label image as a read-only numpy view of the result's own buffer (no copy); the array keeps
// the result alive.
// The capsule's name marks the views segment_labels_top_down() recognises.
const char* const kLabelsCapsule = "topocut.labels";

py::array labels_view(const Shared& result) {
  const cv::Mat& labels = result->segmentation.labels;
  auto* owner = new Shared(result);
  py::capsule base(owner, kLabelsCapsule, [](PyObject* capsule) {
    delete static_cast<Shared*>(PyCapsule_GetPointer(capsule, kLabelsCapsule));
  });
  py::array_t<std::int32_t> view({static_cast<py::ssize_t>(labels.rows), static_cast<py::ssize_t>(labels.cols)},
                                 {static_cast<py::ssize_t>(labels.step[0]), static_cast<py::ssize_t>(sizeof(std::int32_t))},
                                 labels.ptr<std::int32_t>(), base);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

std::vector<RoomView> rooms_of(const Shared& result) {
  std::vector<RoomView> rooms;
  for (std::size_t k = 0; k < result->segmentation.rooms.size(); ++k)
    rooms.push_back({result->segmentation.rooms[k], result->placements[k]});
  return rooms;
}

// A copy of the grid and its frame as the library wants them; checks raise ValueError.
GridArray grid_array(const py::array& grid, double resolution, const py::handle& origin, const GridReading& reading,
                     std::vector<unsigned char>& storage) {
  GridArray a = grid_copy(grid, storage);
  apply(reading, resolution, origin, a);
  return a;
}

Result segment_py(const py::array& grid, double resolution, const py::object& origin, py::kwargs kwargs) {
  const GridReading reading = take_grid_reading(kwargs);
  std::vector<unsigned char> cells;
  const GridArray array = grid_array(grid, resolution, origin, reading, cells);
  const SegmentOptions options = segment_options(kwargs);
  std::shared_ptr<GridSegmentation> out;
  {
    py::gil_scoped_release release;
    out = std::make_shared<GridSegmentation>(segment_grid(array, options));
  }
  return {out};
}

// The entries of the file as segment() keywords, each checked by its row (and the whole by
// to_segment_options, as segment() will), in the file's order.
py::dict load_options_py(const std::string& path) {
  const std::vector<OptionFileEntry> entries = read_option_file(path);
  SegmentSettings settings;
  apply_option_file(entries, segment_option_rows(), settings, "a segmentation option");
  to_segment_options(settings);
  py::dict out;
  for (const OptionFileEntry& entry : entries) {
    const OptionRow<SegmentSettings>& row = *find_option(segment_option_rows(), entry.name);
    const std::string keyword = underscored_option_name(entry.name);
    if (row.is_switch()) {
      out[keyword.c_str()] = entry.switch_value();
    } else {
      out[keyword.c_str()] = entry.number_value();
    }
  }
  return out;
}

Map load_map_py(const std::string& path, const py::object& resolution, py::kwargs kwargs) {
  if (!resolution.is_none()) kwargs["resolution"] = resolution;  // positional, as before keywords
  const MapLoadOptions load = map_load_options(kwargs);
  OccupancyGrid grid;
  std::string cells;
  {
    py::gil_scoped_release release;
    grid = load_map(path, load, &cells);
  }
  // ROS's encoding and row order: -1 unknown, 0 free, 100 occupied, row 0 at the origin.
  Map map;
  map.grid = py::array_t<std::int8_t>({static_cast<py::ssize_t>(grid.height()), static_cast<py::ssize_t>(grid.width())});
  auto out = map.grid.mutable_unchecked<2>();
  for (int r = 0; r < grid.height(); ++r) {
    const unsigned char* row = grid.cells.ptr<unsigned char>(grid.height() - 1 - r);
    for (int c = 0; c < grid.width(); ++c) out(r, c) = row[c] == kFree ? 0 : row[c] == kOccupied ? 100 : -1;
  }
  map.resolution = grid.resolution;
  map.origin = py::make_tuple(grid.origin.x, grid.origin.y, 0.0);
  map.cells = cells;
  // An image holds no scale: say so, as the segment command's summary does.
  if (!is_yaml_path(path) && !kwargs.contains("resolution")) {
    const std::string note = path + ": an image holds no scale: its cells were taken as " + shortest_number(grid.resolution) +
                             " m (the default); pass resolution=M, or load the map_server YAML beside it";
    if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1) != 0) throw py::error_already_set();
  }
  return map;
}

// One segmenter, safe to share between threads: its calls take turns on a lock of its own, taken
// with the GIL released (a thread waiting for the lock while holding the GIL would stop the one
// holding the lock from ever returning into Python).
class PyIncremental {
 public:
  explicit PyIncremental(py::kwargs kwargs) : segmenter_(incremental_options(kwargs)) {}
  Result update(const py::array& grid, double resolution, const py::object& origin, py::kwargs kwargs) {
    const GridReading reading = take_grid_reading(kwargs);
    if (!kwargs.empty()) throw py::type_error("update() takes only the grid-reading options; give segmentation options to IncrementalSegmenter()");
    std::vector<unsigned char> cells;
    const GridArray array = grid_array(grid, resolution, origin, reading, cells);
    std::shared_ptr<GridSegmentation> out;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      segmenter_.update(grid_from_array(array));
      frame_ = frame_of(array);
      out = std::make_shared<GridSegmentation>(framed_.place(segmenter_, frame_));
    }
    return {out};
  }
  Result resegment() {
    std::shared_ptr<GridSegmentation> out;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      if (segmenter_.result().labels.empty()) throw Error("resegment() needs a map: call update() first");
      segmenter_.resegment();
      out = std::make_shared<GridSegmentation>(framed_.place(segmenter_, frame_));
    }
    return {out};
  }
  std::string last_update() {
    IncrementalUpdateReport::Kind kind;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      kind = segmenter_.last_update().kind;
    }
    switch (kind) {
      case IncrementalUpdateReport::Kind::kUnchanged: return "unchanged";
      case IncrementalUpdateReport::Kind::kIncremental: return "incremental";
      case IncrementalUpdateReport::Kind::kBatch: return "batch";
    }
    return "";
  }
  void reset() {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    segmenter_.reset();
  }
  void save_ledger(const std::string& path) {
    std::ostringstream text;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      segmenter_.save_ledger(text);
    }
    write_file_atomically(path, text.str());
  }
  void load_ledger(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot read the id ledger " + path);
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    segmenter_.load_ledger(in);
  }

 private:
  std::mutex mutex_;
  IncrementalSegmenter segmenter_;
  FramedUpdates framed_;  // places each result: the rooms an update left alone keep their deepest cells
  GridFrame frame_;  // of the latest update, for resegment()
};

void bind_results(py::module_& m) {
  py::class_<RoomView>(m, "Room",
                       "A room: id (its label), kind, polygon in the map frame (metres), area, centroid, a point inside, bounding box.")
      .def_property_readonly("id", getter<RoomView>([](const RoomView& r) { return r.room.id; }),
                             "the room's id: its value in the Segmentation's labels (1..N; 0 there is no room)")
      .def_property_readonly("area", getter<RoomView>([](const RoomView& r) { return r.room.area; }),
                             "m², of the polygon (outer minus holes), as every output's area")
      .def_property_readonly("labelled_area", getter<RoomView>([](const RoomView& r) { return r.room.labelled_area; }),
                             "m², of the room's labelled cells (count of labels == id times the cell area)")
      .def_property_readonly("kind", getter<RoomView>([](const RoomView& r) { return std::string(room_kind_name(r.room.kind)); }),
                             "'corridor' (long for its width, narrow, opening onto several rooms) or 'room'; measured on the "
                             "final rooms (thresholds: RoomKindOptions in room_kinds.h)")
      .def_property_readonly("centroid", getter<RoomView>([](const RoomView& r) { return xy(r.room.centroid); }),
                             "(x, y) of the labelled cells")
      .def_property_readonly("inside", getter<RoomView>([](const RoomView& r) { return xy(r.placement.inside); }),
                             "(x, y) of the room's cell farthest from its edge: always in the room, a place for its name")
      .def_property_readonly("bbox", getter<RoomView>([](const RoomView& r) {
        return py::make_tuple(r.placement.min.x, r.placement.min.y, r.placement.max.x, r.placement.max.y);
      }), "(xmin, ymin, xmax, ymax) of the polygon")
      .def_property_readonly("outer", getter<RoomView>([](const RoomView& r) { return points_array(r.room.polygon.outer); }),
                             "outer ring, (n, 2) array, counter-clockwise, not closed")
      .def_property_readonly("holes", getter<RoomView>([](const RoomView& r) {
        py::list holes;
        for (const Ring& h : r.room.polygon.holes) holes.append(points_array(h));
        return holes;
      }), "list of (n, 2) arrays, clockwise")
      .def("__repr__", [](const py::object& self) {
        const RoomView& r = state_of<RoomView>(self);
        return "<topocut.Room " + std::to_string(r.room.id) + ", " + room_kind_name(r.room.kind) + ", " + std::to_string(r.room.area) + " m²>";
      })
      .def(py::pickle([](const py::object& self) { return room_state(state_of<RoomView>(self)); },
                      [](const py::tuple& t) { return room_from(t); }));
  py::class_<Passage>(m, "Passage", "A passage between two rooms: the cut that separates them.")
      .def_property_readonly("rooms", getter<Passage>([](const Passage& p) { return py::make_tuple(p.room_a, p.room_b); }),
                             "(room a, room b), a < b")
      .def_property_readonly("cut", getter<Passage>([](const Passage& p) { return points_array({p.cut.a, p.cut.b}); }),
                             "(2, 2) array: the cut's end points")
      .def_property_readonly("width", getter<Passage>([](const Passage& p) { return p.width; }), "metres")
      .def_property_readonly("kind", getter<Passage>([](const Passage& p) { return std::string(passage_kind(p)); }),
                             "'door' (a narrow gap in a wall) or 'opening' (a wider one)")
      .def_property_readonly("rule", getter<Passage>([](const Passage& p) { return to_string(p.rule); }),
                             "the pipeline rule that made the cut: 'door', 'wall-opening', 'island-cut', 'wall-line' or 'decomposition'")
      .def("__repr__", [](const py::object& self) {
        const Passage& p = state_of<Passage>(self);
        return "<topocut.Passage " + std::to_string(p.room_a) + "-" + std::to_string(p.room_b) + ", " + passage_kind(p) + ">";
      })
      .def(py::pickle([](const py::object& self) { return passage_state(state_of<Passage>(self)); },
                      [](const py::tuple& t) { return passage_from(t); }));
  py::class_<Result>(m, "Segmentation", "The rooms of a grid: labels, rooms, passages.")
      .def_property_readonly("labels", getter<Result>([](const Result& r) { return labels_view(r.result); }),
                             "int32 array, the grid's shape and row order: 0 no room, else the room id (read-only view, no copy);\n"
                             "evaluate() takes it as it is (it knows this row order)")
      .def_property_readonly("rooms", getter<Result>([](const Result& r) { return rooms_of(r.result); }), "list of Room, by id")
      .def_property_readonly("passages", getter<Result>([](const Result& r) { return r.result->segmentation.passages; }),
                             "list of Passage")
      .def_property_readonly("resolution", getter<Result>([](const Result& r) { return r.result->segmentation.resolution; }))
      .def_property_readonly("origin", getter<Result>([](const Result& r) { return xy(r.result->segmentation.origin); }),
                             "(x, y) of the grid's lower-left corner, map frame")
      .def("room_at", [](const py::object& self, double x, double y) { return room_at_py(state_of<Result>(self), x, y); },
           py::arg("x"), py::arg("y"),
           "The Room whose labelled cell holds the point (x, y) of the map frame (metres), or None when the\n"
           "point is on no room's cell (an obstacle, unknown space, off the grid): `topocut segment --at X,Y`.")
      .def("to_json", [](const py::object& self) {
        const Result& r = state_of<Result>(self);
        return rooms_to_json(r.result->segmentation, r.result->placements);
      }, "The rooms JSON the topocut command writes with --out-json (metres, map frame).")
      .def("to_geojson", [](const py::object& self) {
        const Result& r = state_of<Result>(self);
        return rooms_to_geojson(r.result->segmentation, r.result->placements);
      }, "The GeoJSON FeatureCollection the topocut command writes with --out-geojson (map frame, metres):\n"
         "rooms as Polygons (RFC 7946 ring order, closed rings), passages as LineStrings.")
      .def(py::pickle([](const py::object& self) { return result_state(state_of<Result>(self)); },
                      [](const py::tuple& t) { return result_from(t); }));
  py::class_<Map>(m, "Map", "A loaded map: grid (int8, -1 unknown / 0 free / 100 occupied, row 0 at the origin as in ROS), resolution, origin.")
      .def_property_readonly("grid", getter<Map>([](const Map& map) { return map.grid; }),
                             "int8 array (height, width): -1 unknown, 0 free, 100 occupied; row 0 is the row at the origin\n"
                             "(the bottom of the image, as nav_msgs/OccupancyGrid): segment() takes it as it is")
      .def_property_readonly("resolution", getter<Map>([](const Map& map) { return map.resolution; }), "metres per cell")
      .def_property_readonly("origin", getter<Map>([](const Map& map) { return map.origin; }), "(x, y, yaw) of the lower-left corner")
      .def_property_readonly("cells", getter<Map>([](const Map& map) { return map.cells; }),
                             "how the file's values were read (palette or thresholds)")
      .def(py::pickle([](const py::object& self) { return map_state(state_of<Map>(self)); },
                      [](const py::tuple& t) { return map_from(t); }));
}

}  // namespace

std::optional<cv::Mat> segment_labels_top_down(const py::handle& labels) {
  if (py::isinstance<Result>(labels)) return segment_labels_top_down(labels.attr("labels"));
  if (!py::isinstance<py::array>(labels)) return std::nullopt;
  const auto array = py::reinterpret_borrow<py::array>(labels);
  const py::object base = array.base();
  if (base.is_none() || !PyCapsule_IsValid(base.ptr(), kLabelsCapsule)) return std::nullopt;
  const Shared& result = *static_cast<Shared*>(PyCapsule_GetPointer(base.ptr(), kLabelsCapsule));
  const cv::Mat& own = result->segmentation.labels;
  // A view of the view (a flip, a slice) has the same base: only the array as returned qualifies.
  if (array.data() != own.data || array.ndim() != 2 || array.shape(0) != own.rows || array.shape(1) != own.cols ||
      array.strides(0) != static_cast<py::ssize_t>(own.step[0]) || array.strides(1) != static_cast<py::ssize_t>(sizeof(std::int32_t)))
    return std::nullopt;
  cv::Mat top_down;
  if (result->frame.row_order == RowOrder::kBottomUp) {
    cv::flip(own, top_down, 0);
  } else {
    top_down = own.clone();
  }
  return top_down;
}

namespace {

// The rule list's rows as (name, stage, keyword or None, what it does).
py::list segmentation_rules_py() {
  py::list rows;
  for (const RuleListing& row : rule_listing(segmentation_rules())) {
    py::object keyword = py::none();
    if (!row.switch_name.empty()) keyword = py::str(underscored_option_name(row.switch_name));
    rows.append(py::make_tuple(row.name, row.stage, keyword, row.does));
  }
  return rows;
}

}  // namespace

void bind_segmentation(py::module_& m) {
  bind_results(m);
  m.def("segment", &segment_py, py::arg("grid"), py::arg("resolution") = 0.05, py::arg("origin") = py::make_tuple(0.0, 0.0, 0.0),
        ("Segments a grid into rooms.\n\n"
         "grid: 2-D int8 array (nav_msgs/OccupancyGrid values: -1 unknown, 0..100 occupancy; row 0 at the\n"
         "origin unless row_order='top-down') or uint8 grey image (255 free, 0 occupied; rows top-down unless\n"
         "row_order='bottom-up'). resolution: metres per cell. origin: (x, y[, yaw]) of the lower-left corner.\n"
         "int8 cells are free below free_thresh (0.196) and occupied above occupied_thresh (0.65); grey cells\n"
         "follow the palette read from the image, or free_threshold (250) / occupied_threshold (50) with\n"
         "fixed_thresholds=True. Other keywords are the topocut segment command's options with '_' for '-': " +
         segment_option_names() +
         ".\nReturns a Segmentation (labels in the grid's row order, rooms and passages in the map frame).\n"
         "Raises ValueError on bad input. The GIL is released while segmenting.").c_str());
  m.def("segmentation_rules", &segmentation_rules_py,
        "The pipeline segment() runs, one tuple a row in the order the rows run: (name, stage, switch, what it\n"
        "does); switch is the keyword that turns the row off (no_NAME=True), or None: on with its stage. What\n"
        "`topocut rules` prints.");
  m.def("load_options", &load_options_py, py::arg("path"),
        "The segmentation options of a robot's YAML file, read as `topocut segment --config FILE` reads them\n"
        "(the same keys, '_' or '-', the same checks and messages): a dict of segment()'s keywords, so\n"
        "topocut.segment(grid, resolution, origin, **topocut.load_options('robot.yaml')). Raises\n"
        "FileNotFoundError for a missing file, ValueError naming the file and key on bad YAML, a key that is no\n"
        "segmentation option (with the name meant), a key given twice or empty, or a bad value.");
  m.def("load_map", &load_map_py, py::arg("path"), py::arg("resolution") = py::none(),
        ("Loads a ROS map_server YAML or an image as the topocut command does; returns a Map whose int8 grid\n"
         "(ROS encoding and row order) segment() takes as it is. Keywords: the command's map-loading options\n"
         "with '_' for '-' (" + map_load_option_names() + "), checked as there; giving a threshold means\n"
         "fixed thresholds. An image without resolution= warns (UserWarning) that 0.05 m was assumed.\n"
         "Raises ValueError on a bad file or option.").c_str());
  py::class_<PyIncremental>(m, "IncrementalSegmenter",
                            "Segments a growing map update by update, reusing the rooms a change did not reach (ids stay).\n"
                            "Keywords: segment()'s options and absorb_area, absorb_fraction, absorb_across_rooms, batch_fraction,\n"
                            "neighbours_across_doors, neighbours_across_cuts, speck_size, split_after, merge_after.")
      .def(py::init<py::kwargs>())
      .def("update", [](const py::object& self, const py::array& grid, double resolution, const py::object& origin,
                        py::kwargs kwargs) { return state_of<PyIncremental>(self).update(grid, resolution, origin, std::move(kwargs)); },
           py::arg("grid"), py::arg("resolution") = 0.05, py::arg("origin") = py::make_tuple(0.0, 0.0, 0.0),
           "Segments the new grid (as segment() takes it; row_order and thresholds as keywords); returns a Segmentation\n"
           "whose room ids are stable across updates. The GIL is released while segmenting.")
      .def("resegment", [](const py::object& self) { return state_of<PyIncremental>(self).resegment(); },
           "Segments the latest grid again as a whole (a map at rest): segment()'s rooms, ids carried by overlap.\n"
           "Raises ValueError before the first update. The GIL is released while segmenting.")
      .def_property_readonly("last_update", getter<PyIncremental>([](PyIncremental& s) { return s.last_update(); }),
                             "'unchanged', 'incremental' or 'batch'")
      .def("reset", [](const py::object& self) { state_of<PyIncremental>(self).reset(); },
           "Forgets everything; the next update starts afresh.")
      .def("save_ledger", [](const py::object& self, const std::string& path) { state_of<PyIncremental>(self).save_ledger(path); },
           py::arg("path"),
           "Writes the room ids with the latest rooms to path (atomically), for load_ledger() after a restart.\n"
           "Raises ValueError before the first update or when the file cannot be written.")
      .def("load_ledger", [](const py::object& self, const std::string& path) { state_of<PyIncremental>(self).load_ledger(path); },
           py::arg("path"),
           "Forgets everything, then reads a ledger save_ledger() wrote: the next update gives the saved rooms\n"
           "their ids back where they overlap. Raises ValueError on a missing or damaged file.");
}

}  // namespace topocut::python
