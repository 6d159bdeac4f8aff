#!/usr/bin/python3
"""Runs scripts/check_layering.py on small planted trees that carry the project's module graph: it
must pass a tree that keeps the graph (transitive uses and test helpers included), name every planted
violation, one line each, and refuse a tree without a graph."""
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "check_layering.py")
GRAPH = os.path.join(HERE, "..", "cmake", "modules.txt")


def write(root, path, includes):
    full = os.path.join(root, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w", encoding="utf-8") as out:
        out.write("".join(f'#include "{name}"\n' for name in includes) + "int x;\n")


def check(root):
    done = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
    return done.returncode, done.stdout.splitlines()


def expect(condition, message):
    if not condition:
        print("FAILED: " + message)
        sys.exit(1)


def main():
    with tempfile.TemporaryDirectory() as root:
        write(root, "include/topocut/core/error.h", [])
        code, lines = check(root)
        expect(code == 2 and lines == [], f"a tree without a module graph passes: {code} {lines}")
        os.makedirs(os.path.join(root, "cmake"))
        shutil.copy(GRAPH, os.path.join(root, "cmake", "modules.txt"))

        # Allowed: direct and transitive uses (evaluation -> exploration -> scan -> core), a module's
        # private header, a test helper of another module, the adapters using everything.
        write(root, "include/topocut/evaluation/report.h", ["topocut/exploration/run.h", "topocut/core/error.h"])
        write(root, "src/evaluation/report.cpp", ["topocut/scan/scan.h", "evaluation/detail.h", "topocut/io/overlay.h"])
        write(root, "tests/exploration/run_test.cpp", ["topocut/exploration/run.h", "io/temp_dir.h"])
        write(root, "tests/io/temp_dir.h", ["topocut/core/error.h"])
        write(root, "src/cli/main.cpp", ["topocut/walls/walls.h", "topocut/evaluation/report.h", "cli/command.h"])
        # A module's folders (src/segmentation/cuts/...) are the module's: their private headers and
        # test helpers by their path under the module.
        write(root, "src/segmentation/cuts/search.cpp", ["segmentation/cuts/search.h", "topocut/map/grid.h"])
        write(root, "tests/segmentation/merging/graph_test.cpp", ["segmentation/merging/graph.h", "segmentation/ids/rows.h"])
        write(root, "tests/segmentation/ids/rows.h", ["topocut/core/error.h"])
        code, lines = check(root)
        expect(code == 0 and lines == ["layering: ok"], f"a clean tree fails: {code} {lines}")

        # Planted: exploration -> evaluation (upward), walls -> segmentation (sideways), a private
        # header of a forbidden module, the umbrella header, the CLI from the library, a test.
        write(root, "include/topocut/exploration/run.h", ["topocut/evaluation/dataset.h"])
        write(root, "src/walls/pipeline.cpp", ["topocut/walls/walls.h", "topocut/segmentation/segmenter.h"])
        write(root, "src/scan/sim.cpp", ["decomposition/dude.h"])
        write(root, "src/map/all.cpp", ["topocut/topocut.h"])
        write(root, "src/core/bad.cpp", ["cli/command.h"])
        write(root, "tests/lines/fit_test.cpp", ["topocut/lines/fit.h", "topocut/walls/walls.h"])
        # The same from a module's subfolder: the module is the first folder under src/ and tests/.
        write(root, "src/segmentation/merging/up.cpp", ["topocut/evaluation/dataset.h"])
        write(root, "tests/segmentation/cuts/side_test.cpp", ["topocut/segmentation/cuts.h", "walls/helper.h"])
        code, lines = check(root)
        violations = [line for line in lines if not line.startswith("layering:")]
        expected = [
            "include/topocut/exploration/run.h:1: exploration includes evaluation",
            "src/walls/pipeline.cpp:2: walls includes segmentation",
            "src/scan/sim.cpp:1: scan includes decomposition",
            "src/map/all.cpp:1: map includes topocut.h",
            "src/core/bad.cpp:1: core includes cli",
            "tests/lines/fit_test.cpp:2: lines includes walls",
            "src/segmentation/merging/up.cpp:1: segmentation includes evaluation",
            "tests/segmentation/cuts/side_test.cpp:2: segmentation includes walls",
        ]
        expect(code == 1, f"violations pass: {code} {lines}")
        expect(len(violations) == len(expected), f"expected {len(expected)} lines, got {violations}")
        for prefix in expected:
            expect(any(line.startswith(prefix) for line in violations), f"not reported: {prefix} in {violations}")
        expect(lines[-1] == "layering: 8 include(s) break the module graph", f"summary: {lines[-1]}")
    print("check_layering: detects every planted violation, passes the clean tree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
