# Objects valid by construction (no state-less form, every unpickled state checked, the pickle round
# trip fuzzed), merge models bounded as in the command, and the one option parser: every bad value
# of the option table gives the command's message.
import math
import os
import pathlib
import pickle
import subprocess
import sys
import time

import numpy as np
import pytest

import topocut

FUZZ_DIR = pathlib.Path(__file__).resolve().parents[2] / "fuzz"


def rooms_grid():
    grid = np.full((80, 160), 100, np.int8)  # two rooms and a door
    grid[2:-2, 2:-2] = 0
    grid[2:-2, 80] = 100
    grid[30:46, 80] = 0
    return grid


@pytest.fixture(scope="module")
def result():
    return topocut.segment(rooms_grid(), 0.05, (1.0, -2.0, 0.3))


def test_objects_made_by_new_alone_hold_nothing():
    # Each crashed (or read uninitialised memory) on its first property before.
    probes = {
        topocut.Segmentation: lambda o: o.rooms, topocut.Room: lambda o: o.area, topocut.Passage: lambda o: o.width,
        topocut.Map: lambda o: o.grid, topocut.Scores: lambda o: o.recall,
        topocut.IncrementalSegmenter: lambda o: o.update(rooms_grid(), 0.05),
    }
    for cls, probe in probes.items():
        empty = cls.__new__(cls)
        with pytest.raises(TypeError, match="holds nothing: it was made by __new__ without a state"):
            probe(empty)
    for cls in (topocut.Room, topocut.Passage, topocut.Scores):
        with pytest.raises(TypeError, match="holds nothing"):
            repr(cls.__new__(cls))
    with pytest.raises(TypeError, match="holds nothing"):
        topocut.IncrementalSegmenter.__new__(topocut.IncrementalSegmenter).last_update
    for ledger_call in ("save_ledger", "load_ledger"):  # a file name given, the missing state found first
        with pytest.raises(TypeError, match="holds nothing"):
            getattr(topocut.IncrementalSegmenter.__new__(topocut.IncrementalSegmenter), ledger_call)("ledger.txt")
    with pytest.raises(TypeError, match="holds nothing"):
        topocut.Segmentation.__new__(topocut.Segmentation).room_at(0.0, 0.0)
    with pytest.raises(TypeError, match="holds nothing"):
        pickle.dumps(topocut.Segmentation.__new__(topocut.Segmentation))


def set_state(cls, state):
    obj = cls.__new__(cls)
    obj.__setstate__(state)
    return obj


@pytest.mark.parametrize("field, value, message", [
    (1, 0.0, "the resolution must lie in"), (1, math.nan, "the resolution must be finite"), (1, -0.05, "the resolution"),
    (2, (math.nan, 0.0), "the origin must be finite"), (2, (1e10, 0.0), "the origin's x must lie in"),
    (4, math.nan, "the yaw must be finite"), (3, "sideways", "the row order"), (0, np.zeros((2, 2, 2), np.int32), "2-D"),
    (0, np.full((3, 3), -1, np.int32), "negative"), (0, np.zeros((3, 3)), "integers"), (0, np.zeros((0, 3), np.int32), "non-empty"),
    (5, 5, "the rooms has the wrong type"),
])
def test_a_segmentation_state_is_checked_field_by_field(result, field, value, message):
    state = list(result.__getstate__())
    state[field] = value
    with pytest.raises(ValueError, match="^not a topocut.Segmentation state: .*" + message):
        set_state(topocut.Segmentation, tuple(state))


def test_rooms_passages_maps_and_scores_states_are_checked(result):
    room = list(result.rooms[0].__getstate__())
    for field, value in [(0, 0), (1, np.array([[math.nan, 0.0]])), (3, -1.0), (5, (math.inf, 0.0)), (1, np.zeros((3, 3))),
                         (9, "hall"), (9, 1)]:
        bad = list(room)
        bad[field] = value
        with pytest.raises(ValueError, match="^not a topocut.Room state"):
            set_state(topocut.Room, tuple(bad))
    passage = list(result.passages[0].__getstate__())
    for field, value in [(0, -3), (4, math.nan), (5, 1), (6, 99)]:
        bad = list(passage)
        bad[field] = value
        with pytest.raises(ValueError, match="^not a topocut.Passage state"):
            set_state(topocut.Passage, tuple(bad))
    for state in [(np.zeros((2, 2), np.int16), 0.05, (0.0, 0.0, 0.0), ""), (np.full((2, 2), 101, np.int8), 0.05, (0, 0, 0), ""),
                  (np.zeros((2, 2), np.int8), math.nan, (0.0, 0.0, 0.0), ""), (np.zeros((2, 2), np.int8), 0.05, (0.0, 0.0), "")]:
        with pytest.raises(ValueError, match="^not a topocut.Map state"):
            set_state(topocut.Map, state)
    scores = topocut.evaluate(np.asarray(result.labels), np.where(rooms_grid() == 0, 255, 0).astype(np.uint8))
    good = scores.__getstate__()
    for bad in [(good[0], good[1], 2.0, good[3]), ((math.nan,) + good[0][1:], good[1], good[2], good[3]), good[:3]]:
        with pytest.raises(ValueError, match="^not a topocut.Scores state"):
            set_state(topocut.Scores, bad)
    assert set_state(topocut.Scores, good).recall == scores.recall


def test_a_valid_state_round_trips_and_answers(result):
    again = pickle.loads(pickle.dumps(result))
    assert np.array_equal(again.labels, result.labels)
    for room in result.rooms:
        assert again.room_at(*room.inside).id == room.id
    # The extremes a state may hold still answer: nothing is read outside the labels.
    state = list(result.__getstate__())
    state[1], state[2] = 1e-4, (-1e9, 1e9)
    far = set_state(topocut.Segmentation, tuple(state))
    assert far.room_at(0.0, 0.0) is None and far.room_at(1e308, -1e308) is None
    with pytest.raises(ValueError, match="finite"):
        far.room_at(math.nan, 0.0)


def test_the_pickle_round_trip_survives_mutated_states():
    # fuzz/fuzz_pickle.py, bounded by count here (fuzz/run.sh gives it minutes): every mutated state is
    # refused or gives an object whose every method answers. Run in a child so that a crash is a
    # failure with its seed, not the end of the test session.
    code = f"import sys; sys.path.insert(0, {str(FUZZ_DIR)!r}); import fuzz_pickle; print(fuzz_pickle.run(iterations=3000, seed=7))"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, env=env)
    assert done.returncode == 0, done.stderr[-2000:]
    tried, accepted = eval(done.stdout.strip())
    assert tried == 3000 and 0 < accepted < tried  # both kinds were met: the checks check something


def chain_model(trees, depth):
    text = "topocut-merge-model 1\n"
    for _ in range(trees):
        text += "tree\n" + "".join(f"split furniture_end 0.5 {2 * d + 1} {2 * d + 2}\nleaf 0\n" for d in range(depth)) + "leaf 0.1\nend\n"
    return text


def test_merge_models_are_bounded_and_their_options_agree():
    grid = rooms_grid()
    shipped = np.asarray(topocut.segment(grid, 0.05).labels)
    assert np.array_equal(np.asarray(topocut.segment(grid, 0.05, merge_model=None).labels), shipped)
    with pytest.raises(ValueError, match="^merge_model is empty"):
        topocut.segment(grid, 0.05, merge_model="")
    with pytest.raises(ValueError, match="more than 1000 trees"):
        topocut.segment(grid, 0.05, merge_model=chain_model(1001, 0))
    with pytest.raises(ValueError, match="deeper than 12 splits"):
        topocut.segment(grid, 0.05, merge_model=chain_model(1, 13))
    start = time.monotonic()
    with pytest.raises(ValueError, match="more than the limit of 4 MiB"):
        topocut.segment(grid, 0.05, merge_model="#" * (190 << 20))
    assert time.monotonic() - start < 5
    with pytest.raises(ValueError, match="a merge model is given, but learned merging is off"):
        topocut.segment(grid, 0.05, merge_model=chain_model(2, 2), no_learned_merge=True)
    # The incremental segmenter takes the model too (it answered "did you mean merge_model?").
    segmenter = topocut.IncrementalSegmenter(merge_model=chain_model(2, 2))
    assert len(segmenter.update(grid, 0.05).rooms) >= 1
    with pytest.raises(ValueError, match="learned merging is off"):
        topocut.IncrementalSegmenter(merge_model=chain_model(2, 2), no_merge=True)


def test_a_label_image_of_the_wrong_size_is_refused_by_its_header(tmp_path):
    truth = np.where(rooms_grid() == 0, 255, 0).astype(np.uint8)
    labels = tmp_path / "labels.png"
    big = tmp_path / "big.png"
    from PIL import Image
    Image.fromarray(np.zeros((80, 160), np.uint8)).save(labels)
    data = bytearray(labels.read_bytes())
    data[16:24] = (10000).to_bytes(4, "big") * 2  # the header declares 10000 x 10000
    big.write_bytes(bytes(data))
    start = time.monotonic()
    with pytest.raises(ValueError, match=r"is 10000 x 10000 pixels but the ground truth is 160 x 80"):
        topocut.evaluate(str(big), truth)
    with pytest.raises(ValueError, match=r"is 10000 x 10000 pixels but the labels array is 160 x 80"):
        topocut.evaluate(np.zeros((80, 160), np.int32), str(big))
    assert time.monotonic() - start < 2


def number_keywords():
    return [name for name, type_name, _default, _help in topocut._topocut._keywords("segment")
            if type_name in ("float", "int") and name not in ("free_thresh", "occupied_thresh", "free_threshold",
                                                             "occupied_threshold")]


def cli_error(cli, tmp_path, *args):
    grid = np.full((40, 60), 0, np.uint8)
    grid[2:-2, 2:-2] = 255
    path = tmp_path / "map.png"
    if not path.exists():
        from PIL import Image
        Image.fromarray(grid).save(path)
    done = subprocess.run([cli, "segment", str(path), *args], capture_output=True, text=True, timeout=30)
    assert done.returncode == 2, done.stderr
    return done.stderr.strip()


def tail(message, name):
    """The message after the option's name as a front end shows it (--name, 'name' in config ..., name)."""
    at = message.index(name) + len(name)
    return message[at:].split(" (see 'topocut")[0]


def test_every_bad_value_of_the_table_gives_the_commands_message(cli, tmp_path):
    grid = rooms_grid()
    walked = 0
    for name in number_keywords():
        for value, text in [(-1, "-1"), (math.nan, "nan"), (math.inf, "inf"), (1e6, "1e+06"), ("abc", "abc"), (True, "True")]:
            try:
                topocut.segment(grid, 0.05, **{name: value})
                continue  # a value this option takes
            except ValueError as e:
                python = str(e)
            command = cli_error(cli, tmp_path, "--" + name.replace("_", "-") + "=" + text)
            assert python.startswith(name + " "), python
            assert tail(python, name) == tail(command, "--" + name.replace("_", "-")), (python, command)
            walked += 1
    assert walked > 40
    # numpy's numbers and bools are numbers and switches too.
    assert np.array_equal(np.asarray(topocut.segment(grid, 0.05, concavity=np.int64(2), trivial=np.bool_(True)).labels),
                          np.asarray(topocut.segment(grid, 0.05, concavity=2.0, trivial=True).labels))
    # A switch takes True or False, as --config takes YAML's booleans; an option is given once.
    with pytest.raises(ValueError, match="^trivial is a switch: give true or false, not '1'$"):
        topocut.segment(grid, 0.05, trivial=1)
    config = tmp_path / "c.yaml"
    config.write_text("trivial: 1\n")
    assert cli_error(cli, tmp_path, "--config", str(config)).endswith("is a switch: give true or false, not '1' (see 'topocut segment --help')")
    with pytest.raises(ValueError, match="^robot-radius is given twice$"):
        topocut.segment(grid, 0.05, robot_radius=0.1, **{"robot-radius": 0.2})
    assert "is given twice" in cli_error(cli, tmp_path, "--robot-radius", "0.1", "--robot_radius", "0.2")
