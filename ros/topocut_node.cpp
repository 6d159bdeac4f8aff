// topocut_node: rooms of a growing ROS map, live. Subscribes `map` (nav_msgs/OccupancyGrid, latched
// or streamed; size and origin may change between messages) and, for every map, runs the library's
// incremental segmenter (a wholesale change such as a loop closure becomes a batch update with ids
// kept where rooms overlap), then publishes
//   rooms/labels   sensor_msgs/Image 16UC1: the room id of every cell, in the map's row order and
//                  header (0 = no room)
//   rooms/markers  visualization_msgs/MarkerArray: room outlines, ids and passages, for RViz
//   rooms/graph    std_msgs/String: the rooms JSON (rooms_json.h)
//   rooms/timing   std_msgs/String: {"update_ms", "callback_ms", "kind", "rooms"} of that map
// A thin adapter: the conversion, segmentation and JSON are the library's, behind rooms_adapter.h
// (this file is C++17 because ROS 1's message headers are); it only moves values between messages
// and the adapter. Parameters (private, `~name`) carry the CLI's option names with '_' for '-', and
// the library's defaults.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include "rooms_adapter.h"

namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
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
  image.data.resize(2 * labels.size());
  for (std::size_t k = 0; k < labels.size(); ++k) {
    image.data[2 * k] = static_cast<std::uint8_t>(labels[k] & 0xff);  // little-endian, as is_bigendian says
    image.data[2 * k + 1] = static_cast<std::uint8_t>(labels[k] >> 8);
  }
  return image;
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
  for (std::size_t i = 0; i + 3 < rooms.passages.size(); i += 4) {
    passages.points.push_back(point_of(rooms.passages[i], rooms.passages[i + 1]));
    passages.points.push_back(point_of(rooms.passages[i + 2], rooms.passages[i + 3]));
  }
  out.markers.push_back(passages);
  return out;
}

class RoomsNode {
 public:
  explicit RoomsNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh)
      : adapter_([&](const std::string& name, double* value) { return private_nh.getParam(name, *value); },
                 [&](const std::string& name, bool* value) { return private_nh.getParam(name, *value); }) {
    labels_ = nh.advertise<sensor_msgs::Image>("rooms/labels", 1, true);
    markers_ = nh.advertise<visualization_msgs::MarkerArray>("rooms/markers", 1, true);
    graph_ = nh.advertise<std_msgs::String>("rooms/graph", 1, true);
    timing_ = nh.advertise<std_msgs::String>("rooms/timing", 10);
    map_ = nh.subscribe("map", 1, &RoomsNode::on_map, this);
  }

 private:
  void on_map(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    const Clock::time_point received = Clock::now();
    const nav_msgs::MapMetaData& info = msg->info;
    topocut_ros::MapInput map;
    map.data = msg->data.data();
    map.size = msg->data.size();
    map.width = info.width;
    map.height = info.height;
    map.resolution = info.resolution;
    map.x = info.origin.position.x;
    map.y = info.origin.position.y;
    map.yaw = yaw_of(info.origin.orientation);
    try {
      const topocut_ros::RoomsOutput rooms = adapter_.update(map);
      labels_.publish(labels_image(msg->header, info.width, info.height, rooms.labels));
      markers_.publish(room_markers(msg->header, rooms, info.resolution));
      std_msgs::String graph;
      graph.data = rooms.json;
      graph_.publish(graph);
      publish_timing(rooms, ms_between(received, Clock::now()));
    } catch (const std::exception& e) {  // a malformed map or bad values: logged, skipped, never fatal
      ROS_ERROR("topocut_node: skipped a map: %s", e.what());
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
  ros::Publisher labels_, markers_, graph_, timing_;
  ros::Subscriber map_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "topocut");
  ros::NodeHandle nh, private_nh("~");
  try {
    RoomsNode node(nh, private_nh);
    ros::spin();
  } catch (const std::exception& e) {  // bad parameters: one clear line, non-zero exit
    ROS_FATAL("topocut_node: %s", e.what());
    return 1;
  }
  return 0;
}
