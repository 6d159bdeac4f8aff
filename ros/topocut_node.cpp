// topocut_node: rooms of a ROS map, live and on request. Subscribes `map` (nav_msgs/OccupancyGrid,
// latched or streamed; size and origin may change between messages) and, for every map, runs the
// library's incremental segmenter (a wholesale change such as a loop closure becomes a batch update
// with ids kept where rooms overlap); when no map has changed for ~settle_after seconds it segments
// the latest map as a whole (the rooms of `topocut segment`, ids carried: timing kind "settled"). It
// publishes
//   rooms/labels   sensor_msgs/Image 16UC1: the room id of every cell, in the map's row order and
//                  header (0 = no room)
//   rooms/grid     nav_msgs/OccupancyGrid: the same labels on the map's grid (-1 = no room, else the
//                  id; ids above 100 wrap to 1 + (id - 1) mod 100), for RViz's Map display and costmaps
//   rooms/rooms    topocut_msgs/Rooms: the rooms (outline, centre, inside point, bounding box, area)
//                  and passages (rooms, doorway ends, width, door or opening, rule), typed
//   rooms/markers  visualization_msgs/MarkerArray: room outlines, ids and passages, for RViz
//   rooms/graph    std_msgs/String: the rooms JSON (rooms_json.h)
//   rooms/timing   std_msgs/String: {"update_ms", "callback_ms", "kind", "rooms"} of that map
// and answers, under its own name (private, so that two nodes never take each other's over)
//   ~segment_map       topocut_msgs/SegmentMap: one map segmented at once, as `topocut segment` does
//   ~room_at           topocut_msgs/RoomAt: the room holding a point, in the rooms last published
//   ~map_segmentation  actionlib action topocut_msgs/MapSegmentation: segment_map with feedback
// (segment_map and the action are what-ifs: they change neither the published rooms nor their ids).
// With ~id_ledger the room ids are kept in that file (written when the rooms settle and at
// shutdown, read at start), so that a restarted node gives the same rooms the same ids.
// It logs its parameters and names at start and one line per map. A thin adapter: the conversion,
// segmentation and JSON are the library's, behind rooms_adapter.h (this file is C++17 because ROS
// 1's message headers are); it only moves values between messages and the adapter. Parameters
// (private, `~name`) carry the CLI's option names with '_' for '-', and the library's defaults;
// `topocut_node --help` lists them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <actionlib/server/simple_action_server.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/String.h>
#include <topocut_msgs/MapSegmentationAction.h>
#include <topocut_msgs/RoomAt.h>
#include <topocut_msgs/Rooms.h>
#include <topocut_msgs/SegmentMap.h>
#include <visualization_msgs/MarkerArray.h>

#include "rooms_adapter.h"

namespace {

using Clock = std::chrono::steady_clock;

const char* const kUsage =
    "usage: topocut_node [map:=TOPIC] [__name:=NAME] [_PARAMETER:=VALUE ...]   (or: rosrun, roslaunch)\n"
    "Rooms of the nav_msgs/OccupancyGrid on `map`, segmented incrementally for every map and published on\n"
    "rooms/labels (sensor_msgs/Image 16UC1), rooms/grid (nav_msgs/OccupancyGrid: -1 no room, else the id,\n"
    "ids above 100 wrapping), rooms/rooms (topocut_msgs/Rooms), rooms/markers (RViz), rooms/graph (the rooms\n"
    "JSON) and rooms/timing. Under the node's name (private): the services ~segment_map\n"
    "(topocut_msgs/SegmentMap: one map segmented at once, as `topocut segment` does) and ~room_at\n"
    "(topocut_msgs/RoomAt, in the published rooms), and the action ~map_segmentation\n"
    "(topocut_msgs/MapSegmentation: segment_map with feedback). A map unchanged for ~settle_after seconds is\n"
    "segmented as a whole (`topocut segment`'s rooms, the live ids carried); ~id_ledger keeps the ids in a\n"
    "file across restarts. Logs its parameters and names at start and one line per map.\n"
    "Parameters (private; an unknown name is warned about, a bad value stops the node with the reason):\n";

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

// The map's values and metadata, viewed (msg must outlive the result).
topocut_ros::MapInput map_input(const nav_msgs::OccupancyGrid& msg) {
  topocut_ros::MapInput map;
  map.data = msg.data.data();
  map.size = msg.data.size();
  map.width = msg.info.width;
  map.height = msg.info.height;
  map.resolution = msg.info.resolution;
  map.x = msg.info.origin.position.x;
  map.y = msg.info.origin.position.y;
  map.yaw = yaw_of(msg.info.origin.orientation);
  return map;
}

sensor_msgs::Image labels_image(const std_msgs::Header& header, std::uint32_t width, std::uint32_t height,
                                const std::vector<std::uint16_t>& labels) {
  sensor_msgs::Image image;
  image.header = header;
  image.height = height;
  image.width = width;
  image.encoding = "16UC1";
  image.is_bigendian = 0;
  image.step = width * 2;
  const std::uint16_t probe = 1;
  if (*reinterpret_cast<const std::uint8_t*>(&probe) == 1) {  // a little-endian host holds the bytes as sent
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(labels.data());
    image.data.assign(bytes, bytes + 2 * labels.size());
    return image;
  }
  image.data.resize(2 * labels.size());
  for (std::size_t k = 0; k < labels.size(); ++k) {
    image.data[2 * k] = static_cast<std::uint8_t>(labels[k] & 0xff);  // little-endian, as is_bigendian says
    image.data[2 * k + 1] = static_cast<std::uint8_t>(labels[k] >> 8);
  }
  return image;
}

// The labels as an occupancy grid on the map's own grid: -1 where no room, else the id, which an
// int8 holds up to 100 (the occupancy range RViz draws); larger ids wrap.
nav_msgs::OccupancyGrid labels_grid(const std_msgs::Header& header, const nav_msgs::MapMetaData& info,
                                    const std::vector<std::uint16_t>& labels) {
  nav_msgs::OccupancyGrid grid;
  grid.header = header;
  grid.info = info;
  grid.data.resize(labels.size());
  // In 16 bits, so that the loop vectorizes (an int division per cell was most of it); id 0 wraps
  // to something and is then replaced by -1.
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const std::uint16_t id = labels[k];
    const auto wrapped = static_cast<std::int8_t>(static_cast<std::uint16_t>(static_cast<std::uint16_t>(id - 1u) % 100u) + 1);
    grid.data[k] = id == 0 ? std::int8_t{-1} : wrapped;
  }
  return grid;
}

std_msgs::ColorRGBA colour_of(int id) {
  // Golden-ratio hues: neighbouring ids get distant colours, the same id always the same one.
  const double h = std::fmod(id * 0.618033988749895, 1.0) * 6.0;
  const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
  const double rgb[6][3] = {{1, x, 0}, {x, 1, 0}, {0, 1, x}, {0, x, 1}, {x, 0, 1}, {1, 0, x}};
  std_msgs::ColorRGBA c;
  const int sector = static_cast<int>(h) % 6;
  c.r = static_cast<float>(0.2 + 0.8 * rgb[sector][0]);
  c.g = static_cast<float>(0.2 + 0.8 * rgb[sector][1]);
  c.b = static_cast<float>(0.2 + 0.8 * rgb[sector][2]);
  c.a = 1.0f;
  return c;
}

geometry_msgs::Point point_of(double x, double y) {
  geometry_msgs::Point out;
  out.x = x;
  out.y = y;
  return out;
}

geometry_msgs::Polygon polygon_of(const std::vector<double>& xy) {
  geometry_msgs::Polygon out;
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
    geometry_msgs::Point32 p;
    p.x = static_cast<float>(xy[i]);
    p.y = static_cast<float>(xy[i + 1]);
    out.points.push_back(p);
  }
  return out;
}

topocut_msgs::Room room_message(const topocut_ros::RoomShape& room) {
  topocut_msgs::Room out;
  out.id = static_cast<std::uint32_t>(room.id);
  out.outline = polygon_of(room.outer);
  for (const std::vector<double>& hole : room.holes) out.holes.push_back(polygon_of(hole));
  out.centre = point_of(room.centre_x, room.centre_y);
  out.inside = point_of(room.inside_x, room.inside_y);
  out.min = point_of(room.min_x, room.min_y);
  out.max = point_of(room.max_x, room.max_y);
  out.area = room.area;
  out.kind = room.corridor ? topocut_msgs::Room::CORRIDOR : topocut_msgs::Room::ROOM;
  return out;
}

topocut_msgs::Rooms rooms_message(const std_msgs::Header& header, const topocut_ros::RoomsOutput& rooms) {
  topocut_msgs::Rooms out;
  out.header = header;
  for (const topocut_ros::RoomShape& room : rooms.rooms) out.rooms.push_back(room_message(room));
  for (const topocut_ros::PassageShape& p : rooms.passages) {
    topocut_msgs::Passage passage;
    passage.room_a = static_cast<std::uint32_t>(p.room_a);
    passage.room_b = static_cast<std::uint32_t>(p.room_b);
    passage.a = point_of(p.ax, p.ay);
    passage.b = point_of(p.bx, p.by);
    passage.width = p.width;
    passage.kind = p.door ? topocut_msgs::Passage::DOOR : topocut_msgs::Passage::OPENING;
    passage.rule = p.rule;
    out.passages.push_back(passage);
  }
  return out;
}

visualization_msgs::Marker marker(const std_msgs::Header& header, const std::string& ns, int id, int type) {
  visualization_msgs::Marker m;
  m.header = header;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  return m;
}

// Outlines (one closed line strip per room's outer ring), ids (text at a point inside each room)
// and passages (one line list), after a DELETEALL that clears the previous map's rooms.
visualization_msgs::MarkerArray room_markers(const std_msgs::Header& header, const topocut_ros::RoomsOutput& rooms,
                                             double resolution) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker clear = marker(header, "", 0, visualization_msgs::Marker::CUBE);
  clear.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(clear);
  for (const topocut_ros::RoomShape& room : rooms.rooms) {
    visualization_msgs::Marker outline = marker(header, "outlines", room.id, visualization_msgs::Marker::LINE_STRIP);
    outline.scale.x = 2.0 * resolution;
    outline.color = colour_of(room.id);
    for (std::size_t i = 0; i + 1 < room.outer.size(); i += 2) outline.points.push_back(point_of(room.outer[i], room.outer[i + 1]));
    if (!outline.points.empty()) outline.points.push_back(outline.points.front());
    out.markers.push_back(outline);
    visualization_msgs::Marker text = marker(header, "ids", room.id, visualization_msgs::Marker::TEXT_VIEW_FACING);
    text.pose.position = point_of(room.inside_x, room.inside_y);
    text.scale.z = std::max(0.5, 10.0 * resolution);
    text.color = colour_of(room.id);
    text.text = std::to_string(room.id);
    out.markers.push_back(text);
  }
  visualization_msgs::Marker passages = marker(header, "passages", 0, visualization_msgs::Marker::LINE_LIST);
  passages.scale.x = 3.0 * resolution;
  passages.color.r = passages.color.a = 1.0f;
  for (const topocut_ros::PassageShape& p : rooms.passages) {
    passages.points.push_back(point_of(p.ax, p.ay));
    passages.points.push_back(point_of(p.bx, p.by));
  }
  out.markers.push_back(passages);
  return out;
}

// The node's private parameters as the adapter reads them (names without the node's namespace).
std::vector<topocut_ros::Parameter> private_parameters(const ros::NodeHandle& private_nh) {
  std::vector<std::string> names;
  ros::param::getParamNames(names);
  const std::string prefix = private_nh.getNamespace() + "/";
  std::vector<topocut_ros::Parameter> out;
  for (const std::string& name : names) {
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    XmlRpc::XmlRpcValue value;
    if (!private_nh.getParam(name, value)) continue;
    topocut_ros::Parameter p;
    p.name = name.substr(prefix.size());
    switch (value.getType()) {
      case XmlRpc::XmlRpcValue::TypeInt: p.kind = topocut_ros::Parameter::Kind::kNumber, p.number = static_cast<int>(value); break;
      case XmlRpc::XmlRpcValue::TypeDouble: p.kind = topocut_ros::Parameter::Kind::kNumber, p.number = static_cast<double>(value); break;
      case XmlRpc::XmlRpcValue::TypeBoolean: p.kind = topocut_ros::Parameter::Kind::kFlag, p.flag = static_cast<bool>(value); break;
      case XmlRpc::XmlRpcValue::TypeString: p.kind = topocut_ros::Parameter::Kind::kText, p.text = static_cast<std::string>(value); break;
      default: p.text = value.toXml(); break;
    }
    out.push_back(p);
  }
  return out;
}

class RoomsNode {
 public:
  RoomsNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh, const std::vector<topocut_ros::Parameter>& parameters,
            std::vector<std::string>& unknown)
      : adapter_(parameters, unknown), action_(private_nh, "map_segmentation", false) {
    labels_ = nh.advertise<sensor_msgs::Image>("rooms/labels", 1, true);
    grid_ = nh.advertise<nav_msgs::OccupancyGrid>("rooms/grid", 1, true);
    rooms_ = nh.advertise<topocut_msgs::Rooms>("rooms/rooms", 1, true);
    markers_ = nh.advertise<visualization_msgs::MarkerArray>("rooms/markers", 1, true);
    graph_ = nh.advertise<std_msgs::String>("rooms/graph", 1, true);
    timing_ = nh.advertise<std_msgs::String>("rooms/timing", 10);
    segment_ = private_nh.advertiseService("segment_map", &RoomsNode::on_segment, this);
    room_at_ = private_nh.advertiseService("room_at", &RoomsNode::on_room_at, this);
    // Goals are served in the spin thread, like maps and service calls: the adapter needs no lock.
    action_.registerGoalCallback(boost::bind(&RoomsNode::on_goal, this));
    action_.start();
    map_ = nh.subscribe("map", 1, &RoomsNode::on_map, this);
    if (adapter_.settle_after() > 0.0)
      settle_timer_ = nh.createSteadyTimer(ros::WallDuration(std::min(0.25, adapter_.settle_after() / 4.0)),
                                           &RoomsNode::on_settle_timer, this);
  }

  // At shutdown: the ids of the rooms last published, for the next start.
  void save_ledger() {
    try {
      adapter_.save_ledger();
    } catch (const std::exception& e) {
      ROS_ERROR("topocut_node: ~id_ledger not written: %s", e.what());
    }
  }

  // The start-up lines: what it listens to and answers under which names, and with which options.
  void log_start() const {
    ROS_INFO("topocut_node: maps from %s; rooms on %s, %s, %s, %s, %s, %s", map_.getTopic().c_str(),
             labels_.getTopic().c_str(), grid_.getTopic().c_str(), rooms_.getTopic().c_str(), markers_.getTopic().c_str(),
             graph_.getTopic().c_str(), timing_.getTopic().c_str());
    ROS_INFO("topocut_node: services %s, %s; action %s", segment_.getService().c_str(), room_at_.getService().c_str(),
             ros::names::resolve("~map_segmentation").c_str());
    ROS_INFO("topocut_node: parameters %s", adapter_.settings_summary().c_str());
  }

 private:
  void on_map(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    const Clock::time_point received = Clock::now();
    try {
      const topocut_ros::RoomsOutput rooms = adapter_.update(map_input(*msg));
      if (rooms.kind != "unchanged" || !have_map_) {
        last_change_ = Clock::now();
        settled_ = false;
      }
      have_map_ = true;
      latest_ = msg->header;
      latest_info_ = msg->info;
      publish(rooms, received);
    } catch (const std::exception& e) {  // a malformed map or bad values: logged, skipped, never fatal
      ROS_ERROR("topocut_node: skipped a map: %s", e.what());
    }
  }

  // The map has not changed for ~settle_after seconds: its rooms become segment()'s, ids carried.
  void on_settle_timer(const ros::SteadyTimerEvent&) {
    if (!have_map_ || settled_ || ms_between(last_change_, Clock::now()) < 1000.0 * adapter_.settle_after()) return;
    const Clock::time_point start = Clock::now();
    settled_ = true;
    try {
      publish(adapter_.settle(), start);
      adapter_.save_ledger();
    } catch (const std::exception& e) {  // an id beyond 16 bits, an unwritable ledger
      ROS_ERROR("topocut_node: settling: %s", e.what());
    }
  }

  // The rooms of the latest map on every topic, its timing and one log line.
  void publish(const topocut_ros::RoomsOutput& rooms, Clock::time_point received) {
    labels_.publish(labels_image(latest_, latest_info_.width, latest_info_.height, rooms.labels));
    grid_.publish(labels_grid(latest_, latest_info_, rooms.labels));
    rooms_.publish(rooms_message(latest_, rooms));
    markers_.publish(room_markers(latest_, rooms, latest_info_.resolution));
    std_msgs::String graph;
    graph.data = rooms.json;
    graph_.publish(graph);
    const double callback_ms = ms_between(received, Clock::now());
    publish_timing(rooms, callback_ms);
    ROS_INFO("topocut_node: map %u x %u at %g m: %zu rooms, %zu passages (%s, %.1f ms)", latest_info_.width,
             latest_info_.height, static_cast<double>(latest_info_.resolution), rooms.rooms.size(), rooms.passages.size(),
             rooms.kind.c_str(), callback_ms);
  }

  bool on_segment(topocut_msgs::SegmentMap::Request& request, topocut_msgs::SegmentMap::Response& response) {
    try {
      const topocut_ros::RoomsOutput rooms = adapter_.segment(map_input(request.map), request.options);
      response.rooms = rooms_message(request.map.header, rooms);
      response.labels = labels_image(request.map.header, request.map.info.width, request.map.info.height, rooms.labels);
      response.json = rooms.json;
      log_segmented("segment_map", request.map, rooms);
    } catch (const std::exception& e) {  // the caller reads why in response.error
      response.error = e.what();
      ROS_WARN("topocut_node: segment_map: %s", e.what());
    }
    return true;
  }

  // One goal, start to end, with a feedback message as each stage begins; a bad map or option aborts
  // the goal with the reason in result.error.
  void on_goal() {
    const topocut_msgs::MapSegmentationGoalConstPtr goal = action_.acceptNewGoal();
    if (!goal) return;  // preempted before it was taken up
    topocut_msgs::MapSegmentationResult result;
    try {
      feedback("accepted", 0.0f);
      feedback("segmenting", 0.05f);
      const topocut_ros::RoomsOutput rooms = adapter_.segment(map_input(goal->map), goal->options);
      feedback("writing the result", 0.95f);
      result.rooms = rooms_message(goal->map.header, rooms);
      result.labels = labels_image(goal->map.header, goal->map.info.width, goal->map.info.height, rooms.labels);
      result.grid = labels_grid(goal->map.header, goal->map.info, rooms.labels);
      result.json = rooms.json;
      log_segmented("map_segmentation", goal->map, rooms);
      action_.setSucceeded(result);
    } catch (const std::exception& e) {
      result.error = e.what();
      ROS_WARN("topocut_node: map_segmentation: %s", e.what());
      action_.setAborted(result, result.error);
    }
  }

  void feedback(const char* stage, float progress) {
    topocut_msgs::MapSegmentationFeedback message;
    message.stage = stage;
    message.progress = progress;
    action_.publishFeedback(message);
  }

  static void log_segmented(const char* how, const nav_msgs::OccupancyGrid& map, const topocut_ros::RoomsOutput& rooms) {
    ROS_INFO("topocut_node: %s: map %u x %u at %g m: %zu rooms, %zu passages (%.1f ms)", how, map.info.width,
             map.info.height, static_cast<double>(map.info.resolution), rooms.rooms.size(), rooms.passages.size(),
             rooms.update_ms);
  }

  bool on_room_at(topocut_msgs::RoomAt::Request& request, topocut_msgs::RoomAt::Response& response) {
    try {
      topocut_ros::RoomShape room;
      response.id = static_cast<std::uint32_t>(adapter_.room_at(request.point.x, request.point.y, &room));
      if (response.id != 0) response.room = room_message(room);
      response.header = latest_;
      return true;
    } catch (const std::exception& e) {  // a non-finite point: the caller reads why in response.error
      response.error = e.what();
      ROS_WARN("topocut_node: room_at: %s", e.what());
      return true;
    }
  }

  void publish_timing(const topocut_ros::RoomsOutput& rooms, double callback_ms) {
    char text[200];
    std::snprintf(text, sizeof text, "{\"update_ms\": %.4f, \"callback_ms\": %.4f, \"kind\": \"%s\", \"rooms\": %zu}",
                  rooms.update_ms, callback_ms, rooms.kind.c_str(), rooms.rooms.size());
    std_msgs::String timing;
    timing.data = text;
    timing_.publish(timing);
  }

  topocut_ros::RoomsAdapter adapter_;
  std_msgs::Header latest_;  // of the map the published rooms are of
  nav_msgs::MapMetaData latest_info_;
  bool have_map_ = false, settled_ = false;
  Clock::time_point last_change_;
  ros::Publisher labels_, grid_, rooms_, markers_, graph_, timing_;
  ros::ServiceServer segment_, room_at_;
  actionlib::SimpleActionServer<topocut_msgs::MapSegmentationAction> action_;
  ros::Subscriber map_;
  ros::SteadyTimer settle_timer_;
};

}  // namespace

int main(int argc, char** argv) {
  // rosconsole writes INFO to stdout: one line at a time, so that a log file, roslaunch's pipe or the
  // journal sees each line when it happens, not when a buffer fills or the node ends.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  // Before ros::init, which would register with the master (and replace a running node of this name).
  std::vector<std::string> args;
  ros::removeROSArgs(argc, argv, args);
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--help" || args[i] == "-h") {
      std::cout << kUsage << topocut_ros::parameters_help();
      return 0;
    }
    std::cerr << "topocut_node: unknown argument '" << args[i] << "' (topocut_node --help lists what it takes)\n";
    return 2;
  }
  ros::init(argc, argv, "topocut");
  ros::NodeHandle nh, private_nh("~");
  try {
    std::vector<std::string> unknown;
    RoomsNode node(nh, private_nh, private_parameters(private_nh), unknown);
    for (const std::string& line : unknown) ROS_WARN("topocut_node: %s", line.c_str());
    node.log_start();
    ros::spin();
    node.save_ledger();
  } catch (const std::exception& e) {  // bad parameters: one clear line, non-zero exit
    ROS_FATAL("topocut_node: %s", e.what());
    return 1;
  }
  return 0;
}
