# The package as users and editors see it: signatures and type stubs from the option table, the
# room at a point, errors by kind, pickling, shapely and networkx views.
import ast
import inspect
import os
import pathlib
import pickle
import subprocess

import numpy as np
import pytest

import topocut


@pytest.fixture(scope="module")
def floorplan():
    from conftest import SOURCE_DIR

    m = topocut.load_map(str(SOURCE_DIR / "maps" / "floorplan.yaml"))
    return m, topocut.segment(m.grid, m.resolution, m.origin)


def stub_tree():
    path = pathlib.Path(topocut.__file__).with_name("__init__.pyi")
    assert path.exists(), f"{path}: the build writes the stubs beside the package"
    return ast.parse(path.read_text())


def stub_keywords(function):
    """name -> default of a stub function's keyword-only parameters."""
    return {a.arg: ast.literal_eval(d) for a, d in zip(function.args.kwonlyargs, function.args.kw_defaults)}


def stub_functions(tree):
    functions = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
    for c in (n for n in tree.body if isinstance(n, ast.ClassDef)):
        functions.update({f"{c.name}.{n.name}": n for n in c.body if isinstance(n, ast.FunctionDef)})
    return functions


def test_stubs_list_every_keyword_with_its_type_and_default():
    functions = stub_functions(stub_tree())
    for stub, kind in [("segment", "segment"), ("IncrementalSegmenter.__init__", "incremental"),
                       ("IncrementalSegmenter.update", "grid"), ("merge_training_rows", "options"),
                       ("simulate_map", "simulate")]:
        table = topocut._topocut._keywords(kind)
        assert stub_keywords(functions[stub]) == {name: default for name, _, default, _ in table}, stub
        annotations = {a.arg: ast.unparse(a.annotation) for a in functions[stub].args.kwonlyargs}
        assert annotations == {name: type_name for name, type_name, _, _ in table}, stub
    # The segment command's 25 options and the grid reading, at least.
    assert len(stub_keywords(functions["segment"])) >= 30


def test_stub_defaults_are_the_defaults(floorplan):
    m, default = floorplan
    given = stub_keywords(stub_functions(stub_tree())["segment"])
    explicit = topocut.segment(m.grid, m.resolution, m.origin, **given)
    assert np.array_equal(explicit.labels, default.labels)
    incremental = stub_keywords(stub_functions(stub_tree())["IncrementalSegmenter.__init__"])
    a = topocut.IncrementalSegmenter(**incremental).update(m.grid, m.resolution, m.origin)
    b = topocut.IncrementalSegmenter().update(m.grid, m.resolution, m.origin)
    assert np.array_equal(a.labels, b.labels)


def test_stubs_name_exactly_the_keywords_segment_accepts():
    # segment()'s TypeError for an unknown keyword lists what options.cpp accepts.
    with pytest.raises(TypeError) as error:
        topocut.segment(np.zeros((20, 20), np.int8), 0.05, no_such_option=1)
    accepted = {name.strip() for name in str(error.value).split("options are:", 1)[1].split(",")}
    assert accepted == set(stub_keywords(stub_functions(stub_tree())["segment"]))


def test_stubs_and_module_name_the_same_things():
    tree = stub_tree()
    names = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    assert set(topocut.__all__) <= names
    assert names - {"Point", "Pose", "ArrayLike"} <= set(topocut.__all__)
    for c in (n for n in tree.body if isinstance(n, ast.ClassDef)):
        for member in (n.name for n in c.body if isinstance(n, ast.FunctionDef)):
            assert hasattr(getattr(topocut, c.name), member), f"{c.name}.{member}"
        runtime = {name for name in dir(getattr(topocut, c.name)) if not name.startswith("_")}
        stubbed = {n.name for n in c.body if isinstance(n, ast.FunctionDef)}
        assert runtime <= stubbed, f"{c.name}: {runtime - stubbed} are not in the stubs"


def test_help_and_inspect_show_every_option():
    parameters = inspect.signature(topocut.segment).parameters
    for name in ("concavity", "robot_radius", "door_width", "no_merge", "row_order", "free_thresh"):
        assert parameters[name].kind is inspect.Parameter.KEYWORD_ONLY
    assert parameters["concavity"].default == 2.5 and parameters["concavity"].annotation is float
    assert "robot_radius" in inspect.signature(topocut.IncrementalSegmenter).parameters
    assert "concavity: maximum concavity" in topocut.segment.__doc__
    with pytest.raises(TypeError, match="concavty"):
        topocut.segment(np.zeros((20, 20), np.int8), 0.05, concavty=2.0)


def test_room_at_answers_from_the_labels(floorplan):
    m, r = floorplan
    for room in r.rooms:
        assert r.room_at(*room.inside).id == room.id
    h, w = m.grid.shape
    rng = np.random.default_rng(7)
    for x, y in rng.uniform((m.origin[0] - 1, m.origin[1] - 1), (m.origin[0] + w * m.resolution + 1, m.origin[1] + h * m.resolution + 1), (300, 2)):
        col, row = int(np.floor((x - m.origin[0]) / m.resolution)), int(np.floor((y - m.origin[1]) / m.resolution))
        expected = r.labels[row, col] if 0 <= row < h and 0 <= col < w else 0
        found = r.room_at(x, y)
        assert (found.id if found else 0) == expected, (x, y)
    assert r.room_at(-100.0, 3.0) is None
    with pytest.raises(ValueError, match="finite"):
        r.room_at(float("nan"), 1.0)


def test_room_at_equals_the_commands(cli, bundled_map):
    m = topocut.load_map(bundled_map)
    r = topocut.segment(m.grid, m.resolution, m.origin)
    points = [(2.0, 1.5), (5.5, 3.0), (0.01, 0.01), (-5.0, 3.0), (12.3, 7.7)]
    args = [a for x, y in points for a in ("--at", f"{x},{y}")]
    out = subprocess.run([cli, "segment", bundled_map, *args], check=True, capture_output=True, text=True).stdout
    expected = [f"at {x},{y}: " + (f"room {room.id}" if (room := r.room_at(x, y)) else "none") for x, y in points]
    assert out.strip().splitlines()[-len(points):] == expected


def test_missing_and_unreadable_files_raise_os_errors(tmp_path, bundled_map):
    missing = str(tmp_path / "missing.yaml")
    with pytest.raises(FileNotFoundError) as error:
        topocut.load_map(missing)
    assert error.value.filename == missing and "does not exist" in error.value.strerror
    with pytest.raises(FileNotFoundError):
        topocut.evaluate(str(tmp_path / "labels.png"), np.zeros((4, 4), np.uint8))
    with pytest.raises(IsADirectoryError):
        topocut.load_map(str(tmp_path))
    yaml = tmp_path / "map.yaml"
    yaml.write_text(pathlib.Path(bundled_map).read_text())  # names floorplan.png, which is not beside it
    with pytest.raises(FileNotFoundError) as error:
        topocut.load_map(str(yaml))
    assert error.value.filename == str(tmp_path / "floorplan.png")
    # Bad content stays a ValueError.
    (tmp_path / "notes.png").write_text("not an image")
    with pytest.raises(ValueError):
        topocut.load_map(str(tmp_path / "notes.png"))


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads files whatever their permissions")
def test_a_file_without_read_permission_raises_permission_error(tmp_path, bundled_map):
    locked = tmp_path / "locked.png"
    locked.write_bytes(pathlib.Path(bundled_map).with_name("floorplan.png").read_bytes())
    locked.chmod(0)
    with pytest.raises(PermissionError):
        topocut.load_map(str(locked))


def test_results_pickle(floorplan):
    m, r = floorplan
    again = pickle.loads(pickle.dumps(r))
    assert type(again) is topocut.Segmentation
    assert np.array_equal(again.labels, r.labels) and again.labels.shape == r.labels.shape
    assert again.to_json() == r.to_json() and again.to_geojson() == r.to_geojson()
    assert again.resolution == r.resolution and again.origin == r.origin
    assert again.room_at(2.0, 1.5).id == r.room_at(2.0, 1.5).id
    room = pickle.loads(pickle.dumps(r.rooms[2]))
    assert (room.id, room.kind, room.area, room.labelled_area, room.inside, room.bbox) == (
        r.rooms[2].id, r.rooms[2].kind, r.rooms[2].area, r.rooms[2].labelled_area, r.rooms[2].inside, r.rooms[2].bbox)
    corridor = next(room for room in r.rooms if room.kind == "corridor")
    assert pickle.loads(pickle.dumps(corridor)).kind == "corridor"
    assert np.array_equal(room.outer, r.rooms[2].outer)
    passage = pickle.loads(pickle.dumps(r.passages[0]))
    assert (passage.rooms, passage.kind, passage.width, passage.rule) == (
        r.passages[0].rooms, r.passages[0].kind, r.passages[0].width, r.passages[0].rule)
    loaded = pickle.loads(pickle.dumps(m))
    assert np.array_equal(loaded.grid, m.grid) and loaded.origin == m.origin and loaded.cells == m.cells
    labels = np.zeros((40, 40), np.int32)
    labels[:, 20:] = 1
    truth = np.where(labels > 0, 255, 0).astype(np.uint8)
    scores = topocut.evaluate(labels, truth)
    copy = pickle.loads(pickle.dumps(scores))
    assert (copy.recall, copy.precision, copy.f1, copy.pq, copy.matches) == (scores.recall, scores.precision, scores.f1, scores.pq, scores.matches)
    # A bottom-up segmentation keeps its frame.
    assert np.array_equal(pickle.loads(pickle.dumps(r)).labels, r.labels)


def test_shapely_polygons_are_the_rooms(floorplan):
    shapely = pytest.importorskip("shapely.geometry", reason="python3-shapely is not installed")
    _, r = floorplan
    polygons = r.to_shapely()
    assert sorted(polygons) == [room.id for room in r.rooms]
    for room in r.rooms:
        polygon = polygons[room.id]
        assert isinstance(polygon, shapely.Polygon) and polygon.is_valid
        assert polygon.area == pytest.approx(room.area, abs=1e-6)  # the outputs' area is the polygon's
        assert polygon.contains(shapely.Point(room.inside))
    ids = list(polygons)
    for i, a in enumerate(ids):
        for b in ids[i + 1:]:
            assert polygons[a].intersection(polygons[b]).area < 1e-9, (a, b)
    line = r.passages[0].to_shapely()
    assert line.length == pytest.approx(r.passages[0].width, abs=1e-6)


def test_networkx_graph_is_the_room_graph(floorplan):
    networkx = pytest.importorskip("networkx", reason="python3-networkx is not installed")
    _, r = floorplan
    graph = r.to_networkx()
    assert isinstance(graph, networkx.MultiGraph)
    assert sorted(graph.nodes) == [room.id for room in r.rooms]
    assert graph.number_of_edges() == len(r.passages)
    for room in r.rooms:
        assert graph.nodes[room.id]["area"] == room.area and graph.nodes[room.id]["inside"] == room.inside
    for passage in r.passages:
        kinds = [data["kind"] for data in graph.get_edge_data(*passage.rooms).values()]
        assert passage.kind in kinds
    assert networkx.is_connected(graph)  # the floor plan's rooms are all reachable


def test_json_carries_what_python_carries(floorplan):
    import json

    _, r = floorplan
    data = json.loads(r.to_json())
    for room, entry in zip(r.rooms, data["rooms"]):
        assert entry["id"] == room.id and tuple(entry["inside"]) == pytest.approx(room.inside, abs=1e-6)
        assert entry["area"] == pytest.approx(room.area, abs=1e-6)
        assert entry["labelled_area"] == pytest.approx(room.labelled_area, abs=1e-6)
    assert [p["kind"] for p in data["passages"]] == [p.kind for p in r.passages]
    assert [p["rule"] for p in data["passages"]] == [p.rule for p in r.passages]
    assert {p.rule for p in r.passages} <= {"door", "wall-opening", "island-cut", "wall-line", "decomposition"}
