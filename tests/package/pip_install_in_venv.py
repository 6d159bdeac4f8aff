#!/usr/bin/env python3
"""ctest python_package: `pip install --no-build-isolation --no-index .` into a fresh virtual
environment that sees Debian's packages (numpy, matplotlib), reusing the test's CMake build folder,
then runs examples/segment_map.py with the environment's interpreter from another folder and checks
that the installed package (extension, stubs, py.typed) is the one imported.

    pip_install_in_venv.py SOURCE_DIR BUILD_DIR WORK_DIR

Exits 77 (skipped) with a message when python3-venv is missing.
"""
import os
import pathlib
import shutil
import subprocess
import sys


def run(command, **kwargs):
    result = subprocess.run([str(c) for c in command], capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        sys.exit(f"failed ({result.returncode}): {' '.join(map(str, command))}\n{result.stdout}\n{result.stderr}")
    return result.stdout


def main():
    source, build, work = (pathlib.Path(a).resolve() for a in sys.argv[1:4])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    venv = work / "venv"
    made = subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], capture_output=True, text=True)
    if made.returncode != 0 or not (venv / "bin" / "pip").exists():
        print(f"python_package skipped: cannot make a virtual environment with pip (install python3-venv): {made.stderr.strip()}")
        return 77
    python = venv / "bin" / "python"
    env = dict(os.environ, TOPOCUT_BUILD_DIR=str(build), PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.pop("PYTHONPATH", None)
    run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", source], env=env, cwd=work)

    installed = pathlib.Path(run([python, "-c", "import topocut; print(topocut.__file__)"], env=env, cwd=work).strip()).parent
    if venv not in installed.parents:
        sys.exit(f"topocut was imported from {installed}, not from the virtual environment {venv}")
    for name in ("__init__.py", "__init__.pyi", "py.typed"):
        if not (installed / name).exists():
            sys.exit(f"the installed package lacks {name}")
    if not list(installed.glob("_topocut*.so")):
        sys.exit("the installed package lacks its extension")

    # The licence travels with the package: pip show and the wheel's metadata say it.
    shown = run([python, "-m", "pip", "show", "topocut"], env=env, cwd=work)
    if "License: GPL-3.0-or-later" not in shown:
        sys.exit(f"pip show topocut does not give the project's licence:\n{shown}")

    picture = work / "rooms.png"
    out = run([python, source / "examples" / "segment_map.py", source / "maps" / "floorplan.yaml", picture], env=env, cwd=work)
    if "room 1:" not in out or f"wrote {picture}" not in out or picture.stat().st_size < 1000:
        sys.exit(f"the example did not segment the map and draw it:\n{out}")
    print(out.strip())
    print(f"installed into {installed} and ran examples/segment_map.py there")
    shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
