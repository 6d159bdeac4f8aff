#!/usr/bin/python3
"""topocut_node's ~segment_map (/topocut/segment_map) against `topocut segment` on every shared map (issue 26: a static
map sent to the node gets the command's rooms, identical labels).

A node on a private rosmaster (127.0.0.1, free port); each map is read by the library
(topocut_node_reference export: the cells the command sees, as a nav_msgs/OccupancyGrid), sent to
the service, and segmented by the command (--out-labels, --out-json). Prints a Markdown table per
data set: maps whose labels are identical cell for cell and whose JSON is identical byte for byte,
rooms, and the call's round trip from rospy (conversions and transport included) beside the
command's own segmenting time, medians; with the machine.

  /usr/bin/python3 benchmarks/node_segment_map_benchmark.py --build build [DATASET ...]
DATASET: bormann, real_maps, real_maps_gt, sketches/lex, sketches/ezvin (default: all). Needs the ROS
1 packages and the node built; exits 77 with a message when the node or every data set is absent.
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "ros", "test"))
import node_test  # noqa: E402  (the loopback machinery and the comparison with the command, defined once there)
from node_latency_benchmark import cpu_model  # noqa: E402

DATASETS = ["bormann", "real_maps", "real_maps_gt", "sketches/lex", "sketches/ezvin"]


def maps_of(folder):
    """The maps of a data set: images and map_server YAMLs, not ground truth; a PGM with its YAML once."""
    names = sorted(n for n in os.listdir(folder) if n.endswith((".png", ".pgm", ".yaml")) and "_gt_" not in n)
    return [os.path.join(folder, n) for n in names if not (n.endswith(".pgm") and n[:-4] + ".yaml" in names)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the CMake build folder (default: build)")
    parser.add_argument("--data", default=os.path.join(HERE, "..", "..", "shared", "datasets"))
    parser.add_argument("datasets", nargs="*", default=DATASETS)
    args = parser.parse_args()
    node = os.path.join(args.build, "ros", "topocut_node")
    reference = os.path.join(args.build, "ros", "topocut_node_reference")
    cli = os.path.join(args.build, "topocut")
    rosmaster = shutil.which("rosmaster") or "/usr/bin/rosmaster"
    if not all(os.path.exists(p) for p in (node, reference, cli, rosmaster)):
        print("node_segment_map_benchmark: skipped: %s, %s, %s or rosmaster missing" % (node, reference, cli))
        return 77
    datasets = [d for d in args.datasets if os.path.isdir(os.path.join(args.data, d))]
    if not datasets:
        print("node_segment_map_benchmark: skipped: none of %s under %s" % (", ".join(args.datasets), args.data))
        return 77
    sys.path.insert(0, os.path.join(args.build, "ros", "python"))

    work = tempfile.mkdtemp(prefix="topocut_segment_map_")
    master, env = node_test.private_master(rosmaster, work)
    running = None
    rows = []
    try:
        import rospy
        running = subprocess.Popen([node, "__name:=topocut"], env=env, start_new_session=True,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        rospy.init_node("topocut_segment_map_benchmark", anonymous=True, disable_signals=True)
        for dataset in datasets:
            results = []
            for k, path in enumerate(maps_of(os.path.join(args.data, dataset))):
                results.append(node_test.segment_map_against_cli(cli, reference, path, work, k))
                r = results[-1]
                if r["differ"] or not r["json_equal"]:
                    print("  %s: %d cells differ, JSON %s" % (path, r["differ"], "equal" if r["json_equal"] else "differs"),
                          file=sys.stderr)
            rows.append((dataset, results))
            print("  %s: %d maps" % (dataset, len(results)), file=sys.stderr, flush=True)
    finally:
        node_test.stop(running)
        node_test.stop(master)
        shutil.rmtree(work, ignore_errors=True)

    print("node_segment_map_benchmark: %s, %d hardware threads, load average %.1f"
          % (cpu_model(), os.cpu_count(), os.getloadavg()[0]))
    print()
    print("| data set | maps | labels identical | JSON identical | rooms | segment_map round trip ms (median) | "
          "topocut segment ms (median) |")
    print("|---|---|---|---|---|---|---|")
    for dataset, results in rows:
        print("| %s | %d | %d | %d | %d | %.1f | %.1f |" % (
            dataset, len(results), sum(r["differ"] == 0 for r in results), sum(r["json_equal"] for r in results),
            sum(len(r["answer"].rooms.rooms) for r in results), statistics.median(r["call_ms"] for r in results),
            statistics.median(r["cli_ms"] for r in results)))
    every = [r for _, results in rows for r in results]
    identical = sum(r["differ"] == 0 and r["json_equal"] for r in every)
    print()
    print("target: identical labels on every shared map: %d of %d, %s" % (identical, len(every),
                                                                        "met" if identical == len(every) else "NOT met"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
