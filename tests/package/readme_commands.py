#!/usr/bin/python3
"""Runs a block of README.md as written, as a user would paste it in the source folder, and checks
what it did. A block is the ```sh or ```python fence after a line `<!-- readme-test: NAME -->`. A sh
block runs under `bash -euo pipefail`, a python block under /usr/bin/python3 with PYTHONPATH=build/python
(as the README says to run it), in a scratch folder holding `build`, `examples` and `maps` (links to
the build and the checkout), in a session of its own that is ended afterwards, with a time limit.
Each check compares what the block made with what `topocut segment` makes when this script runs it.

    readme_commands.py --source DIR --build DIR --block NAME --cli TOPOCUT

segment: rooms.json is `topocut segment --out-json`'s; labels.png a 16-bit PNG of the map's size
  holding exactly the rooms' ids, each on its labelled area; rooms.png a PNG of the map scaled by a
  whole factor; the `at` line names the room whose label the point's cell holds.
config: rooms.geojson holds the rooms `topocut segment` finds with examples/robot.yaml's options given
  on the command line (and not the default options' rooms).
evaluate: scores.csv has one `ok` row per bundled map with ground truth, its rooms `topocut segment`'s
  count and its scores fractions; report/index.html shows only PNGs that exist.
python_example: the rooms printed (ids, areas) are `topocut segment`'s, and rooms.png is a PNG.
python: the rooms printed and the room at the point are those of `topocut segment --config
  examples/robot.yaml`, and rooms.json is byte for byte its --out-json.
cpp_install: the example built from pkg-config's flags and with CMake prints, on the bundled map,
  the rooms `topocut segment --out-json` finds (ids and areas), both builds the same, and nothing warns.
ros_install: the installed packages are laid out for ROS (node, launch file, RViz configuration
  naming the node's topics, messages); `roslaunch topocut topocut.launch` from the install prefix
  answers the action with `topocut segment`'s rooms and publishes them for the map sent on /map, its
  ~room_at then answers as `topocut segment --at` does, and the node logs the goal. On a master of
  its own on a free port of 127.0.0.1 (ROS_MASTER_URI points there; roslaunch starts it).
  (The feedback printed is checked for order only: ros_node_test checks all of it.)
Exit 77: skipped (a module the check needs, or roslaunch, is not installed).
"""
import argparse
import csv
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
    """The language (sh or python) and the text of the README's block NAME."""
    with open(os.path.join(source, "README.md"), encoding="utf-8") as f:
        text = f.read()
    match = re.search(r"<!-- readme-test: %s -->\n```(sh|python)\n(.*?)```" % re.escape(name), text, re.S)
    if not match:
        sys.exit(f"README.md has no ```sh or ```python block after <!-- readme-test: {name} -->")
    return match.group(1), match.group(2)


def run_block(language, block, work, env):
    """The block's exit code, stdout and stderr; its whole session is ended afterwards."""
    if language == "python":
        command = ["/usr/bin/python3", "-c", block]
        env = dict(env, PYTHONPATH=os.path.join(work, "build", "python"))
    else:
        command = ["bash", "-euo", "pipefail", "-c", block]
    process = subprocess.Popen(command, cwd=work, env=env, start_new_session=True,
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


class Run:
    """One block's run: where it ran, what it printed, and `topocut segment` to compare it with."""

    def __init__(self, cli, source, work):
        self.cli, self.source, self.work = cli, source, work
        self.out = self.err = ""
        self.reference = tempfile.mkdtemp(prefix="reference_", dir=work)  # no block writes here
        self.count = 0

    def path(self, name):
        return os.path.join(self.work, name)

    def segment(self, map_name="floorplan", options=(), at=None, output="--out-json"):
        """`topocut segment`'s output (--out-json by default) on a bundled map, parsed and as text,
        and its --at lines."""
        self.count += 1
        path = os.path.join(self.reference, "%d_%s" % (self.count, map_name))
        command = [self.cli, "segment", os.path.join(self.source, "maps", map_name + ".yaml"), output, path, *options]
        if at:
            command += ["--at", at]
        done = subprocess.run(command, capture_output=True, text=True, timeout=60, check=True)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        return json.loads(text), text, [line for line in done.stdout.splitlines() if line.startswith("at ")]


def cli_rooms(cli, source, work, at=None):
    """`topocut segment`'s rooms JSON on the bundled floor plan, and its --at lines."""
    rooms, _, at_lines = Run(cli, source, work).segment(at=at)
    return rooms, at_lines


def pil_image():
    """PIL's Image, or a skip (python3-pil: bash .ci/setup.sh test installs it)."""
    try:
        from PIL import Image
    except ImportError:
        print("skipped: PIL is not installed (bash .ci/setup.sh test installs python3-pil)")
        sys.exit(77)
    return Image


def png_size(path):
    """The width and height of a PNG file; exits when the file is missing or is no PNG."""
    if not os.path.isfile(path):
        sys.exit(f"the block wrote no {os.path.basename(path)}")
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        sys.exit(f"{os.path.basename(path)} is no PNG")
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def read_json(path):
    if not os.path.isfile(path):
        sys.exit(f"the block wrote no {os.path.basename(path)}")
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def robot_options(source):
    """examples/robot.yaml's options as command-line flags."""
    import yaml

    with open(os.path.join(source, "examples", "robot.yaml"), encoding="utf-8") as f:
        options = yaml.safe_load(f)
    flags = []
    for key, value in options.items():
        flag = "--" + key.replace("_", "-")
        if value is True:
            flags.append(flag)
        elif value is not False:
            flags += [flag, str(value)]
    return flags


def check_segment(run):
    """rooms.json, labels.png, rooms.png and the at line of `topocut segment` on the floor plan."""
    import numpy as np

    expected, _, at_lines = run.segment(at="2,1.5")
    rooms = read_json(run.path("rooms.json"))
    if rooms != expected:
        sys.exit("rooms.json is not the rooms topocut segment --out-json writes")
    width, height = expected["size"]
    labels = np.array(pil_image().open(run.path("labels.png")))
    if labels.shape != (height, width) or png_size(run.path("labels.png")) != (width, height):
        sys.exit(f"labels.png is {labels.shape[::-1]}, not the map's {width} x {height}")
    ids = sorted(int(v) for v in np.unique(labels) if v)
    if ids != [r["id"] for r in rooms["rooms"]]:
        sys.exit(f"labels.png holds the ids {ids}, not the rooms' {[r['id'] for r in rooms['rooms']]}")
    cell = rooms["resolution"] ** 2
    for room in rooms["rooms"]:
        area = np.count_nonzero(labels == room["id"]) * cell
        if abs(area - room["labelled_area"]) > 1e-3 * room["labelled_area"]:
            sys.exit(f"room {room['id']} covers {area} m² of labels.png, the JSON says {room['labelled_area']}")
    over_w, over_h = png_size(run.path("rooms.png"))
    scale = over_w // width
    if scale < 1 or (over_w, over_h) != (scale * width, scale * height):
        sys.exit(f"rooms.png is {over_w} x {over_h}, not the map ({width} x {height}) scaled by a whole factor")
    printed = [line for line in run.out.splitlines() if line.startswith("at ")]
    column = int((2.0 - rooms["origin"][0]) / rooms["resolution"])
    row = height - 1 - int((1.5 - rooms["origin"][1]) / rooms["resolution"])
    if printed != at_lines or printed != ["at 2,1.5: room %d" % labels[row, column]]:
        sys.exit(f"printed {printed}; topocut segment says {at_lines}, labels.png holds {labels[row, column]}")
    print(f"rooms.json, labels.png ({width} x {height}, {len(ids)} rooms), rooms.png (x{scale}) and '{printed[0]}' "
          "are topocut segment's")


def check_config(run):
    """rooms.geojson: the rooms of the options in examples/robot.yaml, given on the command line."""
    flags = robot_options(run.source)
    expected, _, _ = run.segment("furnished", flags, output="--out-geojson")
    default, _, _ = run.segment("furnished", output="--out-geojson")
    written = read_json(run.path("rooms.geojson"))
    if written != expected:
        sys.exit(f"rooms.geojson is not what topocut segment writes with {' '.join(flags)}")
    if written == default:
        sys.exit("rooms.geojson is the default options' GeoJSON: examples/robot.yaml changed nothing")
    rooms = [f for f in written["features"] if f["geometry"]["type"] == "Polygon"]
    print(f"rooms.geojson holds the {len(rooms)} rooms of topocut segment {' '.join(flags)}")


def check_evaluate(run):
    """scores.csv and report/: every bundled map with ground truth scored, with segment's rooms."""
    maps = sorted(f[:-len("_gt_segmentation.png")] for f in os.listdir(os.path.join(run.source, "maps"))
                  if f.endswith("_gt_segmentation.png"))
    path = run.path("scores.csv")
    if not os.path.isfile(path):
        sys.exit("the block wrote no scores.csv")
    with open(path, encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    if sorted(r["map"] for r in rows) != maps:
        sys.exit(f"scores.csv scores {[r['map'] for r in rows]}, not the bundled maps {maps}")
    for row in rows:
        rooms = len(run.segment(row["map"])[0]["rooms"])
        if row["status"] != "ok" or int(row["rooms"]) != rooms:
            sys.exit(f"{row['map']}: status {row['status']}, {row['rooms']} rooms; topocut segment finds {rooms}")
        scores = [float(row[k]) for k in ("recall", "precision", "f1", "pq")]
        if not all(0 < v <= 1 for v in scores):
            sys.exit(f"{row['map']}: scores {scores} are not fractions above 0")
        if f"{row['map']} " not in run.out:
            sys.exit(f"the table printed has no row for {row['map']}:\n{run.out}")
    page = os.path.join(run.path("report"), "index.html")
    if not os.path.isfile(page):
        sys.exit("the block wrote no report/index.html")
    with open(page, encoding="utf-8") as f:
        pictures = re.findall(r'<img[^>]*src="([^"]+)"', f.read())
    for name in maps:
        if not any(p.startswith(name + "_") for p in pictures):
            sys.exit(f"report/index.html shows no picture of {name}")
    for picture in pictures:
        png_size(os.path.join(run.path("report"), picture))
    print(f"scores.csv scores the {len(maps)} bundled maps with topocut segment's rooms; report/index.html shows "
          f"{len(pictures)} PNGs")


def check_python_example(run):
    """examples/segment_map.py printed segment's rooms and drew rooms.png."""
    expected, _, _ = run.segment()
    printed = re.findall(r"^room (\d+): ([0-9.]+) m2", run.out, re.M)
    if [int(i) for i, _ in printed] != [r["id"] for r in expected["rooms"]] or \
            any(abs(float(a) - r["area"]) > 0.051 for (_, a), r in zip(printed, expected["rooms"])):
        sys.exit(f"the example printed rooms that are not topocut segment's:\n{run.out}")
    width, height = png_size(run.path("rooms.png"))
    print(f"examples/segment_map.py printed topocut segment's {len(printed)} rooms and drew rooms.png ({width} x {height})")


def check_python(run):
    """The Python block's rooms, room at the point and rooms.json are segment --config robot.yaml's."""
    config = ["--config", os.path.join(run.source, "examples", "robot.yaml")]
    expected, text, at_lines = run.segment(options=config, at="2,1.5")
    lines = run.out.splitlines()
    rooms = [line.split() for line in lines if not line.startswith("at ")]
    if [int(r[0]) for r in rooms] != [r["id"] for r in expected["rooms"]] or \
            any(abs(float(r[1]) - e["area"]) > 0.051 for r, e in zip(rooms, expected["rooms"])):
        sys.exit(f"the block printed rooms that are not topocut segment --config examples/robot.yaml's:\n{run.out}")
    at = [line.replace(": ", ": room ", 1) for line in lines if line.startswith("at ")]
    if at != at_lines:
        sys.exit(f"the block printed {at}, topocut segment {at_lines}")
    path = run.path("rooms.json")
    if not os.path.isfile(path) or open(path, encoding="utf-8").read() != text:
        sys.exit("rooms.json is not byte for byte what topocut segment --config examples/robot.yaml --out-json writes")
    print(f"the Python block printed the {len(rooms)} rooms and '{at_lines[0]}' of topocut segment --config "
          "examples/robot.yaml, and wrote its rooms JSON byte for byte")


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


# The README's blocks and what each check asks of a run (the ROS and C++ ones take the rooms too).
CHECKS = {
    "segment": check_segment,
    "config": check_config,
    "evaluate": check_evaluate,
    "python_example": check_python_example,
    "python": check_python,
    "cpp_install": lambda run: check_cpp_install(run.out, run.err, cli_rooms(run.cli, run.source, run.work)[0]),
    "ros_install": lambda run: (check_installed_ros(run.path("prefix")),
                                check_ros_install(run.out, run.err, *cli_rooms(run.cli, run.source, run.work, "4.4,6.9"))),
}


def main():
    parser = argparse.ArgumentParser()
    for name in ("source", "build", "block", "cli"):
        parser.add_argument("--" + name, required=True)
    args = parser.parse_args()
    if args.block not in CHECKS:
        sys.exit(f"no checks for the block {args.block}")
    source, build = os.path.abspath(args.source), os.path.abspath(args.build)
    language, block = readme_block(source, args.block)
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
        run = Run(args.cli, source, work)
        code, run.out, run.err = run_block(language, block, work, env)
        if code != 0:
            sys.exit(f"the README's block {args.block} failed (exit {code}):\n{block}\n{run.out}\n{run.err}")
        CHECKS[args.block](run)
        return 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
