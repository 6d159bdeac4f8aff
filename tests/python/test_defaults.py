# No silent defaults in the Python package: segment()'s labels score as returned, and a robot's YAML
# loads with the names, checks and messages of `topocut segment --config`.
import pickle
import subprocess
import warnings

import numpy as np
import pytest

import topocut
from conftest import SOURCE_DIR

FLOORPLAN_GT = str(SOURCE_DIR / "maps" / "floorplan_gt_segmentation.png")
ROBOT_YAML = str(SOURCE_DIR / "examples" / "robot.yaml")


def test_labels_score_as_segment_returns_them(bundled_map):
    m = topocut.load_map(bundled_map)
    r = topocut.segment(m.grid, m.resolution, m.origin)   # a ROS grid: labels bottom-up
    as_returned = topocut.evaluate(r.labels, FLOORPLAN_GT)
    flipped = topocut.evaluate(np.flipud(r.labels), FLOORPLAN_GT)   # what users had to write before
    whole = topocut.evaluate(r, FLOORPLAN_GT)
    assert as_returned.f1 > 0.8 and as_returned.recall > 0.9
    for other in (flipped, whole):
        assert (other.f1, other.recall, other.precision) == (as_returned.f1, as_returned.recall, as_returned.precision)


def test_only_the_array_as_returned_is_taken_as_bottom_up(bundled_map):
    m = topocut.load_map(bundled_map)
    labels = topocut.segment(m.grid, m.resolution, m.origin).labels
    right = topocut.evaluate(labels, FLOORPLAN_GT).f1
    # A copy is an ordinary array (rows top-down), so it scores as the image it would be.
    assert topocut.evaluate(labels.copy(), FLOORPLAN_GT).f1 < right
    assert topocut.evaluate(np.array(np.flipud(labels)), FLOORPLAN_GT).f1 == right
    # An image's labels are already top-down: taken as they are, the same as a copy of them.
    image = np.where(m.grid[::-1] == 0, 255, 0).astype(np.uint8)
    top_down = topocut.segment(image, m.resolution).labels
    assert topocut.evaluate(top_down, FLOORPLAN_GT).f1 == topocut.evaluate(top_down.copy(), FLOORPLAN_GT).f1 > 0.5


def test_load_options_reads_the_config_file(cli, bundled_map, tmp_path):
    options = topocut.load_options(ROBOT_YAML)
    assert options == {"robot_radius": 0.1, "concavity": 3.0, "door_width": 1.2, "min_room_area": 1.5}
    m = topocut.load_map(bundled_map)
    r = topocut.segment(m.grid, m.resolution, m.origin, **options)
    out = tmp_path / "rooms.json"
    subprocess.run([cli, "segment", bundled_map, "--config", ROBOT_YAML, "--out-json", str(out)], check=True,
                   capture_output=True)
    assert r.to_json() == out.read_text()


def test_load_options_refuses_as_config_does(cli, bundled_map, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)   # short paths: a message keeps only the two ends of a long one
    cases = {
        "concavty: 3\n": "'concavty' in config file '{}' is not a segmentation option (did you mean 'concavity'?)",
        "concavity: -1\n": "'concavity' in config file '{}' must",
        "no_merge: maybe\n": "'no_merge' in config file '{}' is a switch: give true or false",
        "- concavity\n": "config file '{}' must be a mapping of option names to values",
        "concavity: [1, 2]\n": "'concavity' in config file '{}' takes one number, not a list",
    }
    for k, (text, message) in enumerate(cases.items()):
        path = f"bad{k}.yaml"
        (tmp_path / path).write_text(text)
        with pytest.raises(ValueError) as raised:
            topocut.load_options(path)
        assert message.format(path) in str(raised.value)
        # The command refuses the same file.
        run = subprocess.run([cli, "segment", bundled_map, "--config", path], capture_output=True, text=True)
        assert run.returncode == 2 and run.stdout == "", run
    with pytest.raises(FileNotFoundError):
        topocut.load_options(str(tmp_path / "missing.yaml"))
    (tmp_path / "output.yaml").write_text("out-json: rooms.json\n")
    with pytest.raises(ValueError, match="is not a segmentation option"):
        topocut.load_options(str(tmp_path / "output.yaml"))


def test_an_images_assumed_resolution_is_announced(bundled_map):
    image = str(SOURCE_DIR / "maps" / "floorplan.png")
    with pytest.warns(UserWarning, match="an image holds no scale: its cells were taken as 0.05 m"):
        assert topocut.load_map(image).resolution == 0.05
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert topocut.load_map(image, 0.1).resolution == 0.1
        assert topocut.load_map(image, resolution=0.05).resolution == 0.05
        assert topocut.load_map(bundled_map).resolution == 0.05   # the YAML gives it


def test_map_and_room_fields_are_documented(bundled_map):
    assert "row 0" in topocut.Map.grid.__doc__ and "-1 unknown" in topocut.Map.grid.__doc__
    assert "labels" in topocut.Room.id.__doc__
    assert "row order" in topocut.load_options.__doc__ or "--config" in topocut.load_options.__doc__
    m = topocut.load_map(bundled_map)
    assert pickle.loads(pickle.dumps(m)).grid.shape == m.grid.shape
