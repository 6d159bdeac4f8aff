#!/usr/bin/python3
"""Checks that the build and the design say what the module graph (cmake/modules.txt) says.

    scripts/check_module_graph.py cmake ROOT LINKS    LINKS: the module links CMake made, one line per
                                                      module library: the module, then the modules
                                                      it links (build/module_links.txt)
    scripts/check_module_graph.py design ROOT DESIGN  DESIGN: DESIGN.md, whose module table's
                                                      "depends on" column must match the graph

Prints one line per disagreement and exits 1, "module graph: ... agree" and 0 when they agree, 2
when a file cannot be read, and 77 (a skipped test) when DESIGN.md is absent: it lives in the shared
folder beside the checkout, which a CI machine may not have.
"""
import os
import sys

from module_graph import ALL, GraphError, design_table, read_graph

SKIPPED = 77


def names(uses):
    return ", ".join(uses) if uses else "nothing"


def compare(graph, other, other_name):
    """One line per module on which other disagrees with graph (both {module: uses})."""
    found = []
    for module, uses in graph.items():
        if module not in other:
            found.append(f"{module}: in cmake/modules.txt, not in {other_name}")
        elif sorted(other[module]) != sorted(uses):
            found.append(f"{module}: {other_name} says it uses {names(other[module])}; cmake/modules.txt says {names(uses)}")
    for module in other:
        if module not in graph:
            found.append(f"{module}: in {other_name}, not in cmake/modules.txt")
    return found


def cmake_links(path):
    with open(path, encoding="utf-8") as source:
        return {words[0]: words[1:] for words in (line.split() for line in source) if words}


def main(argv):
    if len(argv) != 4 or argv[1] not in ("cmake", "design"):
        print("usage: check_module_graph.py cmake ROOT LINKS | design ROOT DESIGN.md", file=sys.stderr)
        return 2
    what, root, path = argv[1], argv[2], argv[3]
    try:
        modules, adapters = read_graph(root)
        if what == "design" and not os.path.isfile(path):
            print(f"module graph: {path} is absent (the shared folder is not beside the checkout); "
                  "DESIGN.md's table not compared")
            return SKIPPED
        if what == "design":
            graph = dict(modules, **{adapter: [ALL] for adapter in adapters})
            other = design_table(path, set(graph))
            found = compare(graph, other, "DESIGN.md")
        else:
            found = compare(modules, cmake_links(path), "CMake")
    except (OSError, GraphError) as error:
        print(f"check_module_graph: {error}", file=sys.stderr)
        return 2
    for line in found:
        print(line)
    subject = "DESIGN.md's table" if what == "design" else "CMake's module links"
    if found:
        print(f"module graph: {subject} and cmake/modules.txt disagree on {len(found)} module(s)")
        return 1
    print(f"module graph: {subject} and cmake/modules.txt agree")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
