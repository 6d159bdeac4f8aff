#!/usr/bin/python3
"""Checks the module layering (cmake/modules.txt, DESIGN.md's table) over the #include lines.

    scripts/check_layering.py [ROOT]      (ROOT: the project, default: this script's parent folder)

Reads every C++ file under include/topocut/<m>/, src/<m>/ and tests/<m>/ (their subfolders too: the module
is the first folder, src/segmentation/cuts/ is segmentation) and fails (exit 1) with one
line per include of a module that <m> may not use; prints "layering: ok" otherwise. Modules are
named by the first folder of an include: "topocut/<module>/..." (public headers) or "<module>/..."
(a module's private headers under src/, or test helpers under tests/).

The rule, from DESIGN.md ("Layout"): a module may use only the modules its line of the graph names,
and what those use; nothing in the library includes an adapter (cli, python, ros: "all" in the
graph), which (like benchmarks/, fuzz/ and examples/, which are not read) may use everything. A test
folder may use what its module may, and any test helper (a header under tests/).
"""
import os
import re
import sys

from module_graph import GraphError, read_graph

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp", ".cc")


def allowed_modules(table):
    """Each module with itself and everything it may use, directly or through the modules it uses."""
    closure = {}

    def visit(module, path):
        if module in closure:
            return closure[module]
        if module in path:
            raise SystemExit("check_layering: the table has a cycle through " + module)
        reach = {module}
        for dep in table[module]:
            reach |= visit(dep, path + [module])
        closure[module] = reach
        return reach

    for module in table:
        visit(module, [])
    return closure


def included_module(include, known):
    """The module an include names, or None for an include of no module (a file beside it)."""
    parts = include.split("/")
    if parts[0] == "topocut" and len(parts) >= 3:
        return parts[1]
    if parts[0] == "topocut" and len(parts) == 2:
        return "topocut.h"  # the umbrella header: every module
    if len(parts) >= 2 and parts[0] in known:
        return parts[0]
    return None


def files_of(root, module):
    for folder in (os.path.join("include", "topocut", module), os.path.join("src", module), os.path.join("tests", module)):
        top = os.path.join(root, folder)
        for directory, _, names in sorted(os.walk(top)):
            for name in sorted(names):
                if name.endswith(SOURCE_SUFFIXES):
                    yield os.path.join(directory, name)


def violations(root, table, adapters):
    reach = allowed_modules(table)
    known = set(table) | set(adapters)
    found = []
    for module in table:
        for path in files_of(root, module):
            relative = os.path.relpath(path, root)
            is_test = relative.startswith("tests" + os.sep)
            with open(path, encoding="utf-8", errors="replace") as source:
                for number, line in enumerate(source, 1):
                    match = INCLUDE.match(line)
                    if not match:
                        continue
                    include = match.group(1)
                    used = included_module(include, known)
                    if used is None or used in reach[module]:
                        continue
                    if is_test and used not in adapters and os.path.isfile(os.path.join(root, "tests", include)):
                        continue  # a test helper
                    if used == "topocut.h":
                        why = "the umbrella header (every module)"
                    elif used in adapters:
                        why = "an adapter, which no library module may include"
                    else:
                        why = "not in its line of the module graph (may use: " + ", ".join(sorted(reach[module] - {module})) + ")"
                    found.append(f"{relative}:{number}: {module} includes {used} ({include}): {why}")
    return found


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    if not os.path.isdir(os.path.join(root, "include", "topocut")):
        print(f"check_layering: {root} has no include/topocut folder", file=sys.stderr)
        return 2
    try:
        table, adapters = read_graph(root)
    except GraphError as error:
        print(f"check_layering: {error}", file=sys.stderr)
        return 2
    found = violations(root, table, adapters)
    for line in found:
        print(line)
    if found:
        print(f"layering: {len(found)} include(s) break the module graph")
        return 1
    print("layering: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
