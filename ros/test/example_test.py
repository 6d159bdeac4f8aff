#!/usr/bin/python3
"""The ROS 1 session of docs/ros.md on the loopback only: a private rosmaster on a free port of 127.0.0.1,
topocut_node, and examples/ros_rooms.py feeding it the bundled floor plan, on /map, through the
service /topocut/segment_map and through the action /topocut/map_segmentation, then asking
/topocut/room_at; the rooms it prints must be the library's (the rooms JSON of `topocut segment
--out-json`) and the room at the point `topocut segment --at`'s. Every
wait is bounded; the master and the node are stopped whatever happens. Exit 77: skipped.

    example_test.py --node NODE --rosmaster ROSMASTER --cli TOPOCUT --source SOURCE_DIR --python-path DIR --msgs DIR
"""
import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from node_test import private_master, stop  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    for name in ("node", "rosmaster", "cli", "source", "python-path", "msgs"):
        parser.add_argument("--" + name, required=True)
    args = parser.parse_args()
    if not os.path.isdir(os.path.join(args.python_path, "topocut")):
        print("skipped: the Python package is not built in %s" % args.python_path)
        return 77
    signal.alarm(60)
    work = tempfile.mkdtemp(prefix="topocut_ros_example_")
    floorplan = os.path.join(args.source, "maps", "floorplan.yaml")
    master = node = None
    try:
        master, env = private_master(args.rosmaster, work)
        env["PYTHONPATH"] = args.msgs + os.pathsep + args.python_path
        node = subprocess.Popen([args.node], env=env, start_new_session=True, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        point = "4.4,6.9"
        cli = subprocess.run([args.cli, "segment", floorplan, "--out-json", os.path.join(work, "rooms.json"), "--at", point],
                             check=True, capture_output=True, text=True, timeout=30)
        with open(os.path.join(work, "rooms.json")) as f:
            rooms = json.load(f)
        expected = [f"room {r['id']}: {r['area']:.1f} m², inside ({r['inside'][0]:.3f}, {r['inside'][1]:.3f})" for r in rooms["rooms"]]
        expected += [f"passage {p['rooms'][0]} - {p['rooms'][1]}: {p['kind']}, {p['width']:.2f} m" for p in rooms["passages"]]
        expected += [line for line in cli.stdout.splitlines() if line.startswith("at ")]
        assert expected[-1].startswith("at " + point + ": room "), cli.stdout
        for mode in ([], ["--service"], ["--action"]):
            out = subprocess.run([sys.executable, os.path.join(args.source, "examples", "ros_rooms.py"), floorplan, "--at", point]
                                 + mode, env=env, capture_output=True, text=True, timeout=45)
            printed = out.stdout.strip().splitlines()
            if out.returncode != 0 or printed != expected:
                print("examples/ros_rooms.py %s printed:\n%s%s\nthe command's rooms are:\n%s" %
                      (" ".join(mode), out.stdout, out.stderr, "\n".join(expected)))
                return 1
        print("\n".join(printed))
        print("ros_rooms.py printed the command's %d rooms, %d passages and room at %s, on /map, from ~segment_map and from ~map_segmentation" %
              (len(rooms["rooms"]), len(rooms["passages"]), point))
        return 0
    finally:
        stop(node)
        stop(master)
        shutil.rmtree(work, ignore_errors=True)
        signal.alarm(0)


if __name__ == "__main__":
    sys.exit(main())
