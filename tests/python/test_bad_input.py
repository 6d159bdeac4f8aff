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
    # The range of the commands' --resolution (the option table), with the keyword's name.
    with pytest.raises(ValueError, match=r"^resolution must lie in \[0.0001, 1000\] metres per cell, got"):
        topocut.segment(free_box(), resolution)


def test_bad_options():
    with pytest.raises(ValueError, match=r"^concavity must lie in \(0, 100000\] metres, got -1$"):
        topocut.segment(free_box(), 0.05, concavity=-1)
    with pytest.raises(ValueError, match="origin"):
        topocut.segment(free_box(), 0.05, origin=(1.0,))
    with pytest.raises(ValueError, match="row_order"):
        topocut.segment(free_box(), 0.05, row_order="sideways")
    with pytest.raises(ValueError, match="--parity already switches every improvement off"):
        topocut.segment(free_box(), 0.05, parity=True, no_merge=True)
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'concavty' \(did you mean concavity\?\)"):
        topocut.segment(free_box(), 0.05, concavty=2.0)
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'xyz'; options are"):
        topocut.segment(free_box(), 0.05, xyz=2.0)


def test_dashed_keywords_are_the_same_options():
    dashed = topocut.segment(free_box(), 0.05, **{"robot-radius": 0.3, "no-merge": True})
    underscored = topocut.segment(free_box(), 0.05, robot_radius=0.3, no_merge=True)
    assert np.array_equal(np.asarray(dashed.labels), np.asarray(underscored.labels))
    # The dashed name reaches the same option: the same check refuses the same bad value.
    with pytest.raises(ValueError, match="robot.radius"):
        topocut.segment(free_box(), 0.05, **{"robot-radius": -1.0})


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


@pytest.mark.parametrize(
    "flag, value",
    [
        ("free-threshold", "256"),
        ("free-threshold", "-1"),
        ("free-threshold", "250.5"),
        ("occupied-threshold", "300"),
        ("resolution", "0"),
        ("resolution", "1e308"),
        ("max-megapixels", "5000"),
    ],
)
def test_load_map_and_segment_refuse_what_the_command_refuses(cli, bundled_map, flag, value):
    # One check per option (the option table): the same values refused with the same message, the
    # option named as each adapter spells it.
    keyword = flag.replace("-", "_")
    image = bundled_map.replace(".yaml", ".png")
    run = subprocess.run([cli, "segment", image, f"--{flag}", value], capture_output=True, text=True)
    assert run.returncode == 2
    with pytest.raises(ValueError) as error:
        topocut.load_map(image, **{keyword: float(value)})
    assert run.stderr.startswith(f"topocut segment: error: {str(error.value).replace(keyword, '--' + flag, 1)} (see")
    if flag in ("free-threshold", "occupied-threshold", "resolution"):
        args = {keyword: float(value)} if flag != "resolution" else {}
        with pytest.raises(ValueError) as error_segment:
            topocut.segment(free_box(np.uint8), float(value) if flag == "resolution" else 0.05, **args)
        assert str(error_segment.value) == str(error.value)


def test_load_map_options_are_the_commands():
    m = topocut.load_map(str(pytest.importorskip("pathlib").Path(__file__).parents[2] / "maps" / "floorplan.png"),
                         free_threshold=200, max_megapixels=1)
    assert m.cells == "free > 200, occupied < 50 (fixed)"  # a threshold given means fixed thresholds
    assert topocut.load_map(str(pytest.importorskip("pathlib").Path(__file__).parents[2] / "maps" / "floorplan.png"), 0.1).resolution == 0.1
    with pytest.raises(TypeError, match="max_megapixels"):
        topocut.load_map("x.png", no_such_option=1)
