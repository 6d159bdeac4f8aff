#include "rooms_adapter.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include "topocut/core/error.h"
#include "topocut/core/grid_array_options.h"
#include "topocut/core/option_names.h"
#include "topocut/core/option_table.h"
#include "topocut/core/option_text.h"
#include "topocut/io/map_load_flags.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/image_input.h"  // ImageLimits
#include "topocut/segmentation/room_at.h"
#include "topocut/segmentation/segment_switches.h"
#include "topocut/topocut.h"

namespace topocut_ros {
namespace {

using topocut::Error;
using topocut::OptionRow;
using topocut::SegmentSettings;

// What the node reads beside the segmentation and incremental options: how a map's values become
// cells, when the rooms settle, and the largest map it segments.
struct MapSettings {
  topocut::GridArray cells;   // map_server's thresholds (occupancy_threshold_rows()); the rest is the map's
  double settle_after = 2.0;  // seconds without a changed map before the rooms become segment()'s
  std::string id_ledger;      // file the room ids are kept in across restarts ("" = none)
  topocut::MapLoadOptions load;  // its limits (the map-loading row --max-megapixels); the map brings the rest
};

struct NodeSettings {
  SegmentSettings segment;
  MapSettings map;
  topocut::IncrementalOptions incremental;  // its own fields (incremental_option_rows()); segment above
};

// The node's rows, after segment_option_rows() (named with '_', as ROS parameters are): map_server's
// thresholds and the image limit are the library's rows; settle_after is the node's own.
const std::vector<OptionRow<MapSettings>>& map_option_rows() {
  static const std::vector<OptionRow<MapSettings>> rows = [] {
    std::vector<OptionRow<MapSettings>> all =
        topocut::rows_within<MapSettings>(topocut::occupancy_threshold_rows(), [](auto& s) -> auto& { return s.cells; });
    all.push_back(topocut::field_row("settle-after", "S", topocut::OptionRange::kNonNegative, &MapSettings::settle_after,
                                     "seconds without a changed map after which the rooms are segment()'s (0: never)"));
    const std::vector<OptionRow<topocut::MapLoadOptions>> limit = {
        *topocut::find_option(topocut::map_load_option_rows(), std::string(topocut::kMaxMegapixelsOption))};
    for (OptionRow<MapSettings>& row : topocut::rows_within<MapSettings>(limit, [](auto& s) -> auto& { return s.load; }))
      all.push_back(std::move(row));
    for (OptionRow<MapSettings>& row : all) row.name = topocut::underscored_option_name(row.name);
    return all;
  }();
  return rows;
}

// The file the ids are kept in, a path.
const std::vector<topocut::TextRow<MapSettings>>& map_text_rows() {
  static const std::vector<topocut::TextRow<MapSettings>> rows = [] {
    std::vector<topocut::TextRow<MapSettings>> all = {topocut::path_row(
        "id-ledger", "PATH", topocut::TextKind::kOutput, &MapSettings::id_ledger,
        "file the room ids are kept in: read at start, written when the rooms settle and at shutdown, so that ids survive a restart")};
    for (topocut::TextRow<MapSettings>& row : all) row.name = topocut::underscored_option_name(row.name);
    return all;
  }();
  return rows;
}

std::vector<std::string> known_names() {
  std::vector<std::string> names;
  for (const auto& row : topocut::segment_option_rows()) names.push_back(topocut::underscored_option_name(row.name));
  for (const auto& row : topocut::incremental_option_rows()) names.push_back(topocut::underscored_option_name(row.name));
  for (const auto& row : map_option_rows()) names.push_back(row.name);
  for (const auto& row : map_text_rows()) names.push_back(row.name);
  return names;
}

// "~name is not a parameter of topocut_node[, ignored] (did you mean ~nearest?)": close means a typo's distance.
std::string unknown_name(const std::string& name, bool ignored) {
  const std::string best = topocut::closest_option_name(name, known_names());
  return "~" + name + " is not a parameter of topocut_node" + (ignored ? ", ignored" : "") + (best.empty() ? "" : " (did you mean ~" + best + "?)");
}

// The value of p for row: a number for a number, true/false for a switch; Error with the reason
// otherwise. A text (a service option's value, or a parameter set as a string, as roslaunch's
// <param value="yes"/> is) is read by the readers of every front end, so that "2.5", "0x10" and "yes"
// mean here what they mean on the command line and in --config.
template <typename Target>
double value_for(const OptionRow<Target>& row, const Parameter& p) {
  const std::string shown = "~" + p.name;
  if (p.kind == Parameter::Kind::kText) {
    if (!row.is_switch()) return topocut::parse_option_number(p.text, shown);
    const std::optional<bool> on = topocut::parse_switch_value(p.text);
    if (!on) throw Error(topocut::switch_value_error(shown, p.text));
    return *on ? 1.0 : 0.0;
  }
  const std::string given = p.kind == Parameter::Kind::kFlag     ? (p.flag ? "true" : "false")
                            : p.kind == Parameter::Kind::kNumber ? topocut::shortest_number(p.number)
                                                                 : p.text;
  if (row.is_switch()) {
    if (p.kind == Parameter::Kind::kFlag) return p.flag ? 1.0 : 0.0;
    throw Error(topocut::switch_value_error(shown, given));
  }
  if (p.kind == Parameter::Kind::kNumber) return p.number;
  throw Error(shown + " needs a number, not '" + given + "'");
}

template <typename Target>
bool set_row(const std::vector<OptionRow<Target>>& rows, const std::string& name, Target& target, const Parameter& p) {
  const OptionRow<Target>* row = topocut::find_option(rows, name);
  if (row != nullptr) topocut::set_option(*row, target, value_for(*row, p), "~" + p.name);
  return row != nullptr;
}

template <typename Target>
const topocut::TextRow<Target>* find_text_row(const std::vector<topocut::TextRow<Target>>& rows, const std::string& name) {
  for (const topocut::TextRow<Target>& row : rows)
    if (row.name == name) return &row;
  return nullptr;
}

// settings with the parameters given, each checked by its row of the option tables; an unknown
// name is appended to unknown, or an Error when unknown is null (a service call's options).
NodeSettings read_parameters(NodeSettings settings, const std::vector<Parameter>& given, std::vector<std::string>* unknown) {
  for (const Parameter& p : given) {
    if (const auto* row = find_text_row(map_text_rows(), topocut::underscored_option_name(p.name))) {
      if (p.kind != Parameter::Kind::kText) throw Error("~" + row->name + " needs the path of a file");
      topocut::set_text_option(*row, settings.map, p.text, "~" + row->name);
      continue;
    }
    if (set_row(topocut::segment_option_rows(), topocut::dashed_option_name(p.name), settings.segment, p) ||
        set_row(topocut::incremental_option_rows(), topocut::dashed_option_name(p.name), settings.incremental, p) ||
        set_row(map_option_rows(), topocut::underscored_option_name(p.name), settings.map, p))
      continue;
    if (unknown == nullptr) throw Error(unknown_name(p.name, false));
    unknown->push_back(unknown_name(p.name, true));
  }
  topocut::to_segment_options(settings.segment);  // the combination, checked before any map arrives
  return settings;
}

// A service call's "name=value" / "name" options as the parameters they override, each value a text
// for its row to read (value_for()); an option given twice (robot_radius and robot-radius name one)
// or without a name is refused, as the command line and --config refuse them.
std::vector<Parameter> options_as_parameters(const std::vector<std::string>& options) {
  std::vector<Parameter> out;
  std::vector<std::string> names;
  for (const std::string& option : options) {
    const std::size_t equals = option.find('=');
    Parameter p;
    p.name = option.substr(0, equals);
    if (p.name.empty()) throw Error("the option '" + option + "': an empty name is no option name");
    const std::string name = topocut::dashed_option_name(p.name);
    if (std::find(names.begin(), names.end(), name) != names.end()) throw Error(topocut::given_twice_error("~" + p.name));
    names.push_back(name);
    if (equals == std::string::npos) {  // "no_merge": a switch turned on, as on the command line
      p.kind = Parameter::Kind::kFlag;
      p.flag = true;
    } else {
      p.kind = Parameter::Kind::kText;
      p.text = option.substr(equals + 1);
    }
    out.push_back(p);
  }
  return out;
}

// The settings' segmentation options over base (the CLI's for segment(), the incremental segmenter's
// for update()).
NodeSettings over(const topocut::SegmentOptions& base, const std::vector<Parameter>& given, std::vector<std::string>* unknown) {
  NodeSettings settings;
  settings.segment.options = base;
  return read_parameters(settings, given, unknown);
}

// nav_msgs holds the resolution as float32: 0.05 arrives as 0.0500000007. The shortest decimal that
// reads back as the same float is the one the map was written with, and what `topocut segment` reads.
double written_resolution(float resolution) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text - 1, resolution).ptr;
  *end = '\0';
  return std::strtod(text, nullptr);
}

topocut::GridArray array_of(const MapInput& map, const MapSettings& settings) {
  if (map.size != static_cast<std::size_t>(map.width) * map.height)
    throw Error("the map's data holds " + std::to_string(map.size) + " values for " + std::to_string(map.width) + " x " +
                std::to_string(map.height) + " cells");
  // Before any cell is read: a well-formed map of 2^31 cells would need about 30 GB to segment.
  if (static_cast<double>(map.width) * map.height > settings.load.limits.max_megapixels * 1e6)
    throw Error("the map has " + std::to_string(map.width) + " x " + std::to_string(map.height) +
                " cells, more than the limit of " + topocut::shortest_number(settings.load.limits.max_megapixels) +
                " megapixels (parameter ~max_megapixels)");
  topocut::GridArray array;
  array.free_thresh = settings.cells.free_thresh;
  array.occupied_thresh = settings.cells.occupied_thresh;
  array.data = map.data;
  array.width = static_cast<int>(map.width);
  array.height = static_cast<int>(map.height);
  array.resolution = written_resolution(map.resolution);
  array.origin = {map.x, map.y, map.yaw};
  return array;
}

std::vector<double> coordinates(const topocut::Ring& ring) {
  std::vector<double> out;
  for (const topocut::Point2& p : ring) out.insert(out.end(), {p.x, p.y});
  return out;
}

RoomShape shape_of(const topocut::Room& room, const topocut::RoomPlacement& placement) {
  RoomShape shape;
  shape.id = room.id;
  shape.outer = coordinates(room.polygon.outer);
  for (const topocut::Ring& hole : room.polygon.holes) shape.holes.push_back(coordinates(hole));
  shape.centre_x = room.centroid.x, shape.centre_y = room.centroid.y;
  shape.inside_x = placement.inside.x, shape.inside_y = placement.inside.y;
  shape.min_x = placement.min.x, shape.min_y = placement.min.y;
  shape.max_x = placement.max.x, shape.max_y = placement.max.y;
  shape.area = room.area;
  shape.corridor = room.kind == topocut::RoomKind::kCorridor;
  return shape;
}

RoomsOutput output_of(const topocut::GridSegmentation& rooms) {
  const topocut::Segmentation& s = rooms.segmentation;
  if (!s.rooms.empty() && s.rooms.back().id > 0xffff)
    throw Error("room id " + std::to_string(s.rooms.back().id) + " does not fit the 16-bit label image");
  RoomsOutput out;
  out.labels.resize(s.labels.total());
  std::size_t k = 0;
  for (int r = 0; r < s.labels.rows; ++r) {  // already bottom-up (the map's order)
    const int* row = s.labels.ptr<int>(r);
    for (int c = 0; c < s.labels.cols; ++c) out.labels[k++] = static_cast<std::uint16_t>(row[c]);
  }
  for (std::size_t i = 0; i < s.rooms.size(); ++i) out.rooms.push_back(shape_of(s.rooms[i], rooms.placements[i]));
  for (const topocut::Passage& p : s.passages)
    out.passages.push_back({p.room_a, p.room_b, p.cut.a.x, p.cut.a.y, p.cut.b.x, p.cut.b.y, p.width, p.door,
                            topocut::to_string(p.rule)});
  out.json = topocut::rooms_to_json(s, rooms.placements);
  return out;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Runs work, its Error made one line fit for a log or a response (control characters out, a long
// name cut to its ends), as the command line and Python show every message.
template <typename Work>
auto one_line(const Work& work) -> decltype(work()) {
  try {
    return work();
  } catch (const Error& e) {
    throw Error(topocut::one_line_message(e.what()));
  }
}

}  // namespace

std::string parameters_help() {
  std::string out;
  auto line = [&](const std::string& name, const std::string& value_name, const std::string& help, const std::string& fallback) {
    std::string left = "  _" + name + ":=" + (value_name.empty() ? "true" : value_name);
    if (left.size() < 28) left += std::string(28 - left.size(), ' ');
    out += left + " " + help + (fallback.empty() ? "" : " (default " + fallback + ")") + "\n";
  };
  const NodeSettings defaults{{topocut::IncrementalOptions{}.segment, {}}, {}, {}};
  for (const auto& row : topocut::segment_option_rows())
    line(topocut::underscored_option_name(row.name), row.value_name, row.help, row.is_switch() ? "" : topocut::shortest_number(row.get(defaults.segment)));
  for (const auto& row : topocut::incremental_option_rows())
    line(topocut::underscored_option_name(row.name), row.is_switch() ? "false" : row.value_name, row.help,
         row.is_switch() ? (row.get(defaults.incremental) != 0.0 ? "true" : "false") : topocut::shortest_number(row.get(defaults.incremental)));
  for (const auto& row : map_option_rows())
    line(row.name, row.value_name, row.help, topocut::shortest_number(row.get(defaults.map)));
  for (const auto& row : map_text_rows()) line(row.name, row.value_name, row.help, "none");
  return out;
}

struct RoomsAdapter::State {
  std::vector<Parameter> parameters;  // as given at start-up, for segment()'s options to go over
  NodeSettings live;                  // over the incremental segmenter's defaults
  topocut::IncrementalSegmenter segmenter;
  topocut::FramedUpdates framed;                    // places every result: the rooms it left alone keep their cells
  std::optional<topocut::GridSegmentation> latest;  // the rooms last published, for room_at()
  topocut::GridFrame frame;                         // of the map they are of
  State(std::vector<Parameter> given, NodeSettings settings, const topocut::IncrementalOptions& options)
      : parameters(std::move(given)), live(std::move(settings)), segmenter(options) {}
};

RoomsAdapter::RoomsAdapter(const std::vector<Parameter>& parameters, std::vector<std::string>& unknown) {
  one_line([&] { start(parameters, unknown); });
}

void RoomsAdapter::start(const std::vector<Parameter>& parameters, std::vector<std::string>& unknown) {
  NodeSettings live = over(topocut::IncrementalOptions{}.segment, parameters, &unknown);
  topocut::IncrementalOptions options = live.incremental;
  options.segment = topocut::to_segment_options(live.segment);
  std::vector<std::string> reported;  // the same names again
  over(topocut::SegmentOptions{}, parameters, &reported);  // segment()'s combination is checked at start-up too
  state_ = std::make_unique<State>(parameters, live, options);
  const std::string& path = live.map.id_ledger;
  std::ifstream in(path);
  if (!path.empty() && in) {
    try {
      state_->segmenter.load_ledger(in);
    } catch (const Error& e) {
      throw Error("~id_ledger " + path + ": " + e.what());
    }
  }
}

RoomsAdapter::~RoomsAdapter() = default;

std::string RoomsAdapter::settings_summary() const {
  const NodeSettings& live = state_->live;
  std::string given, defaulted;
  auto add = [&](const std::string& name, const std::string& value, bool was_given) {
    std::string& list = was_given ? given : defaulted;
    list += (list.empty() ? "" : ", ") + name + " " + value;
  };
  auto was_given = [&](const std::string& name) {
    for (const Parameter& p : state_->parameters)
      if (topocut::underscored_option_name(p.name) == name) return true;
    return false;
  };
  for (const auto& row : topocut::segment_option_rows()) {
    const std::string name = topocut::underscored_option_name(row.name);
    const bool set = was_given(name);
    if (!set && name != "concavity" && name != "robot_radius") continue;  // the rest: their defaults, --help
    add(name, row.is_switch() ? (row.get(live.segment) != 0.0 ? "true" : "false") : topocut::shortest_number(row.get(live.segment)), set);
  }
  for (const auto& row : topocut::incremental_option_rows()) {
    const std::string name = topocut::underscored_option_name(row.name);
    if (was_given(name))
      add(name, row.is_switch() ? (row.get(live.incremental) != 0.0 ? "true" : "false") : topocut::shortest_number(row.get(live.incremental)), true);
  }
  for (const auto& row : map_option_rows())
    if (was_given(row.name)) add(row.name, topocut::shortest_number(row.get(live.map)), true);
  for (const auto& row : map_text_rows())
    if (was_given(row.name)) add(row.name, live.map.id_ledger, true);
  return (given.empty() ? "" : "given: " + given + "; ") + "defaults: " + (defaulted.empty() ? "" : defaulted + " and ") +
         "the rest (topocut_node --help lists them)";
}

RoomsOutput RoomsAdapter::update(const MapInput& map) {
  return one_line([&] { return update_once(map); });
}

RoomsOutput RoomsAdapter::update_once(const MapInput& map) {
  const topocut::GridArray array = array_of(map, state_->live.map);
  const topocut::OccupancyGrid grid = topocut::grid_from_array(array);  // validates the array
  const auto start = std::chrono::steady_clock::now();
  state_->segmenter.update(grid);
  const double update_ms = ms_since(start);
  state_->frame = topocut::frame_of(array);
  topocut::GridSegmentation rooms = state_->framed.place(state_->segmenter, state_->frame);
  RoomsOutput out = output_of(rooms);
  state_->latest = std::move(rooms);
  out.update_ms = update_ms;
  const char* kinds[] = {"unchanged", "incremental", "batch"};
  out.kind = kinds[static_cast<int>(state_->segmenter.last_update().kind)];
  return out;
}

RoomsOutput RoomsAdapter::segment(const MapInput& map, const std::vector<std::string>& options) {
  return one_line([&] { return segment_once(map, options); });
}

RoomsOutput RoomsAdapter::segment_once(const MapInput& map, const std::vector<std::string>& options) {
  std::vector<std::string> reported;  // the start-up parameters' unknown names, reported then
  NodeSettings settings = over(topocut::SegmentOptions{}, state_->parameters, &reported);
  settings = read_parameters(settings, options_as_parameters(options), nullptr);
  const topocut::GridArray array = array_of(map, settings.map);
  const topocut::OccupancyGrid grid = topocut::grid_from_array(array);
  const auto start = std::chrono::steady_clock::now();
  topocut::GridSegmentation rooms =
      topocut::segment_grid(grid, topocut::frame_of(array), topocut::to_segment_options(settings.segment));
  const double segment_ms = ms_since(start);
  RoomsOutput out = output_of(rooms);  // a what-if: the published rooms and their ids stay
  out.update_ms = segment_ms;
  out.kind = "segment";
  return out;
}

RoomsOutput RoomsAdapter::settle() {
  if (!state_->latest) return {};
  const auto start = std::chrono::steady_clock::now();
  state_->segmenter.resegment();
  const double settle_ms = ms_since(start);
  topocut::GridSegmentation rooms = state_->framed.place(state_->segmenter, state_->frame);
  RoomsOutput out = output_of(rooms);
  state_->latest = std::move(rooms);
  out.update_ms = settle_ms;
  out.kind = "settled";
  return out;
}

double RoomsAdapter::settle_after() const { return state_->live.map.settle_after; }

bool RoomsAdapter::save_ledger() const {
  if (state_->live.map.id_ledger.empty() || !state_->latest) return false;
  return one_line([&] {  // the file's name may hold anything: the message stays one line
    std::ostringstream text;
    state_->segmenter.save_ledger(text);
    topocut::write_file_atomically(state_->live.map.id_ledger, text.str());
    return true;
  });
}

int RoomsAdapter::room_at(double x, double y, RoomShape* room) const {
  // The point is checked before there are rooms too: a caller learns of a bad point at once.
  if (!std::isfinite(x) || !std::isfinite(y)) throw Error("the point must have finite coordinates, not (" + std::to_string(x) + ", " + std::to_string(y) + ")");
  if (!state_->latest) return 0;
  const topocut::GridSegmentation& latest = *state_->latest;
  const int id = topocut::room_at(latest, {x, y});
  for (std::size_t i = 0; i < latest.segmentation.rooms.size(); ++i)
    if (id != 0 && latest.segmentation.rooms[i].id == id) *room = shape_of(latest.segmentation.rooms[i], latest.placements[i]);
  return id;
}

}  // namespace topocut_ros
