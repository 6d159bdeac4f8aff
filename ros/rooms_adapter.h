#pragma once
// The library side of topocut_node, behind plain types: ROS 1's message headers do not compile as
// C++20 (they use std::allocator<void>::rebind) and the library needs C++20, so the node is two
// translation units, this adapter (C++20, the library) and the message glue (C++17, roscpp).
// A ROS 2 node would reuse this adapter and replace only the glue.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace topocut_ros {

// A nav_msgs/OccupancyGrid's values and metadata (rows bottom-up, as ROS stores them).
struct MapInput {
  const std::int8_t* data = nullptr;
  std::size_t size = 0;  // number of values in data (checked against width * height)
  std::uint32_t width = 0, height = 0;
  float resolution = 0.0f;  // as nav_msgs/MapMetaData holds it; read as the decimal it was written as
  double x = 0.0, y = 0.0, yaw = 0.0;  // origin pose
};

struct RoomShape {
  int id = 0;
  std::vector<double> outer;               // x0, y0, x1, y1, ... (map frame, metres)
  std::vector<std::vector<double>> holes;  // the same for each hole
  double centre_x = 0.0, centre_y = 0.0;   // centroid of the room's cells
  double inside_x = 0.0, inside_y = 0.0;   // a point inside the room
  double min_x = 0.0, min_y = 0.0, max_x = 0.0, max_y = 0.0;  // bounding box of the outline
  double area = 0.0;                       // m²
  bool corridor = false;                   // its kind (room_kinds.h): a corridor, not another room
};

struct PassageShape {
  int room_a = 0, room_b = 0;
  double ax = 0.0, ay = 0.0, bx = 0.0, by = 0.0;  // the cut's ends (map frame)
  double width = 0.0;
  bool door = false;  // a door, not a wider opening
  std::string rule;   // the rule that made the cut (cut_rule.h's names)
};

struct RoomsOutput {
  std::vector<std::uint16_t> labels;  // width * height ids, rows bottom-up (the map's order)
  std::vector<RoomShape> rooms;
  std::vector<PassageShape> passages;
  std::string json;                   // the rooms JSON (rooms_json.h)
  double update_ms = 0.0;             // the library's segmentation call alone
  std::string kind;                   // "unchanged", "incremental", "batch" (live), "settled" or "segment" (a service call)
};

// One private parameter as the parameter server holds it (its name without the node's namespace).
struct Parameter {
  enum class Kind { kNumber, kFlag, kText, kOther };
  std::string name;
  Kind kind = Kind::kOther;
  double number = 0.0;  // kNumber (an int or a double)
  bool flag = false;    // kFlag
  std::string text;     // kText; kOther: what it is (a list, a dictionary, ...)
};

// The parameters topocut_node takes: every option of `topocut segment` (segment_option_rows(), '_'
// for '-'), the incremental segmenter's (incremental_option_rows()) and the node's own (map_server's
// free_thresh and occupied_thresh, settle_after, max_megapixels, id_ledger), each with its help line
// and default, for --help.
std::string parameters_help();

class RoomsAdapter {
 public:
  // Options from the parameters. A text value is read as the command line reads one ("2.5", "yes").
  // Throws std::runtime_error (topocut::Error) naming the parameter and the reason for a value of the
  // wrong type or out of range; appends one line per unknown name (with the nearest known name when
  // one is close) to unknown.
  RoomsAdapter(const std::vector<Parameter>& parameters, std::vector<std::string>& unknown);
  ~RoomsAdapter();

  // One line for the start-up log: the parameters given with the values they set, then concavity and
  // robot_radius when they were not given ("given: ...; defaults: ...").
  std::string settings_summary() const;

  // Segments the next map incrementally. Throws std::runtime_error with one clear sentence on a
  // malformed map (size, resolution, values: the state is unchanged then) or a room id above 65535.
  RoomsOutput update(const MapInput& map);

  // Segments map at once with the options of `topocut segment`, the parameters and then options
  // ("name=value", or "name" for a switch on) over them, each read as the command line reads it.
  // Throws std::runtime_error on an unknown option, a bad value, an option given twice, an empty name
  // or a malformed map. Every message is one line. A what-if: the published rooms (room_at()) stay.
  RoomsOutput segment(const MapInput& map, const std::vector<std::string>& options);

  // The latest map segmented as a whole (the map stopped changing): the rooms of `topocut segment`
  // with the live ids carried by overlap (kind "settled"); empty before the first update.
  RoomsOutput settle();
  // Seconds without a changed map after which the node settles (~settle_after; 0: never).
  double settle_after() const;
  // Writes the id ledger to ~id_ledger (atomically); false when there is none or nothing to save.
  // Throws std::runtime_error when the file cannot be written.
  bool save_ledger() const;

  // The id of the room holding (x, y) (map frame) in the rooms last published (update()'s or
  // settle()'s), and that room in *room; 0 (and *room untouched) when no room holds it or nothing
  // was published. Throws std::runtime_error for a point that is not finite.
  int room_at(double x, double y, RoomShape* room) const;

 private:
  void start(const std::vector<Parameter>& parameters, std::vector<std::string>& unknown);
  RoomsOutput update_once(const MapInput& map);
  RoomsOutput segment_once(const MapInput& map, const std::vector<std::string>& options);

  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace topocut_ros
