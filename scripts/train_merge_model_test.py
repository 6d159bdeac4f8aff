#!/usr/bin/python3
"""Checks scripts/train_merge_model.py's bag on planted rows, without the library: the one model file
written for a bag of models gives, read node by node as the library reads it (merge_model.h: the first
node when the feature is at most the threshold, the margin the sum of the leaves), the mean of the
members' own margins; and the bootstrap samples keep each set's size, differ between members and are
the same for the same seed, while seed 0 of a single model draws every map once and is written as
before (its header's lines comments); --segment-option's NAME=VALUE is read as topocut.segment's keyword
and named in the header of a model fitted with it."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np

import train_merge_model as tm

NAMES = ["f0", "f1", "f2"]


class Library:
    """What model_text() asks of the library."""

    @staticmethod
    def merge_feature_names():
        return NAMES


def expect(condition, message):
    if not condition:
        print("FAILED: " + message)
        sys.exit(1)


def margins(text, x):
    """Each row's bias + sum of the trees' leaves, walking the file's nodes as the library does."""
    trees, bias = [], 0.0
    for line in text.splitlines():
        words = line.split("#")[0].split()
        if not words:
            continue
        if words[0] == "bias":
            bias = float(words[1])
        elif words[0] == "tree":
            trees.append([])
        elif words[0] in ("leaf", "split"):
            trees[-1].append(words)
    out = np.full(len(x), bias)
    for r, row in enumerate(x):
        for tree in trees:
            node = tree[0]
            while node[0] == "split":
                node = tree[int(node[3]) if row[NAMES.index(node[1])] <= float(node[2]) else int(node[4])]
            out[r] += float(node[1])
    return out


def main():
    import xgboost
    rng = np.random.default_rng(7)
    x = rng.normal(size=(400, 3)).astype(np.float32).astype(float)
    y = (x[:, 0] + 0.5 * x[:, 1] * x[:, 2] + rng.normal(scale=0.5, size=400) > 0).astype(int)
    w = rng.uniform(0.5, 1.5, size=(400, 3)) * (rng.uniform(size=(400, 3)) > 0.3)
    tm.TREES.update(n_estimators=20, max_depth=3, learning_rate=0.3)
    members = tm.fit(x, y, w, workers=2)
    text = tm.model_text(Library, members, {}, len(x), seed=5)
    expected = []
    for member in range(3):
        keep = w[:, member] > 0
        model = xgboost.XGBClassifier(tree_method="hist", n_jobs=1, random_state=tm.SEED, base_score=0.5, **tm.TREES)
        model.fit(x[keep], y[keep], sample_weight=w[keep, member] / w[keep, member].mean())
        expected.append(model.predict(x, output_margin=True))
    got = margins(text, x)
    mean = np.mean(expected, axis=0)
    expect(text.count("\ntree\n") == 60, f"a bag of 3 models of 20 trees is one file of 60 trees, not {text.count(chr(10) + 'tree' + chr(10))}")
    expect(np.max(np.abs(got - mean)) < 1e-4, f"the file's margin is the members' mean (largest difference {np.max(np.abs(got - mean)):.2g})")
    expect(np.max(np.abs(expected[0] - expected[1])) > 0.1, "members fitted on different samples differ")

    single = tm.model_text(Library, members[:1], {}, len(x), seed=0)
    head = single.split("topocut-merge-model 1")[0].splitlines()
    expect(all(line.startswith("# ") for line in head), "every line above the model's first line is a comment")
    expect(any(line.startswith("# 20 trees of depth 3, ") for line in head), "a single model's header says its trees as before")
    expect(np.max(np.abs(margins(single, x) - expected[0])) < 1e-4, "a single model's file is its margin")

    sets = {"a": [("m", "t")] * 10, "b": [("m", "t")] * 3}
    once = tm.draws(sets, 0, 1)
    expect(all((d == 1).all() for d in once.values()), "seed 0 of a single model draws every map once")
    drawn, again, other = tm.draws(sets, 3, 4), tm.draws(sets, 3, 4), tm.draws(sets, 4, 4)
    expect(all(drawn[s].shape == (4, len(sets[s])) and (drawn[s].sum(axis=1) == len(sets[s])).all() for s in sets),
           "every member draws as many maps as each set holds")
    expect(not (drawn["a"][0] == drawn["a"][1]).all(), "members draw different samples")
    expect(all((drawn[s] == again[s]).all() for s in sets), "the same seed draws the same samples")
    expect(not all((drawn[s] == other[s]).all() for s in sets), "another seed draws other samples")
    import argparse
    expect(tm.segment_option("oversegment=0.3") == ("oversegment", 0.3), "NAME=VALUE reads a number")
    expect(tm.segment_option("--no-bays=true") == ("no_bays", True), "a command-line name and true read as a switch")
    expect(tm.segment_option("corridor-openings=4") == ("corridor_openings", 4), "a whole number stays whole")
    for bad in ("oversegment", "=0.3", "oversegment=", "oversegment=small"):
        try:
            tm.segment_option(bad)
            expect(False, f"'{bad}' is refused")
        except argparse.ArgumentTypeError:
            pass
    expect(not any("segment options" in line for line in head), "a model fitted with the defaults names no options")
    tm.SEGMENT_OPTIONS.update([("oversegment", 0.3), ("no_bays", True)])
    with_options = tm.model_text(Library, members[:1], {}, len(x), seed=0)
    tm.SEGMENT_OPTIONS.clear()
    expect("# Fitted with the segment options --oversegment 0.3 --no-bays: give them to topocut with this model.\n"
           in with_options.split("topocut-merge-model 1")[0], "a model fitted with options names them in its header")
    expect(with_options.split("topocut-merge-model 1")[1] == single.split("topocut-merge-model 1")[1],
           "the options change the header only")
    print("train_merge_model_test: passed")


if __name__ == "__main__":
    main()
