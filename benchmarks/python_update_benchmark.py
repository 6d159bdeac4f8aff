#!/usr/bin/python3
"""Python's IncrementalSegmenter.update() on growing maps: the time per update, as a robot's Python
program pays it (the grid's conversion, the update and every room's place, `inside` among it).

For each Bormann map: the map revealed in a square around its centre that grows over --steps grids
and then stays (--still more grids, unchanged: what a robot that stopped exploring publishes), each
given to update() as the nav_msgs-style int8 array `load_map()` gives. Each build runs in its own
process, the builds alternating --rounds times on every map; prints the process-time median per
update of all and of the unchanged grids, per map and build, with the machine.

  /usr/bin/python3 benchmarks/python_update_benchmark.py --build build [--base OLD/build] [MAP ...]
MAP: Bormann names (default: office_a office_e lab_d_scan). Exits 77 with a message when the data set
is absent.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from node_latency_benchmark import cpu_model  # noqa: E402  (the machine line the other benchmarks print)
SHARED = os.path.join(HERE, "..", "..", "shared", "datasets", "bormann")
SKIPPED = 77

# The measuring child: run as `python3 -c CHILD BUILD MAP STEPS STILL`, prints a JSON list of ms.
CHILD = r"""
import json, sys, time
import numpy as np
build, image, steps, still = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
sys.path.insert(0, build + "/python")
import topocut
grid = np.asarray(topocut.load_map(image, resolution=0.05).grid)  # int8, rows bottom-up, as nav_msgs holds them
h, w = grid.shape
seg = topocut.IncrementalSegmenter()
times = []
for step in range(1, steps + still + 1):
    r = (min(step, steps) * max(h, w) + steps - 1) // steps
    g = np.full(grid.shape, -1, np.int8)
    g[max(0, h // 2 - r):h // 2 + r, max(0, w // 2 - r):w // 2 + r] = grid[max(0, h // 2 - r):h // 2 + r, max(0, w // 2 - r):w // 2 + r]
    start = time.process_time()
    seg.update(g, 0.05, (0.0, 0.0, 0.0))
    times.append(1000 * (time.process_time() - start))
print(json.dumps(times))
"""


def measure(build, image, steps, still):
    out = subprocess.run([sys.executable, "-c", CHILD, build, image, str(steps), str(still)],
                         check=True, capture_output=True, text=True, env=dict(os.environ, OPENCV_FOR_THREADS_NUM="1"))
    return json.loads(out.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("maps", nargs="*", default=["office_a", "office_e", "lab_d_scan"], metavar="MAP")
    parser.add_argument("--build", default=os.path.join(HERE, "..", "build"), help="the build folder holding python/topocut")
    parser.add_argument("--base", help="another build to alternate with (its python/topocut)")
    parser.add_argument("--steps", type=int, default=40, help="growing grids per map (default %(default)s)")
    parser.add_argument("--still", type=int, default=20, help="unchanged grids after them (default %(default)s)")
    parser.add_argument("--rounds", type=int, default=2, help="runs of each build per map, alternating (default %(default)s)")
    args = parser.parse_args()
    if args.steps < 1 or args.still < 0 or args.rounds < 1:
        parser.error("--steps and --rounds must be at least 1, --still at least 0")
    builds = ([("base", args.base)] if args.base else []) + [("build", args.build)]
    for name, folder in builds:
        if not os.path.isdir(os.path.join(folder, "python", "topocut")):
            parser.error(f"no python/topocut in {folder} ({name}): build the target topocut_python")
    images = [os.path.join(SHARED, m + ".png") for m in args.maps]
    missing = [i for i in images if not os.path.exists(i)]
    if missing:
        print(f"python_update_benchmark: skipped: {missing[0]} is absent (../shared/datasets/bormann)", file=sys.stderr)
        return SKIPPED
    print("# Python IncrementalSegmenter.update(), process time per update (ms)")
    print(f"machine: {cpu_model()}, {os.cpu_count()} hardware threads, load average {os.getloadavg()[0]:.1f}; "
          f"{args.steps} growing + {args.still} unchanged grids a map, {args.rounds} rounds alternating")
    print()
    print("| map | build | median, every update | median, unchanged grids |")
    print("|---|---|---|---|")
    for m, image in zip(args.maps, images):
        times = {name: [] for name, _ in builds}
        for _ in range(args.rounds):
            for name, folder in builds:
                times[name].append(measure(folder, image, args.steps, args.still))
        for name, _ in builds:
            every = " / ".join(f"{statistics.median(t):.2f}" for t in times[name])
            still = " / ".join(f"{statistics.median(t[args.steps:]):.2f}" for t in times[name]) if args.still else "-"
            print(f"| {m} | {name} | {every} | {still} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
