#!/usr/bin/python3
"""The README's ROS 1 start on the loopback only: a private rosmaster on a free port of 127.0.0.1,
topocut_node, and examples/ros_rooms.py feeding it the bundled floor plan; the rooms it prints must
be the library's (the rooms JSON of `topocut segment --out-json`). Every wait is bounded; the master
and the node are stopped whatever happens. Exit 77: skipped.

    example_test.py --node NODE --rosmaster ROSMASTER --cli TOPOCUT --source SOURCE_DIR --python-path DIR
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
from node_test import free_port, stop, wait_for  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    for name in ("node", "rosmaster", "cli", "source", "python-path"):
        parser.add_argument("--" + name, required=True)
    args = parser.parse_args()
    if not os.path.isdir(os.path.join(args.python_path, "topocut")):
        print("skipped: the Python package is not built in %s" % args.python_path)
        return 77
    signal.alarm(60)
    work = tempfile.mkdtemp(prefix="topocut_ros_example_")
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % port, ROS_IP="127.0.0.1", ROS_HOSTNAME="127.0.0.1",
               ROS_HOME=work, ROS_LOG_DIR=work, PYTHONPATH=args.python_path)
    os.environ.update(env)
    floorplan = os.path.join(args.source, "maps", "floorplan.yaml")
    master = node = None
    try:
        master = subprocess.Popen([args.rosmaster, "--core", "-p", str(port)], env=env, start_new_session=True,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        import rosgraph
        wait_for(lambda: rosgraph.is_master_online(), "rosmaster on port %d" % port)
        node = subprocess.Popen([args.node], env=env, start_new_session=True, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        out = subprocess.run([sys.executable, os.path.join(args.source, "examples", "ros_rooms.py"), floorplan],
                             env=env, capture_output=True, text=True, timeout=45)
        if out.returncode != 0:
            print(out.stdout, out.stderr)
            return 1
        subprocess.run([args.cli, "segment", floorplan, "--out-json", os.path.join(work, "rooms.json")], check=True,
                       capture_output=True, timeout=30)
        with open(os.path.join(work, "rooms.json")) as f:
            rooms = json.load(f)
        expected = [f"room {r['id']}: {r['area']:.1f} m², inside ({r['inside'][0]:.2f}, {r['inside'][1]:.2f})" for r in rooms["rooms"]]
        expected += [f"passage {p['rooms'][0]} - {p['rooms'][1]}: {p['kind']}, {p['width']:.2f} m" for p in rooms["passages"]]
        printed = out.stdout.strip().splitlines()
        if printed != expected:
            print("examples/ros_rooms.py printed:\n%s\nthe command's rooms are:\n%s" % ("\n".join(printed), "\n".join(expected)))
            return 1
        print("\n".join(printed))
        print("ros_rooms.py printed the command's %d rooms and %d passages" % (len(rooms["rooms"]), len(rooms["passages"])))
        return 0
    finally:
        stop(node)
        stop(master)
        shutil.rmtree(work, ignore_errors=True)
        signal.alarm(0)


if __name__ == "__main__":
    sys.exit(main())
