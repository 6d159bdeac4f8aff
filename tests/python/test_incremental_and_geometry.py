# IncrementalSegmenter keeps ids; decompose() cuts a notched polygon; the extractors find the walls
# of a noiseless room.
import math

import numpy as np
import pytest

import topocut


def floor_plan():
    """ROS int8 grid (row 0 at the bottom): a corridor along the bottom, three rooms above it, each
    behind a 0.9 m door."""
    world = np.full((120, 200), 100, dtype=np.int8)
    world[4:36, 4:196] = 0  # corridor
    rooms = []
    for i in range(3):
        x = 4 + 64 * i
        world[40:116, x : x + 60] = 0
        world[36:40, x + 21 : x + 39] = 0  # door
        rooms.append((slice(40, 116), slice(x, x + 60)))
    return world, rooms


def reveal(world, parts):
    grid = np.full(world.shape, -1, dtype=np.int8)
    for rows, cols in parts:
        rows = slice(max(rows.start - 4, 0), rows.stop + 4)
        cols = slice(max(cols.start - 4, 0), cols.stop + 4)
        grid[rows, cols] = world[rows, cols]
    return grid


def test_incremental_loop_keeps_ids():
    world, rooms = floor_plan()
    corridor = (slice(4, 36), slice(4, 196))
    seg = topocut.IncrementalSegmenter()
    first = seg.update(reveal(world, [corridor, rooms[0]]), 0.05)
    assert seg.last_update == "batch"
    room0 = first.labels[78, 30]
    assert room0 > 0
    cells0 = first.labels == room0
    ids = [room0]
    for k in (1, 2):
        result = seg.update(reveal(world, [corridor] + rooms[: k + 1]), 0.05)
        assert seg.last_update in ("incremental", "batch")
        # The first room was not touched by the change: same id, same cells.
        assert result.labels[78, 30] == room0
        assert np.array_equal(result.labels == room0, cells0)
        new_id = result.labels[78, 4 + 64 * k + 30]
        assert new_id > 0 and new_id not in ids
        ids.append(new_id)
    assert seg.update(reveal(world, [corridor] + rooms), 0.05).labels[78, 30] == room0
    assert seg.last_update == "unchanged"


def same_partition(a, b):
    """Whether label images a and b are one partition of the same cells (equal under a renaming)."""
    if not np.array_equal(a > 0, b > 0):
        return False
    pairs = set(zip(a[a > 0].tolist(), b[b > 0].tolist()))
    return len(pairs) == len({p[0] for p in pairs}) == len({p[1] for p in pairs})


def test_incremental_is_batch_on_a_map_given_at_once_and_at_rest():
    world, rooms = floor_plan()
    corridor = (slice(4, 36), slice(4, 196))
    seg = topocut.IncrementalSegmenter()
    with pytest.raises(ValueError):
        seg.resegment()
    assert np.array_equal(seg.update(world, 0.05).labels, topocut.segment(world, 0.05).labels)
    grown = topocut.IncrementalSegmenter()
    for k in range(3):
        last = reveal(world, [corridor] + rooms[: k + 1])
        windowed = grown.update(last, 0.05)
    rest = grown.resegment()
    assert grown.last_update == "batch"
    assert same_partition(rest.labels, topocut.segment(last, 0.05).labels)
    # Rooms the windowed updates found keep their ids where they keep most of their cells.
    assert rest.labels[78, 30] == windowed.labels[78, 30]


def test_saved_ledger_keeps_ids_across_a_restart(tmp_path):
    world, rooms = floor_plan()
    corridor = (slice(4, 36), slice(4, 196))
    seg = topocut.IncrementalSegmenter()
    with pytest.raises(ValueError):
        seg.save_ledger(str(tmp_path / "none.txt"))  # nothing segmented yet
    for parts in ([corridor, rooms[2]], [corridor] + rooms):  # the right room seen first
        live = seg.update(reveal(world, parts), 0.05)
    path = str(tmp_path / "ids.txt")
    seg.save_ledger(path)
    fresh = topocut.IncrementalSegmenter().update(world, 0.05)
    assert not np.array_equal(fresh.labels, live.labels)  # a fresh start numbers the rooms otherwise
    restarted = topocut.IncrementalSegmenter()
    restarted.load_ledger(path)
    assert np.array_equal(restarted.update(world, 0.05).labels, live.labels)
    with open(path, "w") as f:
        f.write("topocut-id-ledger 1\nnext_id -3\n")
    with pytest.raises(ValueError, match="next_id"):
        restarted.load_ledger(path)
    with pytest.raises(ValueError):
        restarted.load_ledger(str(tmp_path / "missing.txt"))


def test_incremental_speck_and_split_options():
    world, rooms = floor_plan()
    seg = topocut.IncrementalSegmenter(speck_size=0.5, split_after=2, merge_after=2, neighbours_across_cuts=False)
    first = seg.update(world, 0.05)
    chair = world.copy()
    chair[70:73, 30:33] = 100  # a 0.15 m obstacle inside room 0: a speck
    second = seg.update(chair, 0.05)
    assert (second.labels[70:73, 30:33] == 0).all()
    outside = np.ones(world.shape, dtype=bool)
    outside[70:73, 30:33] = False
    assert np.array_equal(second.labels[outside], first.labels[outside])
    with pytest.raises(ValueError):
        topocut.IncrementalSegmenter(split_after=0)
    with pytest.raises(ValueError):
        topocut.IncrementalSegmenter(merge_after=0)
    with pytest.raises(ValueError):
        topocut.IncrementalSegmenter(speck_size=-1.0)


def test_decompose_cuts_a_notched_square():
    # A 10 x 10 square with a 6-deep notch from the top: deeper than tau = 1, so it is cut.
    outer = [[0, 0], [10, 0], [10, 10], [6, 10], [6, 4], [4, 4], [4, 10], [0, 10]]
    d = topocut.decompose(np.array(outer, dtype=float), tau=1.0)
    assert len(d["pieces"]) >= 2
    assert sum(p["area"] for p in d["pieces"]) == pytest.approx(100 - 12)
    whole = topocut.decompose(outer, tau=20.0)
    assert len(whole["pieces"]) == 1


def room_scan(x=1.0, y=1.2, width=4.0, depth=3.0, beams=720):
    """Noiseless ranges from (x, y) inside the rectangle [0, width] x [0, depth]."""
    angles = np.linspace(-math.pi, math.pi, beams, endpoint=False) + 1e-3
    ranges = []
    for a in angles:
        c, s = math.cos(a), math.sin(a)
        hits = []
        if c > 0:
            hits.append((width - x) / c)
        if c < 0:
            hits.append(-x / c)
        if s > 0:
            hits.append((depth - y) / s)
        if s < 0:
            hits.append(-y / s)
        ranges.append(min(hits))
    walls = [(width - x, 0.0), (x, math.pi), (depth - y, math.pi / 2), (y, -math.pi / 2)]  # (rho, alpha)
    return angles, np.array(ranges), walls


def angle_gap(a, b):
    return abs((a - b + math.pi) % (2 * math.pi) - math.pi)


@pytest.mark.parametrize("method", ["sef", "lt", "iepf", "smf", "ale"])
def test_extractors_recover_the_walls_of_a_room(method):
    angles, ranges, walls = room_scan()
    lines = getattr(topocut, method)(angles, ranges)
    assert [l["rho"] for l in lines] == [l["rho"] for l in topocut.extract_lines(angles, ranges, method=method)]
    for rho, alpha in walls:
        assert any(abs(l["rho"] - rho) < 0.02 and angle_gap(l["alpha"], alpha) < 0.02 for l in lines), (method, rho, alpha, lines)
    for l in lines:
        if len(l["support"]) >= 10:
            assert any(abs(l["rho"] - rho) < 0.02 and angle_gap(l["alpha"], alpha) < 0.02 for rho, alpha in walls), (method, l)
