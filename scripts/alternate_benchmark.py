#!/usr/bin/python3
"""Runs two builds of one benchmark in turns and prints the medians of their tables and the ratios.

    scripts/alternate_benchmark.py [--rounds N] BASE_BINARY NEW_BINARY [-- ARGUMENTS...]
    scripts/alternate_benchmark.py [--rounds N] --commits BASE [NEW] --target NAME [--same-benchmark]
                                   [--dir DIR] [-- ARGUMENTS...]

On a shared machine the load changes from minute to minute: the base and the new binary run one
after the other, N rounds (default 3), with the same arguments. Every Markdown table they print is
read; each numeric cell (or each number of a cell like "110.8 / 93.1 / 411.1") becomes the median of
its rounds. Printed: the machine line of every run
(with its load average), the base's tables, the new binary's tables, and for every numeric cell
the ratio new / base, with the median of each column's ratios under every table of several rows.
Both binaries must print tables of the same shape.

--commits builds the benchmark NAME of two commits first: each commit's tree (git archive, so
nothing is registered in the repository) in DIR/SHA (default build/commits of this checkout, next
to a link to the checkout's ../shared), built in DIR/SHA/build as a Release build with the
compiler launcher ccache (set CCACHE_DIR and CCACHE_BASEDIR to share objects with other builds).
NEW defaults to this checkout as it is, working tree included, built in its build/. With
--same-benchmark the base tree gets the new tree's benchmarks/ folder, so that both print the
same tables (the base library under the new benchmark's code; it must compile against it).
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def tables_of(text):
    """The Markdown tables of text: lists of rows, each a list of cell strings (separators left out)."""
    tables, current = [], []
    for line in text.splitlines():
        if line.startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if not all(set(c) <= set("-: ") for c in cells):
                current.append(cells)
        elif current:
            tables.append(current)
            current = []
    if current:
        tables.append(current)
    return tables


def numbers(cell):
    """The numbers of a cell: one ("12.5") or several separated by " / " ("110.8 / 93.1 / 411.1"); None if
    any part is no number."""
    try:
        return [float(part) for part in cell.split(" / ")]
    except ValueError:
        return None


def medians(runs):
    """Cell-wise medians of the numeric cells of several runs' tables, part by part in cells of several
    numbers (the first run's text elsewhere)."""
    result = []
    for t, table in enumerate(runs[0]):
        rows = []
        for r, row in enumerate(table):
            cells = []
            for c, cell in enumerate(row):
                values = [numbers(run[t][r][c]) for run in runs if t < len(run) and r < len(run[t]) and c < len(run[t][r])]
                ok = len(values) == len(runs) and all(v is not None and len(v) == len(values[0]) for v in values)
                cells.append(" / ".join(f"{statistics.median(parts):g}" for parts in zip(*values)) if ok else cell)
            rows.append(cells)
        result.append(rows)
    return result


def ratios(base, new):
    """new / base cell by cell, part by part in cells of several numbers."""
    result = []
    for tb, tn in zip(base, new):
        rows = []
        for rb, rn in zip(tb, tn):
            cells = []
            for cb, cn in zip(rb, rn):
                b, n = numbers(cb), numbers(cn)
                ok = b is not None and n is not None and len(b) == len(n) and all(b)
                cells.append(" / ".join(f"{y / x:.2f}" for x, y in zip(b, n)) if ok else cn)
            rows.append(cells)
        result.append(rows)
    return result


def with_median_rows(tables):
    """Each table of ratios with a last row "median of rows": the median of each column's single-number
    cells (tables of more than two rows)."""
    out = []
    for table in tables:
        if len(table) <= 3:
            out.append(table)
            continue
        row = ["median of rows"]
        for c in range(1, len(table[0])):
            values = [numbers(r[c]) for r in table[1:] if c < len(r)]
            values = [v[0] for v in values if v is not None and len(v) == 1]
            row.append(f"{statistics.median(values):.2f}" if values else "")
        out.append(table + [row])
    return out


def print_tables(title, tables):
    print(f"## {title}\n")
    for table in tables:
        print("| " + " | ".join(table[0]) + " |")
        print("|" + "---|" * len(table[0]))
        for row in table[1:]:
            print("| " + " | ".join(row) + " |")
        print()


def git(*arguments, capture=True):
    return subprocess.run(["git", "-C", HERE] + list(arguments), check=True, capture_output=capture,
                          text=True).stdout.strip()


def snapshot(commit, folder, benchmarks_from):
    """The source tree of commit in folder/SHA (made once; benchmarks/ replaced by benchmarks_from's)."""
    sha = git("rev-parse", "--verify", commit + "^{commit}")
    tree = os.path.join(folder, sha[:12] + ("-newbench" if benchmarks_from else ""))
    if not os.path.isdir(tree):
        os.makedirs(tree + ".tmp", exist_ok=True)
        archive = subprocess.Popen(["git", "-C", HERE, "archive", sha], stdout=subprocess.PIPE)
        subprocess.run(["tar", "-x", "-C", tree + ".tmp"], stdin=archive.stdout, check=True)
        if archive.wait() != 0:
            sys.exit(f"alternate_benchmark: git archive {sha} failed")
        os.rename(tree + ".tmp", tree)
    if benchmarks_from:
        shutil.rmtree(os.path.join(tree, "benchmarks"))
        shutil.copytree(os.path.join(benchmarks_from, "benchmarks"), os.path.join(tree, "benchmarks"),
                        ignore=shutil.ignore_patterns("__pycache__"))
    # The benchmarks read the shared data from ../shared beside the source tree.
    link = os.path.join(folder, "shared")
    if not os.path.exists(link) and os.path.isdir(os.path.join(HERE, "..", "shared")):
        os.symlink(os.path.realpath(os.path.join(HERE, "..", "shared")), link)
    return tree


def build(tree, target):
    """Configures (once) and builds target in tree/build; the binary's path."""
    build_dir = os.path.join(tree, "build")
    if not os.path.isfile(os.path.join(build_dir, "CMakeCache.txt")):
        subprocess.run(["cmake", "-S", tree, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                        "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"], check=True, stdout=subprocess.DEVNULL)
    print(f"alternate_benchmark: building {target} in {build_dir}", file=sys.stderr)
    result = subprocess.run(["cmake", "--build", build_dir, "-j2", "--target", target], capture_output=True, text=True)
    if result.returncode != 0:
        sys.stderr.write(result.stdout[-4000:] + result.stderr[-4000:])
        sys.exit(f"alternate_benchmark: {target} does not build in {tree}")
    return os.path.join(build_dir, target)


def parse(argv):
    head, arguments = (argv[:argv.index("--")], argv[argv.index("--") + 1:]) if "--" in argv else (argv, [])
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rounds", type=int, default=3, help="runs of each binary, alternating (default 3)")
    parser.add_argument("--commits", action="store_true", help="the two positionals are commits to build")
    parser.add_argument("--target", help="with --commits: the benchmark to build and run")
    parser.add_argument("--same-benchmark", action="store_true", help="with --commits: the new tree's benchmarks/ in both")
    parser.add_argument("--dir", default=os.path.join(HERE, "build", "commits"), help="with --commits: where the trees go")
    parser.add_argument("builds", nargs="+", help="BASE_BINARY NEW_BINARY, or with --commits BASE [NEW]")
    options = parser.parse_args(head)
    if options.rounds < 1:
        parser.error("--rounds must be at least 1")
    if options.commits:
        if not options.target or len(options.builds) > 2:
            parser.error("--commits takes BASE [NEW] and --target NAME")
    elif len(options.builds) != 2 or options.target or options.same_benchmark:
        parser.error("give BASE_BINARY NEW_BINARY (or --commits BASE [NEW] --target NAME)")
    return options, arguments


def binaries(options):
    if not options.commits:
        return options.builds[0], options.builds[1]
    os.makedirs(options.dir, exist_ok=True)
    new_tree = snapshot(options.builds[1], options.dir, None) if len(options.builds) == 2 else HERE
    base_tree = snapshot(options.builds[0], options.dir, new_tree if options.same_benchmark else None)
    return build(base_tree, options.target), build(new_tree, options.target)


def main(argv):
    options, arguments = parse(argv)
    base, new = binaries(options)
    rounds = options.rounds
    runs = ([], [])
    for k in range(rounds):
        for side, binary in enumerate((base, new)):
            out = subprocess.run([binary] + arguments, check=True, capture_output=True, text=True).stdout
            for line in out.splitlines():
                if line.startswith("machine"):
                    print(f"round {k + 1}, {('base', 'new')[side]}: {line}")
            runs[side].append(tables_of(out))
    print()
    base_tables, new_tables = medians(runs[0]), medians(runs[1])
    print_tables(f"base ({base}), medians of {rounds} rounds", base_tables)
    print_tables(f"new ({new}), medians of {rounds} rounds", new_tables)
    print_tables("new / base", with_median_rows(ratios(base_tables, new_tables)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
