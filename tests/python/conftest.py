# Shared fixtures of the Python tests: where the command, the bundled maps and the datasets are
# (ctest sets the variables; see cmake/python.cmake).
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("TOPOCUT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SHARED_DIR = pathlib.Path(os.environ.get("TOPOCUT_SHARED_DIR", SOURCE_DIR.parent / "shared"))


@pytest.fixture
def cli():
    path = os.environ.get("TOPOCUT_CLI")
    if not path:
        pytest.skip("TOPOCUT_CLI is not set (run through ctest)")
    return path


@pytest.fixture
def bundled_map():
    return str(SOURCE_DIR / "maps" / "floorplan.yaml")


@pytest.fixture
def bormann_map():
    path = SHARED_DIR / "datasets" / "bormann" / "Freiburg52_scan.png"
    if not path.exists():
        pytest.skip(f"{path} is absent (the Bormann dataset lives in ../shared)")
    return str(path)
