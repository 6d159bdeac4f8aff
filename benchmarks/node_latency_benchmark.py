#!/usr/bin/python3
"""topocut_node's latency against the library's update time (issue 14: from receiving a map to
publishing its rooms, p95 at most 2x the library's update time).

For each Bormann map: a fresh node on a private rosmaster (127.0.0.1, free port), the map revealed
around its most central free cell in --steps growing OccupancyGrids (node_test.py's sequence: the
frame grows with new size and origin, as a SLAM map does), each published once the previous one's
rooms came back. The node reports per map (topic rooms/timing) the library's update time and the
callback time (map received -> labels, markers and graph published, conversions included). Prints
a Markdown table per map and pooled, with the machine.

  /usr/bin/python3 benchmarks/node_latency_benchmark.py --build build [--steps 20] [MAP ...]
MAP: Bormann names (default: six maps of different sizes). Needs the ROS 1 packages and the node
built (CMake finds roscpp); exits 77 with a message when the node or the data set is absent.
"""
import argparse
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "ros", "test"))
import node_test  # noqa: E402  (the loopback machinery and the growing sequence, defined once there)

DEFAULT_MAPS = ["Freiburg52_scan", "lab_a_scan", "lab_d_scan", "office_a", "office_e", "NLB"]


def cpu_model():
    """The processor's vendor and family, as benchmarks/benchmark_machine.h names it."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return " ".join(line.split(":", 1)[1].split()[:2])
    except OSError:
        pass
    return platform.machine()


def run_map(args, env, grids):
    """Starts a fresh node, publishes the grids one by one; returns (update_ms, callback_ms) lists."""
    import rospy
    from nav_msgs.msg import OccupancyGrid
    from std_msgs.msg import String

    node = subprocess.Popen([args.node, "__name:=topocut"], env=env, start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        timings = []
        sub = rospy.Subscriber("/rooms/timing", String, lambda m: timings.append(m.data))
        pub = rospy.Publisher("/map", OccupancyGrid, queue_size=10, latch=True)
        node_test.wait_for(lambda: pub.get_num_connections() > 0 and sub.get_num_connections() > 0,
                           "the node to connect")
        time.sleep(0.3)
        updates, callbacks = [], []
        for k, g in enumerate(grids):
            count = len(timings)
            pub.publish(node_test.occupancy_grid_message(g, k))
            node_test.wait_for(lambda: len(timings) > count, "rooms for map %d" % k, timeout=60)
            t = json.loads(timings[-1])
            updates.append(t["update_ms"])
            callbacks.append(t["callback_ms"])
        sub.unregister()
        pub.unregister()
        return updates, callbacks
    finally:
        node_test.stop(node)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the CMake build folder (default: build)")
    parser.add_argument("--data", default=os.path.join(HERE, "..", "..", "shared", "datasets", "bormann"))
    parser.add_argument("--steps", type=int, default=20, help="growing maps per Bormann map (default 20)")
    parser.add_argument("maps", nargs="*", default=DEFAULT_MAPS)
    args = parser.parse_args()
    args.node = os.path.join(args.build, "ros", "topocut_node")
    reference = os.path.join(args.build, "ros", "topocut_node_reference")
    rosmaster = shutil.which("rosmaster") or "/usr/bin/rosmaster"
    if not (os.path.exists(args.node) and os.path.exists(reference) and os.path.exists(rosmaster)):
        print("node_latency_benchmark: skipped: %s, %s or rosmaster missing (build with the ROS 1 packages)"
              % (args.node, reference))
        return 77
    if not os.path.isdir(args.data):
        print("node_latency_benchmark: skipped: no Bormann data set at %s" % args.data)
        return 77

    work = tempfile.mkdtemp(prefix="topocut_node_latency_")
    master, env = node_test.private_master(rosmaster, work)
    rows, all_updates, all_callbacks = [], [], []
    try:
        import rospy
        rospy.init_node("topocut_node_latency", anonymous=True, disable_signals=True)
        for name in args.maps:
            image = os.path.join(args.data, name + ".png")
            if not os.path.exists(image):
                print("node_latency_benchmark: error: no map %s" % image, file=sys.stderr)
                return 2
            grid_path = os.path.join(work, name + ".grid")
            subprocess.run([reference, "export", image, grid_path], check=True, timeout=120)
            full = node_test.read_grid(grid_path)
            grids = node_test.growing_sequence(full, args.steps)
            updates, callbacks = run_map(args, env, grids)
            rows.append((name, full, updates, callbacks))
            all_updates += updates
            all_callbacks += callbacks
            print("  %s: %d updates" % (name, len(updates)), file=sys.stderr, flush=True)
    finally:
        node_test.stop(master)
        shutil.rmtree(work, ignore_errors=True)

    load = os.getloadavg()[0]
    print("node_latency_benchmark: %s, %d hardware threads, load average %.1f; %d growing maps per Bormann map"
          % (cpu_model(), os.cpu_count(), load, args.steps))
    print()
    print("| map | grid | updates | library update ms (median / p95) | node callback ms (median / p95) | "
          "callback p95 / update p95 |")
    print("|---|---|---|---|---|---|")

    def row(name, grid, updates, callbacks):
        ratio = node_test.percentile95(callbacks) / node_test.percentile95(updates) if node_test.percentile95(updates) > 0 else float("inf")
        print("| %s | %s | %d | %.2f / %.2f | %.2f / %.2f | %.2f |" % (
            name, grid, len(updates), statistics.median(updates), node_test.percentile95(updates),
            statistics.median(callbacks), node_test.percentile95(callbacks), ratio))
        return ratio

    for name, full, updates, callbacks in rows:
        row(name, "%d x %d" % (full["width"], full["height"]), updates, callbacks)
    pooled = row("all", "-", all_updates, all_callbacks)
    print()
    print("target: node callback p95 <= 2 x library update p95 (pooled): %.2f, %s"
          % (pooled, "met" if pooled <= 2.0 else "NOT met"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
