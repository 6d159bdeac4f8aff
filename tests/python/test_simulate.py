# topocut.simulate_map: the same arrays as `topocut simulate-map` writes, deterministic per seed, and
# the command's checks on bad input.
import subprocess

import numpy as np
import pytest
from PIL import Image

import topocut
from conftest import SOURCE_DIR

PLAN = str(SOURCE_DIR / "maps" / "floorplan.png")
TRUTH = str(SOURCE_DIR / "maps" / "floorplan_gt_segmentation.png")


def test_equals_the_command(cli, tmp_path):
    out_map, out_gt = tmp_path / "m.png", tmp_path / "g.png"
    subprocess.run([cli, "simulate-map", PLAN, "--seed", "6", "--windows", "0.3", "--out-map", str(out_map),
                    "--out-gt", str(out_gt)], check=True, capture_output=True)
    robot_map, rooms = topocut.simulate_map(PLAN, TRUTH, seed=6, windows=0.3)
    assert robot_map.dtype == np.uint8 and rooms.dtype == np.uint8
    assert np.array_equal(robot_map, np.asarray(Image.open(out_map)))
    assert np.array_equal(rooms, np.asarray(Image.open(out_gt)))
    # The plan and its ground truth as arrays give the same maps as the files.
    plan = np.asarray(Image.open(PLAN).convert("L"))
    truth = np.asarray(Image.open(TRUTH).convert("L"))
    again_map, again_rooms = topocut.simulate_map(plan, truth, 6, windows=0.3)
    assert np.array_equal(again_map, robot_map) and np.array_equal(again_rooms, rooms)


def test_deterministic_per_seed_and_rooms_on_free_cells():
    a, ga = topocut.simulate_map(PLAN, TRUTH, seed=2)
    b, gb = topocut.simulate_map(PLAN, TRUTH, seed=2)
    c, _ = topocut.simulate_map(PLAN, TRUTH, seed=3)
    assert np.array_equal(a, b) and np.array_equal(ga, gb)
    assert not np.array_equal(a, c)
    assert set(np.unique(a)) <= {0, 205, 255} and set(np.unique(ga)) <= {0, 255}
    assert (a == 205).any()
    assert not ((ga == 255) & (a != 255)).any()


def test_a_ground_truth_file_of_another_size_is_refused_by_its_header(tmp_path):
    # 10000 x 10000 declared for the plan's ground truth: refused before a pixel is decoded.
    data = bytearray(open(TRUTH, "rb").read())
    data[16:24] = (10000).to_bytes(4, "big") * 2
    (tmp_path / "big_gt.png").write_bytes(bytes(data))
    width, height = Image.open(PLAN).size
    with pytest.raises(ValueError, match=f"is 10000 x 10000 pixels but the plan is {width} x {height}"):
        topocut.simulate_map(PLAN, str(tmp_path / "big_gt.png"))


def test_bad_input_raises_with_the_commands_message():
    with pytest.raises(ValueError, match="seed"):
        topocut.simulate_map(PLAN, TRUTH, seed=-1)
    with pytest.raises(ValueError, match="windows"):
        topocut.simulate_map(PLAN, TRUTH, windows=2.0)
    with pytest.raises(ValueError, match="differ in size"):
        topocut.simulate_map(PLAN, np.zeros((10, 10), np.uint8))
    with pytest.raises(ValueError, match="uint8"):
        topocut.simulate_map(np.zeros((10, 10), np.float32), TRUTH)
    with pytest.raises(TypeError, match="windows"):
        topocut.simulate_map(PLAN, TRUTH, window=0.1)
    with pytest.raises(FileNotFoundError):
        topocut.simulate_map(str(SOURCE_DIR / "maps" / "nope.png"), TRUTH)
