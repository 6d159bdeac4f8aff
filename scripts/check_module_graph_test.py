#!/usr/bin/python3
"""Runs scripts/check_module_graph.py against planted DESIGN.md tables and CMake link lists built
from the project's graph: it must pass faithful copies, name each planted disagreement (a use
dropped, a use added, a module missing, an unknown module) and skip when DESIGN.md is absent."""
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from module_graph import read_graph  # noqa: E402

SCRIPT = os.path.join(HERE, "check_module_graph.py")
ROOT = os.path.dirname(HERE)


def run(*args):
    done = subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)
    return done.returncode, done.stdout.splitlines()


def expect(condition, message):
    if not condition:
        print("FAILED: " + message)
        sys.exit(1)


def design(rows):
    """A DESIGN.md whose table holds rows ({module cell: depends-on cell}), as the real one is laid out."""
    body = "".join(f"| {name} | what it holds | {uses} |\n" for name, uses in rows.items())
    return "# design\n\n| module | holds | depends on |\n|---|---|---|\n" + body + "\nAfter the table.\n| not | a row |\n"


def links(modules):
    return "".join(f"{module} {' '.join(uses)}\n" for module, uses in modules.items())


def check(root, kind, name, text):
    path = os.path.join(root, name)
    with open(path, "w", encoding="utf-8") as out:
        out.write(text)
    return run(kind, root, path)


def main():
    modules, adapters = read_graph(ROOT)
    expect("walls" in modules and "map" in modules["walls"], "the planted cases assume walls may use map")
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "cmake"))
        shutil.copy(os.path.join(ROOT, "cmake", "modules.txt"), os.path.join(root, "cmake"))

        # DESIGN.md: third-party names and remarks beside the modules, adapters sharing a row.
        rows = {f"`{m}`": ", ".join(uses + ["CGAL (geometry)"]) if uses else "CGAL, OpenCV" for m, uses in modules.items()}
        rows[" / ".join(f"`{a}`" for a in adapters)] = "all"
        code, lines = check(root, "design", "DESIGN.md", design(rows))
        expect(code == 0, f"a faithful DESIGN.md fails: {code} {lines}")
        planted = dict(rows)
        planted["`walls`"] = planted["`walls`"].replace("map, ", "")
        planted["`scan`"] = "core, map"
        del planted["`lines`"]
        planted["`plans`"] = "core"
        code, lines = check(root, "design", "DESIGN.md", design(planted))
        expect(code == 1, f"a DESIGN.md that disagrees passes: {code} {lines}")
        for prefix in ("walls: DESIGN.md says it uses", "scan: DESIGN.md says it uses core, map",
                       "lines: in cmake/modules.txt, not in DESIGN.md", "plans: in DESIGN.md, not in cmake/modules.txt"):
            expect(any(line.startswith(prefix) for line in lines), f"not reported: {prefix} in {lines}")
        expect(len(lines) == 5, f"expected 4 lines and the summary, got {lines}")
        code, lines = run("design", root, os.path.join(root, "absent", "DESIGN.md"))
        expect(code == 77 and "absent" in lines[0], f"an absent DESIGN.md is not skipped: {code} {lines}")

        # CMake's links.
        code, lines = check(root, "cmake", "module_links.txt", links(modules))
        expect(code == 0, f"faithful links fail: {code} {lines}")
        planted = dict(modules)
        planted["exploration"] = modules["exploration"] + ["evaluation"]
        code, lines = check(root, "cmake", "module_links.txt", links(planted))
        expect(code == 1 and lines[0].startswith("exploration: CMake says it uses"),
               f"an extra link passes: {code} {lines}")
    print("check_module_graph: detects every planted disagreement, passes faithful copies")
    return 0


if __name__ == "__main__":
    sys.exit(main())
