#!/usr/bin/python3
"""Fuzzes the pickle round trip of every topocut result type: states of real results, mutated (a
field replaced by a number out of range, NaN, a wrong type, an array of another shape or dtype,
fields dropped or repeated), given to __setstate__. Each must raise ValueError or TypeError, or give
an object whose every property and method answers (room_at at points on and off the grid, to_json,
pickling again). A crash ends the process, which is the finding.

    PYTHONPATH=build/python /usr/bin/python3 fuzz/fuzz_pickle.py SECONDS [SEED]

tests/python/test_state_and_options.py runs it for a bounded count; fuzz/run.sh for SECONDS.
"""
import math
import pickle
import random
import sys
import time
import warnings

import numpy as np

import topocut

ODD_VALUES = [0, -1, 1, 2**31, -2**31 - 1, 2**63, 1e308, -1e308, 1e-320, math.nan, math.inf, -math.inf, True, None,
              "", "bottom-up", "x" * 1000, (), [], {}, (1.0,), (math.nan, 0.0), (0.0, 0.0, 0.0)]


def odd_array(rng):
    shape = rng.choice([(0,), (0, 2), (3,), (2, 2), (1, 1), (3, 5), (2, 2, 2), (1, 70000), (4, 2)])
    dtype = rng.choice([np.int8, np.int32, np.int64, np.uint16, np.float64, np.bool_, object])
    a = np.zeros(shape, dtype=dtype)
    if a.size and dtype is not object:
        flat = a.reshape(-1)
        for i in range(min(flat.size, 8)):
            flat[rng.randrange(flat.size)] = rng.choice([-1, 0, 1, 100, 127]) if dtype != np.float64 else rng.choice(
                [math.nan, -1.0, 1e300, 0.5])
    return a


def odd_value(rng):
    return odd_array(rng) if rng.random() < 0.3 else rng.choice(ODD_VALUES)


def mutate(state, rng, depth=0):
    """state with one part changed (recursively into tuples, lists and arrays)."""
    if isinstance(state, (tuple, list)) and state and depth < 6 and rng.random() < 0.8:
        items = list(state)
        i = rng.randrange(len(items))
        roll = rng.random()
        if roll < 0.1:
            del items[i]
        elif roll < 0.15:
            items.insert(i, items[i])
        elif roll < 0.2:
            j = rng.randrange(len(items))
            items[i], items[j] = items[j], items[i]
        else:
            items[i] = mutate(items[i], rng, depth + 1)
        return tuple(items) if isinstance(state, tuple) else items
    if isinstance(state, np.ndarray) and state.size and rng.random() < 0.7:
        a = state.copy()
        flat = a.reshape(-1)
        value = rng.choice([-1, -2**31, 2**31 - 1, 0, 101, 127, -128]) if a.dtype.kind in "iu" else rng.choice(
            [math.nan, math.inf, -1e308, 0.0])
        try:
            flat[rng.randrange(flat.size)] = value
        except (OverflowError, ValueError):
            pass
        return a
    return odd_value(rng)


def results():
    """Real results of every type, from a small map with rooms, passages and holes."""
    grid = np.full((80, 160), 100, np.int8)  # two rooms, a door, a pillar
    grid[2:-2, 2:-2] = 0
    grid[2:-2, 80] = 100
    grid[30:46, 80] = 0
    grid[10:14, 20:24] = 100
    s = topocut.segment(grid, 0.05, (1.0, -2.0, 0.3))
    m = topocut.Map.__new__(topocut.Map)
    m.__setstate__((grid, 0.05, (1.0, -2.0, 0.3), "test"))
    labels = np.asarray(s.labels)
    truth = np.where(grid == 0, 255, 0).astype(np.uint8)
    scores = topocut.evaluate(labels, truth)
    return [s, m, scores] + list(s.rooms) + list(s.passages)


def exercise(obj, rng):
    """Every property and method of obj: must answer or raise ValueError, never crash."""
    for name in dir(obj):
        if name.startswith("__"):
            continue
        value = getattr(obj, name)
        if callable(value) and name == "room_at":
            for x, y in [(0.0, 0.0), (1.1, -1.9), (1e308, -1e308), (rng.uniform(-5, 10), rng.uniform(-5, 10))]:
                value(x, y)
            try:
                value(math.nan, 0.0)
            except ValueError:
                pass
        elif callable(value) and name in ("to_json", "to_geojson"):
            value()
        elif isinstance(value, np.ndarray):
            value.sum()
    repr(obj)
    pickle.loads(pickle.dumps(obj))


def fuzz_once(base, rng):
    cls = type(base)
    state = base.__getstate__()
    for _ in range(rng.randint(1, 3)):
        state = mutate(state, rng)
    obj = cls.__new__(cls)
    try:
        obj.__setstate__(state)
    except (ValueError, TypeError):
        return False
    exercise(obj, rng)
    return True


def run(seconds=None, iterations=None, seed=0):
    """Fuzzes until seconds pass or iterations are done; returns (tried, accepted)."""
    rng = random.Random(seed)
    warnings.simplefilter("ignore")  # numpy's overflow warnings about the mutated values themselves
    bases = results()
    end = time.monotonic() + seconds if seconds is not None else math.inf
    tried = accepted = 0
    while time.monotonic() < end and (iterations is None or tried < iterations):
        accepted += fuzz_once(rng.choice(bases), rng)
        tried += 1
    return tried, accepted


if __name__ == "__main__":
    seconds = float(sys.argv[1]) if len(sys.argv) > 1 else 10.0
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else int(time.time())
    tried, accepted = run(seconds=seconds, seed=seed)
    print(f"fuzz_pickle: seed {seed}, {tried} mutated states, {accepted} accepted and exercised, "
          f"{tried - accepted} refused; no crash")
