#!/usr/bin/python3
"""Fits topocut's merge model to people's rooms and writes src/segmentation/merging/merge_model.txt.

    /usr/bin/python3 scripts/train_merge_model.py                 # retrain: writes the model file
    /usr/bin/python3 scripts/train_merge_model.py --check         # exit 1 unless the shipped file is what this produces
    /usr/bin/python3 scripts/train_merge_model.py --generalisation  # leave-one-kind-out and 5-fold tables
    /usr/bin/python3 scripts/train_merge_model.py --generalisation --folds 0 --every 5  # a quicker check (minutes)

The merge model decides, for two adjacent rooms in the making and the cut between them, whether people
would call them one room (segmentation/merge_model.h; the features are merge_feature_names(), all of
them measurements, none a rule's decision; the lengths are in the component's own scale, its typical
piece's thickness and cut's length, so that a kind never fitted on is judged by its own sizes). Its rows come from the library itself
(topocut.merge_training_rows): every candidate merge the segmenter weighs on a map with the library's
default options, labelled by the map's ground truth. Merging is greedy (the most probable merge first,
then the probabilities next to the grown room are computed again), so the rooms it meets depend on its
own earlier decisions; the rows are therefore gathered in rounds (DAgger, Ross et al. 2011): round 1
weighs the first candidates only, each later round merges with the model of the round before, and every
model is fitted on all rounds' rows so far.

The maps, of every kind users bring (../shared/datasets): office plans (Bormann plain and furnished),
homes (r2v's residential plans), hand-drawn sketches (both annotators), raw SLAM maps registered onto
people's rooms, and robot-made maps that `topocut simulate-map` makes of the plans of the first three
kinds (a simulated lidar exploring the plan; people's rooms carried over). Each kind weighs the same,
each set within its kind, each map within its set and each candidate within its map (times how purely
each side lies in one room of people's): a small room lost costs a matched room as a large one does.
The model: gradient-boosted trees of depth 5 (XGBoost, 300 trees at learning rate 0.05, histogram
splits, one thread, fixed seed), written from XGBoost's public JSON dump of its trees. Deterministic:
the same data and library versions give the same file, byte for byte; the file's header records the
sets, their sizes and the versions.

Needs the Python module and the topocut command built (bash .ci/setup.sh test builds both into build/),
python3-xgboost and ../shared/datasets. Takes a few minutes on 2 cores (--generalisation: about
ten trainings more).
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import zlib
from concurrent.futures import ProcessPoolExecutor

os.environ.setdefault("OMP_NUM_THREADS", "1")  # sums in one order: the same model every time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MODEL_FILE = os.path.join(ROOT, "src", "segmentation", "merging", "merge_model.txt")
ROUNDS = 3
SEED = 0
RESOLUTION = 0.05  # metres a cell: the Bormann-layout images hold no scale (merge_training_rows's default too)
TREES = dict(n_estimators=300, max_depth=5, learning_rate=0.05, max_bin=256)
FOLDS = 5  # --generalisation's default: every map scored by a model fitted without its building, plan or sketch
SKIPPED = 77  # ctest's skip code: --check without the shared data sets
FIRST_ROUND = "topocut-merge-model 1\nthreshold 2\n"  # merges nothing: the first candidates only
# Robot-made maps: (set name, plans' folder under datasets/, seeds per plan).
ROBOT_SETS = [("robot-made homes", "r2v", 1), ("robot-made offices", "bormann", 2),
              ("robot-made sketches (lex)", "sketches/lex", 2), ("robot-made sketches (ezvin)", "sketches/ezvin", 2)]
# The kinds of map, each weighing the same, and the plans' kind of each robot-made set.
KINDS = {"office plans": ["Bormann plain", "Bormann furnished"], "homes": ["homes (r2v)"],
         "sketches": ["sketches (lex)", "sketches (ezvin)"], "raw real maps": ["raw maps with people's rooms"],
         "robot-made": [name for name, _, _ in ROBOT_SETS]}
PLAN_KIND = {"robot-made homes": "homes", "robot-made offices": "office plans",
             "robot-made sketches (lex)": "sketches", "robot-made sketches (ezvin)": "sketches"}


def pairs(folder, image_suffix=".png"):
    """[(map image, ground truth)] of a Bormann-layout folder."""
    names = sorted(p[: -len("_gt_segmentation.png")] for p in glob.glob(os.path.join(folder, "*_gt_segmentation.png")))
    return [(n + image_suffix, n + "_gt_segmentation.png") for n in names if os.path.exists(n + image_suffix)]


def robot_made(topocut_command, datasets, folder, progress):
    """Makes the robot-made maps of ROBOT_SETS into folder (kept: the command is deterministic per seed, so a
    folder made before by the same command holds the same maps); {set name: [(image, ground truth)]}."""
    out = {}
    for name, plans, seeds in ROBOT_SETS:
        target = os.path.join(folder, plans.replace("/", "_"))
        expected = len(pairs(os.path.join(datasets, plans))) * seeds
        if len(pairs(target)) != expected:
            progress(f"making the robot-made maps of {plans} ({seeds} seed{'s' if seeds > 1 else ''} a plan) in {target}")
            made = subprocess.run([topocut_command, "simulate-map", "--dataset", os.path.join(datasets, plans), "--seeds",
                                   str(seeds), "--out", target], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            if made.returncode != 0:
                sys.exit(f"train_merge_model: {topocut_command} simulate-map failed: " + made.stderr.strip().splitlines()[-1])
        out[name] = pairs(target)
    return out


def datasets(shared, topocut_command, robot_folder, progress):
    """{set name: [(map image, ground truth)]} of every set of KINDS."""
    d = os.path.join(shared, "datasets")
    sets = {"Bormann plain": pairs(os.path.join(d, "bormann")),
            "Bormann furnished": pairs(os.path.join(d, "bormann"), "_furnitures.png"),
            "homes (r2v)": pairs(os.path.join(d, "r2v")),
            "sketches (lex)": pairs(os.path.join(d, "sketches/lex")), "sketches (ezvin)": pairs(os.path.join(d, "sketches/ezvin")),
            "raw maps with people's rooms": pairs(os.path.join(d, "real_maps_gt"))}
    missing = [s for s, maps in sets.items() if not maps]
    if missing:
        sys.exit(f"train_merge_model: no maps for {', '.join(missing)} under {d}")
    sets.update(robot_made(topocut_command, d, robot_folder, progress))
    return sets


def kind_of(set_name):
    return next(kind for kind, names in KINDS.items() if set_name in names)


def _rows_of_map(job):
    import topocut
    image, truth, policy = job
    x, same, purity, _ = topocut.merge_training_rows(image, truth, merge_model=policy)
    return x, same, purity


def rows(sets, policy, workers):
    """Features, labels and weights of every candidate merge on the sets' maps, merging with policy."""
    jobs, share = [], []
    kinds = {kind_of(s) for s in sets}
    for name, maps in sets.items():
        in_kind = sum(1 for s in sets if kind_of(s) == kind_of(name))
        for image, truth in maps:
            jobs.append((image, truth, policy))
            share.append(1.0 / len(kinds) / in_kind / len(maps))
    with ProcessPoolExecutor(workers) as pool:
        found = list(pool.map(_rows_of_map, jobs, chunksize=4))
    xs, ys, ws = [], [], []
    for (x, same, purity), map_share in zip(found, share):
        if len(x) == 0:
            continue
        xs.append(x)
        ys.append(same)
        ws.append(purity * map_share / len(x))
    return np.vstack(xs), np.concatenate(ys), np.concatenate(ws)


def fit(x, y, w):
    import xgboost
    model = xgboost.XGBClassifier(tree_method="hist", n_jobs=1, random_state=SEED, base_score=0.5, **TREES)
    model.fit(x, y, sample_weight=w / w.mean())
    return model


def tree_lines(tree, names):
    """One tree of XGBoost's JSON dump in the model file's form: nodes in preorder (a split's nodes come after
    it). XGBoost sends x < t to its first child, the file x <= threshold: the threshold is the float below t
    (XGBoost compares in single precision)."""
    order = []
    stack = [tree]
    while stack:
        node = stack.pop()
        order.append(node)
        stack.extend(reversed(node.get("children", [])))
    at = {node["nodeid"]: i for i, node in enumerate(order)}
    lines = ["tree"]
    for node in order:
        if "leaf" in node:
            lines.append(f"leaf {node['leaf']:.9g}")
        else:
            threshold = float(np.nextafter(np.float32(node["split_condition"]), np.float32(-np.inf)))
            lines.append(f"split {names[int(node['split'][1:])]} {threshold:.9g} {at[node['yes']]} {at[node['no']]}")
    lines.append("end")
    return lines


def model_text(topocut, model, sets, row_count):
    """The model as the library reads it (merge_model.h): a header saying what it was fitted on, then each
    tree's nodes in order."""
    import xgboost
    names = topocut.merge_feature_names()
    fitted_on = "; ".join(f"{kind}: " + ", ".join(f"{s} ({len(sets[s])} maps)" for s in KINDS[kind] if s in sets)
                          for kind in KINDS if any(s in sets for s in KINDS[kind]))
    lines = ["# topocut's merge model: p(one room) = 1 / (1 + exp(-(bias + the sum of the trees' leaves))).",
             "# Written by scripts/train_merge_model.py (retrain: /usr/bin/python3 scripts/train_merge_model.py).",
             f"# {TREES['n_estimators']} trees of depth {TREES['max_depth']}, {ROUNDS} rounds, {row_count} candidate merges, "
             f"fitted on {fitted_on}.",
             f"# XGBoost {xgboost.__version__}, NumPy {np.__version__}.",
             "# A split goes to its first node when the feature is at most the threshold.",
             "topocut-merge-model 1", "threshold 0.5", "bias 0"]
    for dump in model.get_booster().get_dump(dump_format="json"):
        lines += tree_lines(json.loads(dump), names)
    return "\n".join(lines) + "\n"


def train(topocut, sets, workers, progress=print):
    """The model text after ROUNDS rounds of gathering rows and fitting."""
    policy, xs, ys, ws = FIRST_ROUND, [], [], []
    for r in range(ROUNDS):
        x, y, w = rows(sets, policy, workers)
        xs.append(x), ys.append(y), ws.append(w)
        count = sum(len(v) for v in ys)
        policy = model_text(topocut, fit(np.vstack(xs), np.concatenate(ys), np.concatenate(ws)), sets, count)
        progress(f"round {r + 1} of {ROUNDS}: {count} rows")
    return policy


def _f1_of_map(job):
    import topocut
    image, truth, model = job
    m = topocut.load_map(image, resolution=RESOLUTION)
    result = topocut.segment(m.grid, m.resolution, m.origin, merge_model=model)
    return topocut.evaluate(result, truth, free=image, clip_to_free=False).f1


def scores(sets, model, workers):
    """Mean matched-room F1 (%) of each set's maps segmented with model, as `topocut evaluate` scores."""
    jobs = [(image, truth, model) for maps in sets.values() for image, truth in maps]
    with ProcessPoolExecutor(workers) as pool:
        f1 = iter(pool.map(_f1_of_map, jobs, chunksize=4))
    return {name: 100.0 * float(np.mean([next(f1) for _ in maps])) for name, maps in sets.items()}


def plan_key(image):
    """A map's building, plan or sketch: its plain and furnished images, both annotators' rooms and its
    robot-made maps share it."""
    name = os.path.basename(image)[: -len(".png")].replace("_furnitures", "")
    return re.sub(r"_s\d+$", "", name)


def without_kind(sets, kind):
    """The sets with kind left out, and with it the robot-made maps of its plans."""
    return {s: m for s, m in sets.items() if kind_of(s) != kind and PLAN_KIND.get(s) != kind}


def generalisation(topocut, sets, workers, folds, with_kinds=True):
    """Matched-room F1 per set: fitted on every kind; fitted without the set's kind (and the robot-made
    maps of its plans; skipped unless with_kinds); and on maps whose building, plan or sketch was not
    fitted on (folds folds, none when 0)."""
    quiet = lambda s: print("train_merge_model: " + s, file=sys.stderr)
    full = scores(sets, train(topocut, sets, workers, quiet), workers)
    others = {}
    for kind in KINDS if with_kinds else []:
        model = train(topocut, without_kind(sets, kind), workers, quiet)
        others.update(scores({s: sets[s] for s in KINDS[kind]}, model, workers))
    fold = lambda image: zlib.crc32(plan_key(image).encode()) % folds
    unseen = {name: [] for name in sets}
    for f in range(folds):
        trained = {name: [m for m in maps if fold(m[0]) != f] for name, maps in sets.items()}
        held = {name: [m for m in maps if fold(m[0]) == f] for name, maps in sets.items()}
        held = {name: maps for name, maps in held.items() if maps}
        for name, f1 in scores(held, train(topocut, trained, workers, quiet), workers).items():
            unseen[name].append((f1, len(held[name])))
    print("| set | kind | fitted on every kind |" + (" fitted without its kind |" if with_kinds else "") +
          (f" on maps not fitted on ({folds} folds) |" if folds else ""))
    print("|---|---|---|" + ("---|" if with_kinds else "") + ("---|" if folds else ""))
    for name in sets:
        row = f"| {name} | {kind_of(name)} | {full[name]:.1f} |"
        if with_kinds:
            row += f" {others[name]:.1f} ({others[name] - full[name]:+.1f}) |"
        if folds:
            fold_f1 = sum(f * n for f, n in unseen[name]) / sum(n for _, n in unseen[name])
            row += f" {fold_f1:.1f} ({fold_f1 - full[name]:+.1f}) |"
        print(row)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="the build folder holding python/topocut and topocut")
    parser.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"), help="the folder holding datasets/")
    parser.add_argument("--robot-maps", default=None,
                        help="where the robot-made maps are made (default BUILD/robot_maps; kept between runs)")
    parser.add_argument("--out", default=MODEL_FILE, help="where to write the model")
    parser.add_argument("--workers", type=int, default=2, help="processes segmenting maps at once")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 unless --out equals what training produces (77: no data sets to train on)")
    parser.add_argument("--generalisation", action="store_true", help="print the leave-one-kind-out and fold table")
    parser.add_argument("--folds", type=int, default=FOLDS,
                        help=f"--generalisation: folds by building, plan or sketch (default {FOLDS}; 0: leave-one-kind-out only)")
    parser.add_argument("--no-kinds", action="store_true", help="--generalisation: the folds only, no leave-one-kind-out")
    parser.add_argument("--every", type=int, default=1,
                        help="a quicker check: every N-th map of the sets of more than 100 maps (homes, robot-made homes), "
                             "for fitting and scoring; the model file records the maps it was fitted on")
    args = parser.parse_args()
    if args.folds < 0 or args.folds == 1:
        parser.error("--folds must be 0 or at least 2")
    if args.every < 1:
        parser.error("--every must be at least 1")
    if args.every > 1 and args.check:
        parser.error("--check compares with a model fitted on every map: --every leaves some out")
    if args.no_kinds and args.folds == 0:
        parser.error("--no-kinds with --folds 0 leaves nothing to measure")
    if not os.path.isdir(os.path.join(args.shared, "datasets")):
        print(f"train_merge_model: skipped: no {os.path.join(args.shared, 'datasets')} to train on", file=sys.stderr)
        return SKIPPED if args.check else 1
    sys.path.insert(0, os.path.join(args.build, "python"))
    import topocut
    progress = lambda s: print("train_merge_model: " + s, file=sys.stderr)
    sets = datasets(args.shared, os.path.join(args.build, "topocut"), args.robot_maps or os.path.join(args.build, "robot_maps"),
                    progress)
    sets = {name: maps[:: args.every] if len(maps) > 100 else maps for name, maps in sets.items()}
    if args.generalisation:
        generalisation(topocut, sets, args.workers, args.folds, not args.no_kinds)
        return 0
    text = train(topocut, sets, args.workers, progress)
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
