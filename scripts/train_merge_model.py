#!/usr/bin/python3
"""Fits topocut's merge model to people's rooms and writes src/segmentation/merge_model.txt.

    /usr/bin/python3 scripts/train_merge_model.py                 # retrain: writes the model file
    /usr/bin/python3 scripts/train_merge_model.py --check         # exit 1 unless the shipped file is what this produces
    /usr/bin/python3 scripts/train_merge_model.py --generalisation  # leave-one-set-out and 5-fold tables

The merge model decides, for two adjacent rooms in the making and the cut between them, whether people
would call them one room (segmentation/merge_model.h; the features are merge_feature_names()). Its rows
come from the library itself (topocut.merge_training_rows): every candidate merge the segmenter weighs on
a map with the library's default options, labelled by the map's ground truth. Merging is greedy (the
most probable merge first, then the probabilities next to the grown room are computed again), so the
rooms it meets depend on its own earlier decisions; the rows are therefore gathered in rounds (DAgger,
Ross et al. 2011): round 1 weighs the first candidates only, each later round merges with the model of
the round before, and every model is fitted on all rounds' rows so far.

The sets (../shared/datasets): Bormann plain and furnished, both annotators of the even sketches, the raw
maps registered onto people's rooms. Each set weighs the same; within a set each map weighs the same,
and each row by the smaller room's area (m²) and by how purely each side lies in one room of people's.
The model: gradient-boosted shallow regression trees (scikit-learn's HistGradientBoostingClassifier,
200 trees of depth 3 at learning rate 0.05, fixed seed, one thread). Deterministic: the same data give the same file, byte
for byte. (Trees of depth 2, and trees constrained to be monotone in the features whose direction looks
clear, scored 0-4 points lower on maps they were not trained on; benchmarks/README.md, "Merge model".)

Needs the Python module built (bash .ci/setup.sh test builds it into build/python), python3-sklearn and
../shared/datasets. Takes a few minutes on 2 cores.
"""
import argparse
import glob
import os
import sys
import zlib

os.environ.setdefault("OMP_NUM_THREADS", "1")  # histogram sums in one order: the same model every time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MODEL_FILE = os.path.join(ROOT, "src", "segmentation", "merge_model.txt")
ROUNDS = 3
SEED = 0
# Trees of depth 3: at most three features interact in a leaf, so a tree still reads at once.
TREES = dict(max_depth=3, max_iter=200, learning_rate=0.05, min_samples_leaf=20, l2_regularization=0.0)
FOLDS = 5  # --generalisation: every map scored by a model fitted without its building or sketch
SKIPPED = 77  # ctest's skip code: --check without the shared data sets
FIRST_ROUND = "topocut-merge-model 1\nthreshold 2\n"  # merges nothing: the first candidates only


def datasets(shared):
    """{set name: [(map image, ground truth)]} from the shared data sets."""
    d = os.path.join(shared, "datasets")
    def pairs(folder, image_suffix=".png"):
        names = sorted(p[: -len("_gt_segmentation.png")] for p in glob.glob(os.path.join(d, folder, "*_gt_segmentation.png")))
        return [(n + image_suffix, n + "_gt_segmentation.png") for n in names]
    sets = {"Bormann plain": pairs("bormann"), "Bormann furnished": pairs("bormann", "_furnitures.png"),
            "sketches (lex)": pairs("sketches/lex"), "sketches (ezvin)": pairs("sketches/ezvin"),
            "raw maps with people's rooms": pairs("real_maps_gt")}
    missing = [s for s, maps in sets.items() if not maps]
    if missing:
        sys.exit(f"train_merge_model: no maps for {', '.join(missing)} under {d}")
    return sets


def rows(topocut, sets, policy):
    """Features, labels and weights of every candidate merge on the sets' maps, merging with policy."""
    names = topocut.merge_feature_names()
    narrow, wide = names.index("log_narrow_area"), names.index("log_wide_area")
    xs, ys, ws = [], [], []
    for maps in sets.values():
        for image, truth in maps:
            x, same, purity, _ = topocut.merge_training_rows(image, truth, merge_model=policy)
            if len(x) == 0:
                continue
            area = np.exp(np.minimum(x[:, narrow], x[:, wide]))
            xs.append(x)
            ys.append(same)
            ws.append(purity * area * 100.0 / len(maps) / len(x))
    return np.vstack(xs), np.concatenate(ys), np.concatenate(ws)


def fit(topocut, x, y, w):
    from sklearn.ensemble import HistGradientBoostingClassifier
    names = topocut.merge_feature_names()
    model = HistGradientBoostingClassifier(random_state=SEED, early_stopping=False, **TREES)
    model.fit(x, y, sample_weight=w)
    return model


def model_text(topocut, model, sets):
    """The model as the library reads it (merge_model.h): bias, then each tree's nodes in order."""
    names = topocut.merge_feature_names()
    lines = ["# topocut's merge model: p(one room) = 1 / (1 + exp(-(bias + the sum of the trees' leaves))).",
             "# Written by scripts/train_merge_model.py (retrain: /usr/bin/python3 scripts/train_merge_model.py);",
             f"# {len(model._predictors)} trees of depth {TREES['max_depth']} fitted in {ROUNDS} rounds on: " + ", ".join(
                 f"{name} ({len(maps)} maps)" for name, maps in sets.items()) + ".",
             "# A split goes to its first node when the feature is at most the threshold.",
             "topocut-merge-model 1", "threshold 0.5", f"bias {float(np.ravel(model._baseline_prediction)[0]):.9g}"]
    for predictor in model._predictors:
        lines.append("tree")
        for node in predictor[0].nodes:
            if node["is_leaf"]:
                lines.append(f"leaf {node['value']:.9g}")
            else:
                lines.append(f"split {names[node['feature_idx']]} {node['num_threshold']:.9g} {node['left']} {node['right']}")
        lines.append("end")
    return "\n".join(lines) + "\n"


def train(topocut, sets, progress=print):
    """The model text after ROUNDS rounds of gathering rows and fitting."""
    policy, xs, ys, ws = FIRST_ROUND, [], [], []
    for r in range(ROUNDS):
        x, y, w = rows(topocut, sets, policy)
        xs.append(x), ys.append(y), ws.append(w)
        model = fit(topocut, np.vstack(xs), np.concatenate(ys), np.concatenate(ws))
        policy = model_text(topocut, model, sets)
        progress(f"round {r + 1} of {ROUNDS}: {sum(len(v) for v in ys)} rows")
    return policy


def scores(topocut, sets, model):
    """Mean matched-room F1 (%) of each set's maps segmented with model, as `topocut evaluate` scores."""
    out = {}
    for name, maps in sets.items():
        f1 = []
        for image, truth in maps:
            m = topocut.load_map(image)
            labels = np.flipud(np.asarray(topocut.segment(m.grid, m.resolution, m.origin, merge_model=model).labels))
            f1.append(topocut.evaluate(labels, truth, free=image, clip_to_free=False).f1)
        out[name] = 100.0 * float(np.mean(f1))
    return out


def folds(sets, fold):
    """The maps of one of FOLDS folds of every set; a building or sketch falls into the same fold in
    every set (its plain and furnished images, both annotators' rooms)."""
    def key(image):
        return zlib.crc32(os.path.basename(image).replace("_furnitures", "").encode()) % FOLDS
    return {name: [m for m in maps if key(m[0]) == fold] for name, maps in sets.items()}


def generalisation(topocut, sets):
    """Matched-room F1 per set: trained on every set; trained on the other sets only (leave one set
    out); and on maps whose building or sketch was not trained on (FOLDS folds)."""
    quiet = lambda s: print("train_merge_model: " + s, file=sys.stderr)
    full = scores(topocut, sets, train(topocut, sets, quiet))
    others = {}
    for name in sets:
        rest = {k: v for k, v in sets.items() if k != name}
        others.update(scores(topocut, {name: sets[name]}, train(topocut, rest, quiet)))
    unseen = {name: [] for name in sets}
    for fold in range(FOLDS):
        trained = {name: [m for f in range(FOLDS) if f != fold for m in folds(sets, f)[name]] for name in sets}
        held = {name: maps for name, maps in folds(sets, fold).items() if maps}
        for name, f1 in scores(topocut, held, train(topocut, trained, quiet)).items():
            unseen[name].append((f1, len(held[name])))
    print(f"| set | trained on every set | trained on the other sets | on maps not trained on ({FOLDS} folds) |")
    print("|---|---|---|---|")
    for name in sets:
        fold_f1 = sum(f * n for f, n in unseen[name]) / max(1, sum(n for _, n in unseen[name]))
        print(f"| {name} | {full[name]:.1f} | {others[name]:.1f} ({others[name] - full[name]:+.1f}) | "
              f"{fold_f1:.1f} ({fold_f1 - full[name]:+.1f}) |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="the build folder holding python/topocut")
    parser.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"), help="the folder holding datasets/")
    parser.add_argument("--out", default=MODEL_FILE, help="where to write the model")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 unless --out equals what training produces (77: no data sets to train on)")
    parser.add_argument("--generalisation", action="store_true", help="print the leave-one-set-out table")
    args = parser.parse_args()
    if not os.path.isdir(os.path.join(args.shared, "datasets")):
        print(f"train_merge_model: skipped: no {os.path.join(args.shared, 'datasets')} to train on", file=sys.stderr)
        return SKIPPED if args.check else 1
    sys.path.insert(0, os.path.join(args.build, "python"))
    import topocut
    sets = datasets(args.shared)
    if args.generalisation:
        generalisation(topocut, sets)
        return 0
    text = train(topocut, sets, progress=lambda s: print("train_merge_model: " + s, file=sys.stderr))
    if args.check:
        with open(args.out) as f:
            shipped = f.read()
        if shipped != text:
            print(f"train_merge_model: {args.out} is not what training produces; retrain with "
                  "/usr/bin/python3 scripts/train_merge_model.py", file=sys.stderr)
            return 1
        print(f"train_merge_model: {args.out} is what training produces")
        return 0
    with open(args.out, "w") as f:
        f.write(text)
    print(f"train_merge_model: wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
