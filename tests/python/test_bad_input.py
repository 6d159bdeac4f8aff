# Bad input raises one ValueError with the command's message (a missing file FileNotFoundError);
# nothing crashes.
import subprocess

import numpy as np
import pytest

import topocut


def free_box(dtype=np.int8):
    grid = np.full((40, 60), 100 if dtype == np.int8 else 0, dtype=dtype)
    grid[2:-2, 2:-2] = 0 if dtype == np.int8 else 255
    return grid


@pytest.mark.parametrize(
    "grid, message",
    [
        (np.zeros((10, 10), dtype=np.float64), "int8 .* or uint8"),
        (np.zeros((10, 10), dtype=np.int16), "int8 .* or uint8"),
        (np.zeros((4, 10, 10), dtype=np.int8), "2-D"),
        (np.zeros((0, 10), dtype=np.int8), "empty"),
        (np.zeros((10, 0), dtype=np.uint8), "empty"),
        (np.zeros((10, 20), dtype=np.int8)[:, ::2], "adjacent in memory"),
        (np.full((10, 10), 101, dtype=np.int8), "101 .*outside -1..100"),
        (np.full((10, 10), -7, dtype=np.int8), "-7 .*outside -1..100"),
    ],
)
def test_bad_grids(grid, message):
    with pytest.raises(ValueError, match=message):
        topocut.segment(grid, 0.05)


@pytest.mark.parametrize("resolution", [0.0, -0.05, float("nan"), float("inf")])
def test_bad_resolution(resolution):
    with pytest.raises(ValueError, match="resolution must be a positive number"):
        topocut.segment(free_box(), resolution)


def test_bad_options():
    with pytest.raises(ValueError, match="^concavity must be a positive number$"):
        topocut.segment(free_box(), 0.05, concavity=-1)
    with pytest.raises(ValueError, match="origin"):
        topocut.segment(free_box(), 0.05, origin=(1.0,))
    with pytest.raises(ValueError, match="row_order"):
        topocut.segment(free_box(), 0.05, row_order="sideways")
    with pytest.raises(ValueError, match="--parity already switches every improvement off"):
        topocut.segment(free_box(), 0.05, parity=True, no_merge=True)
    with pytest.raises(TypeError, match="unexpected keyword argument 'concavty'"):
        topocut.segment(free_box(), 0.05, concavty=2.0)


def test_no_free_space():
    with pytest.raises(ValueError):
        topocut.segment(np.full((10, 10), 100, dtype=np.int8), 0.05)


def test_messages_are_the_commands(cli, tmp_path):
    missing = str(tmp_path / "missing.png")
    run = subprocess.run([cli, "segment", missing], capture_output=True, text=True)
    assert run.returncode != 0
    with pytest.raises(FileNotFoundError) as error:
        topocut.load_map(missing)
    assert error.value.filename == missing
    assert run.stderr.strip() == f"topocut segment: error: {error.value.strerror}"
    run = subprocess.run([cli, "segment", missing, "--parity", "--no-merge"], capture_output=True, text=True)
    with pytest.raises(ValueError) as error:
        topocut.segment(free_box(), 0.05, parity=True, no_merge=True)
    assert str(error.value) in run.stderr


def test_bad_polygons_and_scans():
    with pytest.raises(ValueError, match="at least 3 points"):
        topocut.decompose([[0, 0], [1, 0]], tau=1.0)
    with pytest.raises(ValueError, match="at least 3 points"):
        topocut.decompose([[0, 0], [4, 0], [4, 4], [0, 4]], holes=[[[1, 1], [2, 1]]], tau=1.0)
    with pytest.raises(ValueError, match=r"\(n, 2\)"):
        topocut.decompose([[0, 0, 0], [1, 0, 0], [1, 1, 1]], tau=1.0)
    with pytest.raises(ValueError, match="tau"):
        topocut.decompose([[0, 0], [1, 0], [1, 1]], tau=0.0)
    with pytest.raises(ValueError):
        topocut.extract_lines([0.0, 0.1], [1.0], method="smf")
    with pytest.raises(ValueError):
        topocut.extract_lines([0.0, 0.1], [1.0, 1.0], method="hough")
