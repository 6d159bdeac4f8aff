#!/usr/bin/python3
"""topocut_node soak, run by hand (not in CI): maps at 10 Hz for an hour by default, a Bormann map
revealed step by step and then again from the start (the node's incremental state grows, is reset
by a batch update and grows again), on the loopback with a private rosmaster as in node_test.py.

Every minute it prints the node's resident memory (VmRSS), its peak (VmHWM), the maps published
and the answers received. At the end it checks that the node is alive, answered at least 90 % of
the maps (the subscriber queue holds one map: a map that arrives while the node works replaces the
one waiting), and that its memory is flat: the median RSS of the last fifth of the run at most
10 % (and 20 MB) above that of the second fifth (the first fifth warms the allocator up).

    python3 ros/test/node_soak.py --node build/ros/topocut_node --reference build/ros/topocut_node_reference \\
        --rosmaster "$(command -v rosmaster)" --map ../shared/datasets/bormann/Freiburg52_scan.png [--minutes 60]
Exit status 0: passed, 1: a check failed, 77: skipped (no map).
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from node_test import (growing_sequence, occupancy_grid_message, private_master, read_grid, stop,  # noqa: E402
                       wait_for)


def memory_kb(pid, field):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith(field + ":"):
                return int(line.split()[1])
    return 0


def soak(args, env, work):
    import rospy
    from nav_msgs.msg import OccupancyGrid
    from std_msgs.msg import String

    subprocess.run([args.reference, "export", args.map, os.path.join(work, "full.grid")], check=True, timeout=60)
    full = read_grid(os.path.join(work, "full.grid"))
    grids = growing_sequence(full, args.steps)
    log = open(os.path.join(work, "node.log"), "wb")
    node = subprocess.Popen([args.node, "__name:=topocut"], env=env, start_new_session=True, stdout=log,
                            stderr=subprocess.STDOUT)
    try:
        rospy.init_node("topocut_node_soak", anonymous=True, disable_signals=True)
        answers = []
        rospy.Subscriber("/rooms/timing", String, lambda m: answers.append(m.data))
        publisher = rospy.Publisher("/map", OccupancyGrid, queue_size=1)
        wait_for(lambda: publisher.get_num_connections() > 0, "the node to subscribe to /map")
        time.sleep(1.0)
        messages = [occupancy_grid_message(g, k) for k, g in enumerate(grids)]
        samples = []  # (seconds, rss kB)
        start = time.monotonic()
        end = start + 60.0 * args.minutes
        published = 0
        next_report = start + 60.0
        print("| minute | maps published | answers | node RSS MB | node peak MB |\n|---|---|---|---|---|", flush=True)
        while time.monotonic() < end:
            tick = time.monotonic()
            publisher.publish(messages[published % len(messages)])
            published += 1
            if node.poll() is not None:
                print("the node exited with status %s" % node.returncode)
                return 1
            if published % 10 == 0:
                samples.append((tick - start, memory_kb(node.pid, "VmRSS")))
            if tick >= next_report:
                print("| %d | %d | %d | %.1f | %.1f |" % (round((tick - start) / 60), published, len(answers),
                                                          memory_kb(node.pid, "VmRSS") / 1024.0,
                                                          memory_kb(node.pid, "VmHWM") / 1024.0), flush=True)
                next_report += 60.0
            time.sleep(max(0.0, 0.1 - (time.monotonic() - tick)))
        time.sleep(2.0)
        alive = node.poll() is None
        fifth = len(samples) // 5
        early = statistics.median(rss for _, rss in samples[fifth:2 * fifth]) / 1024.0
        late = statistics.median(rss for _, rss in samples[4 * fifth:]) / 1024.0
        share = len(answers) / published
        print("node alive: %s; %d maps published, %d answered (%.1f %%); RSS median %.1f MB (second fifth) -> %.1f MB "
              "(last fifth)" % (alive, published, len(answers), 100 * share, early, late))
        flat = late <= early * 1.10 or late - early <= 20.0
        ok = alive and share >= 0.90 and flat
        print("node_soak: %s" % ("all checks passed" if ok else "FAILED"))
        return 0 if ok else 1
    finally:
        stop(node)
        log.close()


def main():
    parser = argparse.ArgumentParser()
    for name in ("node", "reference", "rosmaster", "map"):
        parser.add_argument("--" + name, required=True)
    parser.add_argument("--minutes", type=float, default=60.0)
    parser.add_argument("--steps", type=int, default=30, help="maps in one revealing sequence")
    args = parser.parse_args()
    if not os.path.exists(args.map):
        print("skipped: the map %s is not there" % args.map)
        return 77
    work = tempfile.mkdtemp(prefix="topocut_node_soak_")
    master, env = private_master(args.rosmaster, work)
    try:
        result = soak(args, env, work)
        if result == 0:
            shutil.rmtree(work, ignore_errors=True)
        else:
            print("node log and grids kept in " + work)
        return result
    finally:
        stop(master)


if __name__ == "__main__":
    sys.exit(main())
