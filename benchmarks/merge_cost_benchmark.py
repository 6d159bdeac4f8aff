#!/usr/bin/python3
"""What the learned merging costs against the hand rules (issue 25: map-suite times at most 1.3x).

For each real map and each Bormann image: `topocut segment MAP` and `topocut segment MAP
--no-learned-merge`, alternating, --repeats times each; the process CPU time (user + system, which a
busy machine disturbs less than wall-clock time), the least of the repeats. Prints the per-map times
of the real maps and the ratios learned / hand rules (median, max) per set, with the machine.

  /usr/bin/python3 benchmarks/merge_cost_benchmark.py --build build [--repeats 3]
Exits 77 with a message when ../shared/datasets is absent.
"""
import argparse
import glob
import os
import resource
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
from node_latency_benchmark import cpu_model  # noqa: E402  (the machine line the other benchmarks print)


def cpu_seconds(command):
    """Process CPU time of command (user + system), seconds."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def maps(datasets):
    """{set: [map file]}: the real maps (a PGM with a YAML is read through its YAML) and Bormann's images."""
    real = sorted(glob.glob(os.path.join(datasets, "real_maps", "*.png")) + glob.glob(os.path.join(datasets, "real_maps", "*.yaml"))
                  + [p for p in glob.glob(os.path.join(datasets, "real_maps", "*.pgm")) if not os.path.exists(p[:-4] + ".yaml")])
    bormann = sorted(p for p in glob.glob(os.path.join(datasets, "bormann", "*.png")) if "_gt_" not in p)
    return {"real maps": real, "Bormann": bormann}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(HERE, "..", "build"), help="the build folder holding topocut")
    parser.add_argument("--shared", default=os.path.join(HERE, "..", "..", "shared"), help="the folder holding datasets/")
    parser.add_argument("--repeats", type=int, default=3, help="runs per map and method, the least taken (default 3)")
    args = parser.parse_args()
    datasets = os.path.join(args.shared, "datasets")
    if not os.path.isdir(datasets):
        print(f"merge_cost_benchmark: skipped: no {datasets}", file=sys.stderr)
        return 77
    topocut = os.path.join(args.build, "topocut")
    print("# Learned merging against the hand rules: process CPU time\n")
    print(f"machine: {cpu_model()}, {os.cpu_count()} hardware threads, "
          f"load average {os.getloadavg()[0]:.1f}; least of {args.repeats} runs each, alternating\n")
    ratios = {}
    rows = []
    for name, files in maps(datasets).items():
        ratios[name] = []
        for path in files:
            learned, hand = [], []
            for _ in range(args.repeats):
                learned.append(cpu_seconds([topocut, "segment", path]))
                hand.append(cpu_seconds([topocut, "segment", path, "--no-learned-merge"]))
            ratios[name].append(min(learned) / min(hand))
            if name == "real maps":
                rows.append(f"| {os.path.basename(path)} | {1000 * min(learned):.0f} | {1000 * min(hand):.0f} | {min(learned) / min(hand):.2f} |")
    print("| real map | learned ms | hand rules ms | ratio |\n|---|---|---|---|")
    print("\n".join(rows) + "\n")
    print("| set | maps | learned / hand rules, median | max |\n|---|---|---|---|")
    for name, values in ratios.items():
        print(f"| {name} | {len(values)} | {statistics.median(values):.2f} | {max(values):.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
