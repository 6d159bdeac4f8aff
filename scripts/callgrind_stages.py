#!/usr/bin/python3
"""Instructions per stage of `topocut segment`, counted by callgrind: repeatable on a busy machine.

    scripts/callgrind_stages.py [--jobs N] [--base-options OPTIONS] TOPOCUT [BASE_TOPOCUT] -- MAP...

Runs `TOPOCUT segment MAP --out-json FILE` under valgrind --tool=callgrind for every map and reads
the inclusive instruction count of the functions that make each stage (by name, so that builds of
different commits, whose signatures differ, compare). Prints one table per binary (millions of
instructions per map and stage, and the sum over the maps) and, with BASE_TOPOCUT, the ratios
TOPOCUT / BASE_TOPOCUT. --base-options adds segment options to BASE_TOPOCUT's runs only: the same
binary twice with --base-options=--no-learned-merge gives the learned merging over the hand rules. Stages: load (load_map), front end (segmentation_input, free_space_polygons,
simplified_where_valid), cuts and decomposition (decompose_pieces less the simplification), of which
DuDe (decompose), merging (merge_rooms), open rooms (join_open_rooms), labelling (rooms_from_pieces),
leave-out (the rows after it: leave_out_fans, leave_out_outside_parts),
segment (the whole of segment()), outputs (in_frame: the JSON's points inside rooms), process (all).
Runs with one OpenCV thread (OPENCV_FOR_THREADS_NUM=1), so that the work of OpenCV's pool is counted
in the stage that asked for it. Needs valgrind; callgrind runs about 50 times slower than the program.
"""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys
import tempfile

STAGES = [
    ("load", ["load_map"]),
    ("front end", ["segmentation_input", "free_space_polygons", "simplified_where_valid"]),
    ("cuts + decomposition", ["decompose_pieces", "-simplified_where_valid"]),
    ("of which DuDe", ["decompose"]),
    ("merging", ["merge_rooms"]),
    ("open rooms", ["join_open_rooms"]),
    ("labelling", ["rooms_from_pieces"]),
    ("leave-out", ["leave_out_fans", "leave_out_outside_parts"]),
    ("segment", ["segment"]),
    ("outputs", ["in_frame"]),
    ("process", ["PROGRAM TOTALS"]),
]

LINE = re.compile(r"^\s*([\d,]+)\s+\([^)]*\)\s+(.*)$")


def inclusive_counts(profile):
    """The inclusive instruction count of each topocut:: function (largest over its entries) and the total."""
    out = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", profile], check=True,
                         capture_output=True, text=True).stdout
    counts = {}
    for line in out.splitlines():
        m = LINE.match(line)
        if not m:
            continue
        count, what = int(m.group(1).replace(",", "")), m.group(2)
        if what.startswith("PROGRAM TOTALS"):
            counts["PROGRAM TOTALS"] = count
            continue
        f = re.search(r"topocut::(\w+)\(", what)
        if f and "(anonymous namespace)" not in what.split(f.group(0))[0]:
            counts[f.group(1)] = max(counts.get(f.group(1), 0), count)
    return counts


def profile(binary, path, folder, extra=()):
    out = os.path.join(folder, "callgrind.out")
    # One OpenCV thread: work its pool would share out lands in the function that asked for it.
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", binary, "segment", path,
                    "--out-json", os.path.join(folder, "rooms.json"), *extra], check=True, capture_output=True,
                   env=dict(os.environ, OPENCV_FOR_THREADS_NUM="1"))
    counts = inclusive_counts(out)
    row = []
    for _, parts in STAGES:
        total = 0
        for p in parts:
            total += -counts.get(p[1:], 0) if p.startswith("-") else counts.get(p, 0)
        row.append(total)
    return row


def table(names, rows, fmt):
    lines = ["| map | " + " | ".join(s for s, _ in STAGES) + " |", "|" + "---|" * (len(STAGES) + 1)]
    for name, row in zip(names, rows):
        lines.append(f"| {name} | " + " | ".join(fmt(v) for v in row) + " |")
    return "\n".join(lines)


def main(argv):
    head, maps = (argv[:argv.index("--")], argv[argv.index("--") + 1:]) if "--" in argv else (argv, [])
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--jobs", type=int, default=1, help="callgrind runs at once (default 1)")
    parser.add_argument("--base-options", default="", help="segment options for BASE_TOPOCUT's runs only")
    parser.add_argument("binaries", nargs="+", help="TOPOCUT [BASE_TOPOCUT]")
    options = parser.parse_args(head)
    if not maps or len(options.binaries) > 2:
        parser.error("give one or two topocut binaries, then -- and the maps")
    binaries = [os.path.realpath(b) for b in options.binaries]
    labels = [binaries[0], binaries[1] + (" " + options.base_options if options.base_options else "")] if len(binaries) == 2 else binaries
    names = [os.path.basename(m) for m in maps]
    with tempfile.TemporaryDirectory(prefix="callgrind_stages_") as work:
        jobs = {}
        with concurrent.futures.ThreadPoolExecutor(max_workers=options.jobs) as pool:
            for b, binary in enumerate(binaries):
                for m, path in enumerate(maps):
                    folder = os.path.join(work, f"{b}_{m}")
                    os.makedirs(folder)
                    extra = options.base_options.split() if b == 1 else []
                    jobs[(b, m)] = pool.submit(profile, binary, os.path.realpath(path), folder, extra)
        results = [[jobs[(b, m)].result() for m in range(len(maps))] for b in range(len(binaries))]
    for b, binary in enumerate(binaries):
        rows = results[b] + [[sum(col) for col in zip(*results[b])]]
        print(f"## {labels[b]}: millions of instructions (callgrind, inclusive)\n")
        print(table(names + ["sum"], rows, lambda v: f"{v / 1e6:.1f}") + "\n")
    if len(binaries) == 2:
        new = results[0] + [[sum(col) for col in zip(*results[0])]]
        base = results[1] + [[sum(col) for col in zip(*results[1])]]
        ratios = [[n / b if b else float("nan") for n, b in zip(rn, rb)] for rn, rb in zip(new, base)]
        print(f"## {labels[0]} / {labels[1]}\n")
        print(table(names + ["sum"], ratios, lambda v: "-" if v != v else f"{v:.2f}") + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
