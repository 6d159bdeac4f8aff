"""Reads the module dependency graph (cmake/modules.txt) and DESIGN.md's module table, for
scripts/check_layering.py and scripts/check_module_graph.py."""
import os
import re

GRAPH_FILE = os.path.join("cmake", "modules.txt")
ALL = "all"  # an adapter's uses: every module


class GraphError(Exception):
    """The graph file or the table cannot be read as a graph."""


def read_graph(root):
    """(modules, adapters): modules maps each library module to the modules it may use directly, in
    the file's order; adapters lists the modules marked "all"."""
    path = os.path.join(root, GRAPH_FILE)
    try:
        with open(path, encoding="utf-8") as source:
            lines = source.read().splitlines()
    except OSError as error:
        raise GraphError(f"cannot read {path}: {error.strerror}") from error
    modules, adapters = {}, []
    for number, line in enumerate(lines, 1):
        words = line.split("#", 1)[0].split()
        if not words:
            continue
        name, uses = words[0], words[1:]
        if name in modules or name in adapters:
            raise GraphError(f"{path}:{number}: {name} is listed twice")
        if uses == [ALL]:
            adapters.append(name)
            continue
        for used in uses:
            if used not in modules:
                raise GraphError(f"{path}:{number}: {name} uses {used}, which is not listed above it")
        modules[name] = uses
    return modules, adapters


def design_table(path, known):
    """DESIGN.md's module table as {module: [modules its "depends on" cell names]}, for the rows whose
    first cell names modules (a row may name several: `python`, `ros`); a cell saying "all" gives
    ["all"]. Words in the cell that are no module (CGAL, "laser logs") are left out; known is the
    set of module names."""
    with open(path, encoding="utf-8") as source:
        text = source.read()
    header = re.search(r"^\|\s*module\s*\|.*\|\s*depends on\s*\|\s*$", text, re.M)
    if not header:
        raise GraphError(f"{path}: no table with the columns module ... depends on")
    table = {}
    for line in text[header.end():].lstrip("\n").splitlines():
        if not line.startswith("|"):
            break
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if set(cells[0]) <= set("-: "):
            continue  # the separator row
        names = re.findall(r"`([a-z_]+)`", cells[0])
        words = re.findall(r"[A-Za-z_]+", cells[-1])
        uses = [ALL] if words == [ALL] else [word for word in words if word in known]
        for name in names:
            table[name] = uses
    return table
