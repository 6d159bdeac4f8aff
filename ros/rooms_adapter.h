#pragma once
// The library side of topocut_node, behind plain types: ROS 1's message headers do not compile as
// C++20 (they use std::allocator<void>::rebind) and the library needs C++20, so the node is two
// translation units, this adapter (C++20, the library) and the message glue (C++17, roscpp).
// A ROS 2 node would reuse this adapter and replace only the glue.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace topocut_ros {

// A nav_msgs/OccupancyGrid's values and metadata (rows bottom-up, as ROS stores them).
struct MapInput {
  const std::int8_t* data = nullptr;
  std::size_t size = 0;  // number of values in data (checked against width * height)
  std::uint32_t width = 0, height = 0;
  double resolution = 0.0;
  double x = 0.0, y = 0.0, yaw = 0.0;  // origin pose
};

struct RoomShape {
  int id = 0;
  std::vector<double> outer;  // x0, y0, x1, y1, ... (map frame, metres)
  double inside_x = 0.0, inside_y = 0.0;  // a point inside the room
};

struct RoomsOutput {
  std::vector<std::uint16_t> labels;  // width * height ids, rows bottom-up (the map's order)
  std::vector<RoomShape> rooms;
  std::vector<double> passages;       // ax, ay, bx, by per passage (map frame)
  std::string json;                   // the rooms JSON (rooms_json.h)
  double update_ms = 0.0;             // IncrementalSegmenter::update alone
  std::string kind;                   // "unchanged", "incremental" or "batch"
};

// Reads one parameter; returns false when it is not set (the library's default then stays).
using DoubleParameter = std::function<bool(const std::string& name, double* value)>;
using FlagParameter = std::function<bool(const std::string& name, bool* value)>;

class RoomsAdapter {
 public:
  // Options from the parameters (the CLI's names with '_' for '-'); throws std::runtime_error
  // (topocut::Error) on invalid values.
  RoomsAdapter(const DoubleParameter& number, const FlagParameter& flag);
  ~RoomsAdapter();

  // Segments the next map incrementally. Throws std::runtime_error with one clear sentence on a
  // malformed map (size, resolution, values: the state is unchanged then) or a room id above 65535.
  RoomsOutput update(const MapInput& map);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace topocut_ros
