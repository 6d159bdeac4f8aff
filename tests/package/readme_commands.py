#!/usr/bin/python3
"""Runs a shell block of README.md as written, as a user would paste it in the source folder, and
checks what it did. A block is the ```sh fence after a line `<!-- readme-test: NAME -->`. It runs
under `bash -euo pipefail` in a scratch folder holding `build`, `examples` and `maps` (links to the
build and the checkout), in a session of its own that is ended afterwards, with a time limit.

    readme_commands.py --source DIR --build DIR --block cpp_install --cli TOPOCUT
    readme_commands.py --source DIR --build DIR --block ros_install --cli TOPOCUT

cpp_install: the example built from pkg-config's flags and with CMake prints, on the bundled map,
  the rooms `topocut segment --out-json` finds (ids and areas), both builds the same, and nothing warns.
ros_install: the installed packages are laid out for ROS (node, launch file, RViz configuration
  naming the node's topics, messages); `roslaunch topocut topocut.launch` from the install prefix
  answers the action with `topocut segment`'s rooms and publishes them for the map sent on /map, its
  ~room_at then answers as `topocut segment --at` does, and the node logs the goal. On a master of
  its own on a free port of 127.0.0.1 (ROS_MASTER_URI points there; roslaunch starts it). Exit 77:
  skipped.
  (The feedback printed is checked for order only: ros_node_test checks all of it.)
"""
import argparse
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile

BLOCK_SECONDS = 240


def readme_block(source, name):
    with open(os.path.join(source, "README.md"), encoding="utf-8") as f:
        text = f.read()
    match = re.search(r"<!-- readme-test: %s -->\n```sh\n(.*?)```" % re.escape(name), text, re.S)
    if not match:
        sys.exit(f"README.md has no ```sh block after <!-- readme-test: {name} -->")
    return match.group(1)


def run_block(block, work, env):
    """The block's exit code, stdout and stderr; its whole session is ended afterwards."""
    process = subprocess.Popen(["bash", "-euo", "pipefail", "-c", block], cwd=work, env=env, start_new_session=True,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        out, err = process.communicate(timeout=BLOCK_SECONDS)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        out, err = process.communicate()
        sys.exit(f"the block ran longer than {BLOCK_SECONDS} s:\n{out}\n{err}")
    finally:
        try:
            os.killpg(process.pid, signal.SIGKILL)  # roslaunch, a master: nothing outlives the block
        except ProcessLookupError:
            pass
    return process.returncode, out, err


def cli_rooms(cli, source, work, at=None):
    """`topocut segment`'s rooms JSON on the bundled floor plan, and its --at lines."""
    path = os.path.join(work, "cli_rooms.json")
    command = [cli, "segment", os.path.join(source, "maps", "floorplan.yaml"), "--out-json", path]
    if at:
        command += ["--at", at]
    done = subprocess.run(command, capture_output=True, text=True, timeout=60, check=True)
    with open(path) as f:
        return json.load(f), [line for line in done.stdout.splitlines() if line.startswith("at ")]


def check_cpp_install(out, err, rooms):
    if re.search(r"warning", out + err, re.I):
        sys.exit("the README's C++ commands warn:\n" + out + err)
    printed = [line for line in out.splitlines() if line.startswith("room ")]
    expected = [r["id"] for r in rooms["rooms"]]
    half = len(printed) // 2
    if len(printed) != 2 * len(expected) or printed[:half] != printed[half:]:
        sys.exit(f"expected the {len(expected)} rooms twice (pkg-config build, CMake build), got:\n{out}")
    for line, room in zip(printed[:half], rooms["rooms"]):
        number, area = re.match(r"room (\d+): ([0-9.]+) m2", line).groups()
        if int(number) != room["id"] or abs(float(area) - room["area"]) > 1e-3 * max(1.0, room["area"]):
            sys.exit(f"'{line}' is not topocut segment's room {room['id']} ({room['area']} m2)")
    print("\n".join(printed[:half]))
    print(f"pkg-config and CMake builds of examples/segment_map.cpp print topocut segment's {len(expected)} rooms, "
          "without a warning")


def check_installed_ros(prefix):
    import yaml

    for path in ("lib/topocut/topocut_node", "share/topocut/topocut_node", "share/topocut/package.xml",
                 "share/topocut/launch/topocut.launch", "share/topocut/rviz/topocut.rviz",
                 "share/topocut_msgs/package.xml", "share/topocut_msgs/action/MapSegmentation.action",
                 "share/topocut_msgs/msg/MapSegmentationGoal.msg", "share/topocut_msgs/srv/SegmentMap.srv",
                 "include/topocut_msgs/MapSegmentationAction.h", "include/topocut_msgs/Rooms.h"):
        if not os.path.exists(os.path.join(prefix, path)):
            sys.exit(f"cmake --install did not install {path}")
    with open(os.path.join(prefix, "share/topocut/rviz/topocut.rviz")) as f:
        rviz = yaml.safe_load(f)
    topics = {d.get("Topic") or d.get("Marker Topic") for d in rviz["Visualization Manager"]["Displays"]}
    if topics != {"/map", "/rooms/grid", "/rooms/markers"}:
        sys.exit(f"the RViz configuration shows {topics}, not the map and the node's rooms/grid and rooms/markers")


def check_ros_install(out, err, rooms, at_lines):
    # The example's two runs: the action's answer, then the rooms published for the map on /map and
    # ~room_at in them (the action is a what-if: room_at answers in the published rooms only).
    listed = [f"room {r['id']}: {r['area']:.1f} m², inside ({r['inside'][0]:.3f}, {r['inside'][1]:.3f})" for r in rooms["rooms"]]
    listed += [f"passage {p['rooms'][0]} - {p['rooms'][1]}: {p['kind']}, {p['width']:.2f} m" for p in rooms["passages"]]
    expected = listed + listed + at_lines
    printed = [line for line in out.splitlines() if line.startswith(("room ", "passage ", "at "))]
    if printed != expected:
        sys.exit("the action's and the published rooms are not topocut segment's:\n%s\nexpected:\n%s\nstderr:\n%s" %
                 ("\n".join(printed), "\n".join(expected), err))
    # Feedback and result travel on two topics: a client drops the feedback that comes after the result,
    # so what it printed is the stages' beginning, in order (ros_node_test reads all of it on the topic).
    stages = re.findall(r"/topocut/map_segmentation: ([a-z ]+) \((\d+)%\)", err)
    if [s for s, _ in stages] != ["accepted", "segmenting", "writing the result"][:len(stages)] or \
            [int(p) for _, p in stages] != sorted(int(p) for _, p in stages):
        sys.exit(f"feedback out of order: {stages}\n{err}")
    if not re.search(r"^nav_msgs/OccupancyGrid map$", out, re.M) or not re.search(r"^string\[\] options$", out, re.M):
        sys.exit("rosmsg show did not show the installed goal:\n" + out + err)
    if "topocut_node: map_segmentation: map 400 x 300 at 0.05 m: %d rooms" % len(rooms["rooms"]) not in out + err:
        sys.exit("the node did not log the goal:\n" + out + err)
    print("\n".join(printed))
    print("roslaunch topocut topocut.launch from the install prefix: the action and the map on /map gave topocut segment's "
          "%d rooms and %d passages, feedback %s" % (len(rooms["rooms"]), len(rooms["passages"]), ", ".join(s for s, _ in stages)))


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def main():
    parser = argparse.ArgumentParser()
    for name in ("source", "build", "block", "cli"):
        parser.add_argument("--" + name, required=True)
    args = parser.parse_args()
    source, build = os.path.abspath(args.source), os.path.abspath(args.build)
    block = readme_block(source, args.block)
    work = tempfile.mkdtemp(prefix="topocut_readme_")
    try:
        for name, target in (("build", build), ("examples", os.path.join(source, "examples")),
                             ("maps", os.path.join(source, "maps"))):
            os.symlink(target, os.path.join(work, name))
        env = {k: v for k, v in os.environ.items() if not k.startswith(("ROS_", "PKG_CONFIG"))}
        env.pop("PYTHONPATH", None)
        env["HOME"] = work
        if args.block == "ros_install":
            if not shutil.which("roslaunch"):
                print("skipped: roslaunch is not installed (bash .ci/setup.sh test installs python3-roslaunch)")
                return 77
            env.update(ROS_MASTER_URI="http://127.0.0.1:%d" % free_port(), ROS_IP="127.0.0.1", ROS_HOSTNAME="127.0.0.1",
                       ROS_HOME=work, ROS_LOG_DIR=os.path.join(work, "log"))
        rooms, at_lines = cli_rooms(args.cli, source, work, "4.4,6.9" if args.block == "ros_install" else None)
        code, out, err = run_block(block, work, env)
        if code != 0:
            sys.exit(f"the README's block {args.block} failed (exit {code}):\n{block}\n{out}\n{err}")
        if args.block == "cpp_install":
            check_cpp_install(out, err, rooms)
        elif args.block == "ros_install":
            check_installed_ros(os.path.join(work, "prefix"))
            check_ros_install(out, err, rooms, at_lines)
        else:
            sys.exit(f"no checks for the block {args.block}")
        return 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
