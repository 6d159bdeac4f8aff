# Thread safety (issue 28): an IncrementalSegmenter shared by many threads takes their calls in
# turn (it crashed the interpreter with two threads and different grid shapes); unshared segmenters
# and segment() run in parallel and give the results a single thread gives; results are read-only
# and may be shared.
import threading

import numpy as np

import topocut


def plan(rooms, width=40):
    """ROS int8 grid: a corridor along the bottom and `rooms` rooms above it, each behind a door."""
    grid = np.full((70, 8 + rooms * (width + 4)), 100, dtype=np.int8)
    grid[4:20, 4:-4] = 0
    for i in range(rooms):
        x = 4 + i * (width + 4)
        grid[24:66, x : x + width] = 0
        grid[20:24, x + 14 : x + 26] = 0
    return grid


GRIDS = [plan(k) for k in (1, 2, 3, 2, 4, 1)]  # shapes change from update to update


def run_threads(target, count):
    errors = []

    def guarded(i):
        try:
            target(i)
        except BaseException as e:  # noqa: BLE001 - reported below
            errors.append(repr(e))

    threads = [threading.Thread(target=guarded, args=(i,)) for i in range(count)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []


def valid(result, grid):
    labels = result.labels
    assert labels.shape == grid.shape
    ids = {room.id for room in result.rooms}
    assert set(np.unique(labels)) <= ids | {0}
    assert ((labels > 0) <= (grid == 0)).all()  # rooms only on free cells


def test_a_shared_segmenter_takes_calls_in_turn():
    shared = topocut.IncrementalSegmenter()

    def work(i):
        for k in range(6):
            grid = GRIDS[(i + k) % len(GRIDS)]
            valid(shared.update(grid, 0.05), grid)
            assert shared.last_update in ("unchanged", "incremental", "batch")
            if (i + k) % 5 == 0:
                shared.reset()

    run_threads(work, 12)
    # Still usable, and as a fresh segmenter after reset().
    shared.reset()
    assert np.array_equal(shared.update(GRIDS[2], 0.05).labels, topocut.IncrementalSegmenter().update(GRIDS[2], 0.05).labels)


def test_unshared_segmenters_and_segment_give_the_single_thread_results():
    def sequence():
        seg = topocut.IncrementalSegmenter()
        return [seg.update(g, 0.05).labels.copy() for g in GRIDS]

    expected_sequence = sequence()
    expected_batch = [topocut.segment(g, 0.05).labels.copy() for g in GRIDS]
    results = {}

    def work(i):
        if i % 2:
            results[i] = sequence()
        else:
            results[i] = [topocut.segment(g, 0.05).labels.copy() for g in GRIDS]

    run_threads(work, 10)
    for i, got in results.items():
        expected = expected_batch if i % 2 == 0 else expected_sequence
        assert all(np.array_equal(a, b) for a, b in zip(got, expected)), i


def test_results_are_read_only_and_shared():
    result = topocut.segment(GRIDS[4], 0.05)
    reference = (result.labels.copy(), [r.area for r in result.rooms], result.to_json())

    def work(i):
        for _ in range(20):
            assert np.array_equal(result.labels, reference[0])
            assert [r.area for r in result.rooms] == reference[1]
            assert result.to_json() == reference[2]

    run_threads(work, 8)
    assert not result.labels.flags.writeable

