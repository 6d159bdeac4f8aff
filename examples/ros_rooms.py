#!/usr/bin/env python3
"""Feeds a map file to a running topocut_node and prints the rooms it answers. By default the map goes
out on /map as map_server would publish it (latched nav_msgs/OccupancyGrid, ROS row order) and the
rooms come back on /rooms/rooms (topocut_msgs/Rooms: the rooms and passages of `topocut segment
--out-json`, map frame, metres); with --service the map is sent to the node's service
/topocut/segment_map instead (the whole map at once, with --option overrides), and with --action to
its action /topocut/map_segmentation (the same, with progress printed on stderr as it comes), each
answering with the same rooms. --at X,Y then asks /topocut/room_at which room holds that point in the
rooms the node published (the service and the action are what-ifs: they publish nothing, so --at
answers from the latest map on /map).
--node names the node (default topocut, the launch file's name).

    export ROS_MASTER_URI=http://127.0.0.1:11311 PYTHONPATH=build/ros/python:build/python
    roscore &  build/ros/topocut_node &
    /usr/bin/python3 examples/ros_rooms.py maps/floorplan.yaml [--service|--action [--option concavity=3]] [--at 4.4,6.9]

Needs python3-rospy, python3-nav-msgs and python3-actionlib (bash .ci/setup.sh installs them), the
generated messages (build/ros/python, built with the node, or installed) and the topocut Python package
to read the map file (build/python, or installed).
"""
import argparse
import threading

import rospy
from geometry_msgs.msg import Point
from nav_msgs.msg import OccupancyGrid
from topocut_msgs.msg import MapSegmentationAction, MapSegmentationGoal, Rooms
from topocut_msgs.srv import RoomAt, SegmentMap

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


def published_rooms(grid, timeout):
    """Publishes grid on /map and waits for its rooms on /rooms/rooms."""
    answered, rooms = threading.Event(), []

    def on_rooms(msg):
        if msg.header.stamp == grid.header.stamp:
            rooms.append(msg)
            answered.set()

    rospy.Subscriber("rooms/rooms", Rooms, on_rooms)
    publisher = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)
    publisher.publish(grid)
    if not answered.wait(timeout):
        raise SystemExit(f"no rooms on {rospy.resolve_name('rooms/rooms')} within {timeout} s: is topocut_node running?")
    return rooms[0]


def served_rooms(grid, node, options, timeout):
    """Sends grid to the node's service segment_map."""
    name = f"/{node}/segment_map"
    try:
        rospy.wait_for_service(name, timeout)
    except rospy.ROSException:
        raise SystemExit(f"no service {name} within {timeout} s: is topocut_node running?")
    answer = rospy.ServiceProxy(name, SegmentMap)(grid, options)
    if answer.error:
        raise SystemExit("segment_map: " + answer.error)
    return answer.rooms


def action_rooms(grid, node, options, timeout):
    """Sends grid as a goal to the node's action map_segmentation; prints its feedback on stderr.
    actionlib's ActionClient, not SimpleActionClient: rospy's SimpleActionClient records its goal only
    after sending it, so the first feedback of a server that answers within milliseconds (as this one
    does on small maps) can arrive before it and be dropped; ActionClient registers the callbacks first."""
    import sys

    import actionlib
    from actionlib_msgs.msg import GoalStatus

    name = f"/{node}/map_segmentation"
    client = actionlib.ActionClient(name, MapSegmentationAction)
    if not client.wait_for_server(rospy.Duration(timeout)):
        raise SystemExit(f"no action server {name} within {timeout} s: is topocut_node running?")
    done = threading.Event()

    def on_transition(handle):
        if handle.get_comm_state() == actionlib.CommState.DONE:
            done.set()

    def on_feedback(handle, feedback):
        print(f"{name}: {feedback.stage} ({feedback.progress:.0%})", file=sys.stderr)

    handle = client.send_goal(MapSegmentationGoal(map=grid, options=options), on_transition, on_feedback)
    if not done.wait(timeout):
        handle.cancel()
        raise SystemExit(f"{name}: no result within {timeout} s")
    result = handle.get_result()
    if handle.get_goal_status() != GoalStatus.SUCCEEDED or result is None or result.error:
        raise SystemExit(f"{name}: " + (result.error if result and result.error else handle.get_goal_status_text()))
    return result.rooms


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("map", help="ROS map_server YAML or image")
    how = parser.add_mutually_exclusive_group()
    how.add_argument("--service", action="store_true", help="send the map to the node's ~segment_map instead of /map")
    how.add_argument("--action", action="store_true", help="send the map as a goal to the node's ~map_segmentation")
    parser.add_argument("--option", action="append", default=[], metavar="NAME=VALUE",
                        help="with --service or --action: an option over the node's parameters (repeatable), e.g. concavity=3")
    parser.add_argument("--node", default="topocut", help="the node's name (default topocut)")
    parser.add_argument("--at", metavar="X,Y", help="then print the room at this point (map frame, metres) in the node's published rooms")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds to wait for the rooms")
    args = parser.parse_args()
    rospy.init_node("topocut_example", anonymous=True)
    grid = occupancy_grid(topocut.load_map(args.map))
    if args.service:
        rooms = served_rooms(grid, args.node, args.option, args.timeout)
    elif args.action:
        rooms = action_rooms(grid, args.node, args.option, args.timeout)
    else:
        rooms = published_rooms(grid, args.timeout)
    for room in rooms.rooms:
        print(f"room {room.id}: {room.area:.1f} m², inside ({room.inside.x:.3f}, {room.inside.y:.3f})")
    for passage in rooms.passages:
        kind = "door" if passage.kind == passage.DOOR else "opening"
        print(f"passage {passage.room_a} - {passage.room_b}: {kind}, {passage.width:.2f} m")
    if args.at:
        x, y = (float(v) for v in args.at.split(","))
        answer = rospy.ServiceProxy(f"/{args.node}/room_at", RoomAt)(Point(x, y, 0.0))
        print(f"at {args.at}: " + (f"room {answer.id}" if answer.id else "none"))


if __name__ == "__main__":
    main()
