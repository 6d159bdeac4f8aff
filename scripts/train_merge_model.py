#!/usr/bin/python3
"""Fits topocut's merge model to people's rooms and writes src/segmentation/merging/merge_model.txt.

    /usr/bin/python3 scripts/train_merge_model.py                 # retrain: writes the model file
    /usr/bin/python3 scripts/train_merge_model.py --check         # exit 1 unless the shipped file is what this produces
    /usr/bin/python3 scripts/train_merge_model.py --generalisation  # leave-one-kind-out and 5-fold tables
    /usr/bin/python3 scripts/train_merge_model.py --generalisation --folds 0 --every 5  # a quicker check (minutes)
    ... --generalisation --folds 0 --every 5 --seed 2 --out M.txt  # the same on a bootstrap sample: a change
                                                                   # counts when it moves more than this does
    ... --segment-option oversegment=0.3 --out M.txt  # a model for maps segmented with other options
                                                       # (topocut segment --oversegment 0.3 --merge-model M.txt)

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
import inspect
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
SEED = 0  # 0 with BAG 1: every map once; otherwise the seed of the bootstrap samples
BAG = 1  # models averaged, each fitted on its own bootstrap sample of the maps
RESOLUTION = 0.05  # metres a cell: the Bormann-layout images hold no scale (merge_training_rows's default too)
TREES = dict(n_estimators=300, max_depth=5, learning_rate=0.05, max_bin=256)
SEGMENT_OPTIONS = {}  # --segment-option: the segmenter's keyword options for the rows and the scores (none: its defaults)
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
    image, truth, policy, options = job
    x, same, purity, _ = topocut.merge_training_rows(image, truth, merge_model=policy, **options)
    return x, same, purity


def draws(sets, seed, bag):
    """How many times each member of the bag draws each map, {set name: array (bag, maps)}: every map once
    for a single model of seed 0 (the shipped model's sample); otherwise, per member, as many maps drawn
    with replacement within each set as it holds (a bootstrap; numpy's generator seeded by seed and member)."""
    if bag == 1 and seed == 0:
        return {name: np.ones((1, len(maps))) for name, maps in sets.items()}
    out = {name: np.zeros((bag, len(maps))) for name, maps in sets.items()}
    for member in range(bag):
        rng = np.random.default_rng([seed, member + 1])
        for name, maps in sets.items():
            out[name][member] = rng.multinomial(len(maps), np.full(len(maps), 1.0 / len(maps)))
    return out


def rows(sets, policy, workers, drawn):
    """Features, labels and one weight column per member of the bag (drawn: draws()) of every candidate
    merge on the sets' maps, merging with policy; maps no member draws are not segmented."""
    jobs, share = [], []
    kinds = {kind_of(s) for s in sets}
    for name, maps in sets.items():
        in_kind = sum(1 for s in sets if kind_of(s) == kind_of(name))
        for (image, truth), counts in zip(maps, drawn[name].T):
            if counts.any():
                jobs.append((image, truth, policy, SEGMENT_OPTIONS))
                share.append(counts / len(kinds) / in_kind / len(maps))
    with ProcessPoolExecutor(workers) as pool:
        found = list(pool.map(_rows_of_map, jobs, chunksize=4))
    xs, ys, ws = [], [], []
    for (x, same, purity), map_share in zip(found, share):
        if len(x) == 0:
            continue
        xs.append(x)
        ys.append(same)
        ws.append(np.outer(purity, map_share) / len(x))
    return np.vstack(xs), np.concatenate(ys), np.vstack(ws)


def _fit_member(job):
    import xgboost
    x, y, w = job
    model = xgboost.XGBClassifier(tree_method="hist", n_jobs=1, random_state=SEED, base_score=0.5, **TREES)
    keep = w > 0
    model.fit(x[keep], y[keep], sample_weight=w[keep] / w[keep].mean())
    return [json.loads(dump) for dump in model.get_booster().get_dump(dump_format="json")]


def fit(x, y, w, workers):
    """The trees of each member of the bag (one per column of w), fitted in separate processes of one
    thread each (sums in one order: the same trees every time)."""
    jobs = [(x, y, w[:, member]) for member in range(w.shape[1])]
    if len(jobs) == 1:
        return [_fit_member(jobs[0])]
    with ProcessPoolExecutor(min(workers, len(jobs))) as pool:
        return list(pool.map(_fit_member, jobs))


def tree_lines(tree, names, scale=1.0):
    """One tree of XGBoost's JSON dump in the model file's form: nodes in preorder (a split's nodes come after
    it), leaves times scale. XGBoost sends x < t to its first child, the file x <= threshold: the threshold
    is the float below t (XGBoost compares in single precision)."""
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
            lines.append(f"leaf {node['leaf'] * scale:.9g}")
        else:
            threshold = float(np.nextafter(np.float32(node["split_condition"]), np.float32(-np.inf)))
            lines.append(f"split {names[int(node['split'][1:])]} {threshold:.9g} {at[node['yes']]} {at[node['no']]}")
    lines.append("end")
    return lines


def segment_option(text):
    """NAME=VALUE of --segment-option as a keyword option of topocut.segment (NAME as the command line or
    Python spells it; VALUE a number, true or false)."""
    name, sep, value = text.partition("=")
    if not sep or not name or not value:
        raise argparse.ArgumentTypeError(f"'{text}' is not NAME=VALUE (e.g. oversegment=0.3)")
    words = {"true": True, "false": False}
    if value.lower() in words:
        return name.lstrip("-").replace("-", "_"), words[value.lower()]
    try:
        number = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{value}' of {name} is not a number, true or false")
    return name.lstrip("-").replace("-", "_"), int(number) if number.is_integer() and "." not in value else number


def segment_flags():
    """SEGMENT_OPTIONS as topocut's command line spells them (a switch set false is its default: left out)."""
    flag = lambda n: "--" + n.replace("_", "-")
    return " ".join(flag(n) if v is True else f"{flag(n)} {v}" for n, v in SEGMENT_OPTIONS.items() if v is not False)


def model_text(topocut, members, sets, row_count, seed):
    """The model as the library reads it (merge_model.h): a header saying what it was fitted on, then each
    tree's nodes in order. A bag's members are averaged: their margins' mean is the sum of every member's
    trees with the leaves divided by the members' count (each member's bias is 0)."""
    import xgboost
    names = topocut.merge_feature_names()
    fitted_on = "; ".join(f"{kind}: " + ", ".join(f"{s} ({len(sets[s])} maps)" for s in KINDS[kind] if s in sets)
                          for kind in KINDS if any(s in sets for s in KINDS[kind]))
    lines = ["# topocut's merge model: p(one room) = 1 / (1 + exp(-(bias + the sum of the trees' leaves))).",
             "# Written by scripts/train_merge_model.py (retrain: /usr/bin/python3 scripts/train_merge_model.py).",
             (f"# {len(members)} models, each fitted on a bootstrap sample of the maps (seed {seed}), averaged: " if len(members) > 1
              else "# " if seed == 0 else f"# fitted on a bootstrap sample of the maps (seed {seed}): ") +
             f"{TREES['n_estimators']} trees of depth {TREES['max_depth']}{' each' if len(members) > 1 else ''}, "
             f"{ROUNDS} rounds, {row_count} candidate merges, fitted on {fitted_on}.",
             f"# XGBoost {xgboost.__version__}, NumPy {np.__version__}.",
             *([f"# Fitted with the segment options {segment_flags()}: give them to topocut with this model."]
               if segment_flags() else []),
             "# A split goes to its first node when the feature is at most the threshold.",
             "topocut-merge-model 1", "threshold 0.5", "bias 0"]
    for trees in members:
        for tree in trees:
            lines += tree_lines(tree, names, 1.0 / len(members))
    return "\n".join(lines) + "\n"


def train(topocut, sets, workers, progress=print, seed=SEED, bag=BAG):
    """The model text after ROUNDS rounds of gathering rows and fitting (a bag of bag models, averaged)."""
    policy, xs, ys, ws = FIRST_ROUND, [], [], []
    drawn = draws(sets, seed, bag)
    for r in range(ROUNDS):
        x, y, w = rows(sets, policy, workers, drawn)
        xs.append(x), ys.append(y), ws.append(w)
        count = sum(len(v) for v in ys)
        policy = model_text(topocut, fit(np.vstack(xs), np.concatenate(ys), np.vstack(ws), workers), sets, count, seed)
        progress(f"round {r + 1} of {ROUNDS}: {count} rows")
    return policy


def _f1_of_map(job):
    import topocut
    image, truth, model, options = job
    m = topocut.load_map(image, resolution=RESOLUTION)
    result = topocut.segment(m.grid, m.resolution, m.origin, merge_model=model, **options)
    return topocut.evaluate(result, truth, free=image, clip_to_free=False).f1


def scores(sets, model, workers):
    """Mean matched-room F1 (%) of each set's maps segmented with model, as `topocut evaluate` scores."""
    jobs = [(image, truth, model, SEGMENT_OPTIONS) for maps in sets.values() for image, truth in maps]
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


def generalisation(topocut, sets, workers, folds, with_kinds=True, seed=SEED, bag=BAG, out=None):
    """Matched-room F1 per set: fitted on every kind (that model written to out, unless None); fitted
    without the set's kind (and the robot-made maps of its plans; skipped unless with_kinds); and on maps
    whose building, plan or sketch was not fitted on (folds folds, none when 0)."""
    quiet = lambda s: print("train_merge_model: " + s, file=sys.stderr)
    text = train(topocut, sets, workers, quiet, seed, bag)
    if out:
        with open(out, "w") as f:
            f.write(text)
    full = scores(sets, text, workers)
    others = {}
    for kind in KINDS if with_kinds else []:
        model = train(topocut, without_kind(sets, kind), workers, quiet, seed, bag)
        others.update(scores({s: sets[s] for s in KINDS[kind]}, model, workers))
    fold = lambda image: zlib.crc32(plan_key(image).encode()) % folds
    unseen = {name: [] for name in sets}
    for f in range(folds):
        trained = {name: [m for m in maps if fold(m[0]) != f] for name, maps in sets.items()}
        held = {name: [m for m in maps if fold(m[0]) == f] for name, maps in sets.items()}
        held = {name: maps for name, maps in held.items() if maps}
        for name, f1 in scores(held, train(topocut, trained, workers, quiet, seed, bag), workers).items():
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
    parser.add_argument("--out", default=MODEL_FILE,
                        help="where to write the model (--generalisation: the model fitted on every kind, when given)")
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
    parser.add_argument("--seed", type=int, default=SEED,
                        help=f"the bootstrap samples' seed (default {SEED}: with --bag 1, every map once, as shipped); "
                             "another seed with --bag 1 measures how far the model moves with its sample")
    parser.add_argument("--bag", type=int, default=BAG, help=f"models averaged, each on a bootstrap sample of the maps (default {BAG})")
    parser.add_argument("--trees", type=int, default=TREES["n_estimators"], help="trees of each model (default %(default)s)")
    parser.add_argument("--depth", type=int, default=TREES["max_depth"], help="the trees' depth (default %(default)s)")
    parser.add_argument("--learning-rate", type=float, default=TREES["learning_rate"], help="default %(default)s")
    parser.add_argument("--segment-option", type=segment_option, action="append", default=[], metavar="NAME=VALUE",
                        help="a segmenter option for the training rows and the scores, as topocut.segment takes it "
                             "(repeatable; e.g. oversegment=0.3): the model is then for maps segmented with it, "
                             "and its file says so")
    args = parser.parse_args()
    if args.seed < 0 or args.bag < 1 or args.trees < 1 or not 1 <= args.depth <= 12 or args.learning_rate <= 0:
        parser.error("--seed must be at least 0, --bag and --trees at least 1, --depth 1-12, --learning-rate positive")
    TREES.update(n_estimators=args.trees, max_depth=args.depth, learning_rate=args.learning_rate)
    SEGMENT_OPTIONS.update(args.segment_option)
    if args.folds < 0 or args.folds == 1:
        parser.error("--folds must be 0 or at least 2")
    if args.every < 1:
        parser.error("--every must be at least 1")
    if args.every > 1 and args.check:
        parser.error("--check compares with a model fitted on every map: --every leaves some out")
    if args.segment_option and args.check:
        parser.error("--check compares with the shipped model, fitted with the segmenter's defaults")
    if args.no_kinds and args.folds == 0:
        parser.error("--no-kinds with --folds 0 leaves nothing to measure")
    if not os.path.isdir(os.path.join(args.shared, "datasets")):
        print(f"train_merge_model: skipped: no {os.path.join(args.shared, 'datasets')} to train on", file=sys.stderr)
        return SKIPPED if args.check else 1
    sys.path.insert(0, os.path.join(args.build, "python"))
    import topocut
    known = inspect.signature(topocut.merge_training_rows).parameters
    unknown = [n for n in SEGMENT_OPTIONS if n not in known or n in ("image", "ground_truth", "resolution", "merge_model")]
    if unknown:
        parser.error(f"--segment-option: no segmenter option {', '.join(unknown)} (topocut segment --help lists them)")
    try:  # a value out of range is refused here, with the library's message, not in every worker
        topocut.segment(np.zeros((8, 8), np.int8), RESOLUTION, **SEGMENT_OPTIONS)
    except ValueError as error:
        parser.error(f"--segment-option: {error}")
    progress = lambda s: print("train_merge_model: " + s, file=sys.stderr)
    sets = datasets(args.shared, os.path.join(args.build, "topocut"), args.robot_maps or os.path.join(args.build, "robot_maps"),
                    progress)
    sets = {name: maps[:: args.every] if len(maps) > 100 else maps for name, maps in sets.items()}
    if args.generalisation:
        generalisation(topocut, sets, args.workers, args.folds, not args.no_kinds, args.seed, args.bag,
                       args.out if args.out != MODEL_FILE else None)
        return 0
    text = train(topocut, sets, args.workers, progress, args.seed, args.bag)
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
