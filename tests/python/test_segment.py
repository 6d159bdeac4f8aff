# segment() and load_map(): the same rooms as the topocut command, in either row order.
import subprocess

import numpy as np
import pytest
from PIL import Image

import topocut


def cli_labels(cli, map_path, tmp_path, *options):
    out = tmp_path / "labels.png"
    subprocess.run([cli, "segment", map_path, "--out-labels", str(out), *options], check=True, capture_output=True)
    return np.array(Image.open(out)).astype(np.int32)


def test_labels_equal_the_commands_on_a_bormann_map(cli, bormann_map, tmp_path):
    expected = cli_labels(cli, bormann_map, tmp_path)
    m = topocut.load_map(bormann_map)
    result = topocut.segment(m.grid, m.resolution, m.origin)
    # load_map gives ROS row order (row 0 at the bottom); the label PNG is top-down.
    labels = np.flipud(result.labels)
    assert labels.shape == expected.shape
    assert expected.max() > 5, "the map should have several rooms"
    assert np.array_equal(labels, expected)
    assert len(result.rooms) == expected.max()


def test_options_are_the_commands(cli, bundled_map, tmp_path):
    expected = cli_labels(cli, bundled_map, tmp_path, "--concavity", "1.5", "--no-merge")
    m = topocut.load_map(bundled_map)
    result = topocut.segment(m.grid, m.resolution, m.origin, concavity=1.5, no_merge=True)
    assert np.array_equal(np.flipud(result.labels), expected)
    # The options reach the segmenter: one room per free-space component is fewer rooms.
    trivial = topocut.segment(m.grid, m.resolution, m.origin, trivial=True)
    assert len(trivial.rooms) < len(result.rooms)


def test_segmentation_rules_are_the_commands_list_and_its_switches(cli):
    rows = topocut.segmentation_rules()
    printed = subprocess.run([cli, "rules"], capture_output=True, text=True, check=True).stdout.splitlines()
    assert [line.split()[0] for line in printed] == [name for name, _, _, _ in rows]
    for line, (name, stage, keyword, does) in zip(printed, rows):
        assert line.split()[1] == stage and line.endswith(does)
        assert ("--no-" + name in line.split()) == (keyword is not None)
    # Each keyword is a switch segment() takes.
    keywords = [keyword for _, _, keyword, _ in rows if keyword is not None]
    assert "no_merge" in keywords
    topocut.segment(np.zeros((20, 20), np.int8), 0.05, **{keyword: True for keyword in keywords})


def grey_image(occupancy):
    """The top-down grey picture of an int8 ROS grid: 255 free, 0 occupied, 128 unknown."""
    grey = np.where(occupancy == 0, 255, np.where(occupancy == 100, 0, 128)).astype(np.uint8)
    return np.ascontiguousarray(np.flipud(grey))


def test_ros_row_order_gives_the_same_rooms_flipped(bundled_map):
    m = topocut.load_map(bundled_map)
    ros = topocut.segment(m.grid, m.resolution, m.origin)
    image = topocut.segment(grey_image(m.grid), m.resolution, m.origin, fixed_thresholds=True)
    assert len(ros.rooms) >= 3
    assert np.array_equal(ros.labels, np.flipud(image.labels))
    for a, b in zip(ros.rooms, image.rooms):
        assert a.id == b.id and a.area == b.area
        assert np.array_equal(a.outer, b.outer)
        assert a.inside == b.inside
    assert [(p.rooms, p.width, p.kind) for p in ros.passages] == [(p.rooms, p.width, p.kind) for p in image.passages]
    # A view of the same buffer in the other row order (negative stride) reads the same cells.
    flipped_view = np.flipud(m.grid)
    assert flipped_view.strides[0] < 0
    same = topocut.segment(flipped_view, m.resolution, m.origin, row_order="top-down")
    assert np.array_equal(same.labels, image.labels)


def test_rooms_passages_and_json(bundled_map):
    import json

    m = topocut.load_map(bundled_map)
    r = topocut.segment(m.grid, m.resolution, m.origin)
    assert r.labels.dtype == np.int32 and r.labels.shape == m.grid.shape
    assert not r.labels.flags.writeable
    ids = sorted(set(np.unique(r.labels)) - {0})
    assert ids == [room.id for room in r.rooms]
    for room in r.rooms:
        # The inside point's cell carries the room's label (ROS rows: row 0 at origin y).
        col = int((room.inside[0] - m.origin[0]) / m.resolution)
        row = int((room.inside[1] - m.origin[1]) / m.resolution)
        assert r.labels[row, col] == room.id
        xmin, ymin, xmax, ymax = room.bbox
        assert (room.outer[:, 0] >= xmin).all() and (room.outer[:, 1] <= ymax).all()
        assert room.labelled_area == pytest.approx(np.count_nonzero(r.labels == room.id) * m.resolution**2)
    assert r.passages and all(p.kind in ("door", "opening") for p in r.passages)
    data = json.loads(r.to_json())
    assert [room["id"] for room in data["rooms"]] == ids
    assert len(data["passages"]) == len(r.passages)


def test_labels_outlive_the_result(bundled_map):
    m = topocut.load_map(bundled_map)
    labels = topocut.segment(m.grid, m.resolution, m.origin).labels
    import gc

    gc.collect()
    assert labels.max() >= 3


def test_geojson_matches_the_command(cli, bundled_map, tmp_path):
    import json

    out = tmp_path / "rooms.geojson"
    subprocess.run([cli, "segment", bundled_map, "--out-geojson", str(out)], check=True, capture_output=True)
    m = topocut.load_map(bundled_map)
    r = topocut.segment(m.grid, m.resolution, m.origin)
    assert json.loads(r.to_geojson()) == json.loads(out.read_text())
    features = json.loads(out.read_text())["features"]
    rooms = [f for f in features if f["geometry"]["type"] == "Polygon"]
    assert [f["properties"]["id"] for f in rooms] == [room.id for room in r.rooms]
    for f in rooms:
        exterior = np.array(f["geometry"]["coordinates"][0])
        assert (exterior[0] == exterior[-1]).all()
        x, y = exterior[:, 0], exterior[:, 1]
        assert np.sum(x[:-1] * y[1:] - x[1:] * y[:-1]) > 0  # counter-clockwise
    lines = [f for f in features if f["geometry"]["type"] == "LineString"]
    assert len(lines) == len(r.passages)
    assert {f["properties"]["kind"] for f in lines} <= {"door", "opening"}


def test_example_script_draws_the_rooms(bundled_map, tmp_path):
    import os
    import sys

    from conftest import SOURCE_DIR

    out = tmp_path / "rooms.png"
    run = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "segment_map.py"), bundled_map, str(out)],
                         capture_output=True, text=True, env=os.environ.copy())
    assert run.returncode == 0, run.stderr
    assert "room 1:" in run.stdout
    picture = np.array(Image.open(out))
    assert picture.shape[0] > 200 and picture.shape[1] > 200


def test_room_kinds_are_the_commands_on_the_floorplan(cli, bundled_map, tmp_path):
    # The bundled floor plan: a corridor 2 m wide across the building at y 6..8 m, rooms north and south.
    import json

    out, labels_png = tmp_path / "rooms.json", tmp_path / "labels.png"
    subprocess.run([cli, "segment", bundled_map, "--out-json", str(out), "--out-labels", str(labels_png)], check=True,
                   capture_output=True)
    m = topocut.load_map(bundled_map)
    r = topocut.segment(m.grid, m.resolution, m.origin)
    assert np.array_equal(np.flipud(r.labels), np.array(Image.open(labels_png)).astype(np.int32))
    command = {room["id"]: room["kind"] for room in json.loads(out.read_text())["rooms"]}
    assert command == {room.id: room.kind for room in r.rooms}
    corridor = r.room_at(10.0, 7.0)
    assert corridor is not None and corridor.kind == "corridor"
    assert [room.id for room in r.rooms if room.kind == "corridor"] == [corridor.id]
    assert len(r.rooms) >= 5 and "corridor" in repr(corridor)
    try:
        import networkx  # noqa: F401
    except ImportError:
        return
    assert r.to_networkx().nodes[corridor.id]["kind"] == "corridor"
