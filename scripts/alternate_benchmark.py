#!/usr/bin/python3
"""Runs two builds of one benchmark in turns and prints the medians of their tables and the ratios.

    scripts/alternate_benchmark.py [--rounds N] BASE_BINARY NEW_BINARY [-- ARGUMENTS...]

On a shared machine the load changes from minute to minute: the base and the new binary run one
after the other, N rounds (default 3), with the same arguments. Every Markdown table they print is
read; each numeric cell becomes the median of its rounds. Printed: the base's tables, the new
binary's tables, and for every numeric cell the ratio new / base. Both binaries must print tables
of the same shape (build one benchmark source against both libraries).
"""
import statistics
import subprocess
import sys


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


def number(cell):
    try:
        return float(cell)
    except ValueError:
        return None


def medians(runs):
    """Cell-wise medians of the numeric cells of several runs' tables (the first run's text elsewhere)."""
    result = []
    for t, table in enumerate(runs[0]):
        rows = []
        for r, row in enumerate(table):
            cells = []
            for c, cell in enumerate(row):
                values = [number(run[t][r][c]) for run in runs if t < len(run) and r < len(run[t]) and c < len(run[t][r])]
                ok = all(v is not None for v in values) and len(values) == len(runs)
                cells.append(f"{statistics.median(values):g}" if ok else cell)
            rows.append(cells)
        result.append(rows)
    return result


def ratios(base, new):
    result = []
    for tb, tn in zip(base, new):
        rows = []
        for rb, rn in zip(tb, tn):
            cells = []
            for cb, cn in zip(rb, rn):
                b, n = number(cb), number(cn)
                cells.append(f"{n / b:.2f}" if b and n is not None else cn)
            rows.append(cells)
        result.append(rows)
    return result


def print_tables(title, tables):
    print(f"## {title}\n")
    for table in tables:
        print("| " + " | ".join(table[0]) + " |")
        print("|" + "---|" * len(table[0]))
        for row in table[1:]:
            print("| " + " | ".join(row) + " |")
        print()


def main(argv):
    rounds = 3
    if argv[:1] == ["--rounds"]:
        rounds, argv = int(argv[1]), argv[2:]
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    base, new, arguments = argv[0], argv[1], argv[3:] if argv[2:3] == ["--"] else argv[2:]
    runs = {base: [], new: []}
    for k in range(rounds):
        for binary in (base, new):
            out = subprocess.run([binary] + arguments, check=True, capture_output=True, text=True).stdout
            if k == 0 and binary == base:
                print("\n".join(l for l in out.splitlines() if l.startswith("machine")) + "\n")
            runs[binary].append(tables_of(out))
    base_tables, new_tables = medians(runs[base]), medians(runs[new])
    print_tables(f"base ({base}), medians of {rounds} rounds", base_tables)
    print_tables(f"new ({new}), medians of {rounds} rounds", new_tables)
    print_tables("new / base", ratios(base_tables, new_tables))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
