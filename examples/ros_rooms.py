#!/usr/bin/env python3
"""Feeds a map file to a running topocut_node and prints the rooms it answers: the map goes out on
/map as map_server would publish it (latched nav_msgs/OccupancyGrid, ROS row order), the rooms come
back on /rooms/graph (the rooms JSON of `topocut segment --out-json`, map frame, metres).

    export ROS_MASTER_URI=http://127.0.0.1:11311
    rosmaster --core -p 11311 &  build/ros/topocut_node &
    PYTHONPATH=build/python /usr/bin/python3 examples/ros_rooms.py maps/floorplan.yaml

Needs python3-rospy and python3-nav-msgs (bash .ci/setup.sh installs them) and the topocut Python
package to read the map file (build/python, or pip-installed).
"""
import argparse
import json
import threading

import rospy
from nav_msgs.msg import OccupancyGrid
from std_msgs.msg import String

import topocut


def occupancy_grid(m):
    msg = OccupancyGrid()
    msg.header.frame_id = "map"
    msg.header.stamp = rospy.Time.now()
    msg.info.resolution = m.resolution
    msg.info.height, msg.info.width = m.grid.shape
    msg.info.origin.position.x, msg.info.origin.position.y = m.origin[0], m.origin[1]
    msg.info.origin.orientation.w = 1.0
    msg.data = m.grid.ravel().tolist()  # row 0 at the origin, as load_map gives it
    return msg


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("map", help="ROS map_server YAML or image")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds to wait for the rooms")
    args = parser.parse_args()
    rospy.init_node("topocut_example", anonymous=True)
    answered, graph = threading.Event(), {}

    def on_graph(msg):
        graph.update(json.loads(msg.data))
        answered.set()

    rospy.Subscriber("rooms/graph", String, on_graph)
    publisher = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)
    publisher.publish(occupancy_grid(topocut.load_map(args.map)))
    if not answered.wait(args.timeout):
        raise SystemExit(f"no rooms on {rospy.resolve_name('rooms/graph')} within {args.timeout} s: is topocut_node running?")
    for room in graph["rooms"]:
        print(f"room {room['id']}: {room['area']:.1f} m², inside ({room['inside'][0]:.2f}, {room['inside'][1]:.2f})")
    for passage in graph["passages"]:
        print(f"passage {passage['rooms'][0]} - {passage['rooms'][1]}: {passage['kind']}, {passage['width']:.2f} m")


if __name__ == "__main__":
    main()
