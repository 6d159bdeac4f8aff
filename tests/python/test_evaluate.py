# topocut.evaluate: hand-made labels with hand-computed scores, and the same figures as the
# `topocut evaluate --labels` command on the same images.
import csv
import subprocess

import numpy as np
import pytest
from PIL import Image

import topocut
from conftest import SHARED_DIR


def strip_of_rooms(n=13):
    """A ground truth of n rooms of 12 x 10 px in a row, separated by one-pixel lines."""
    gt = np.zeros((12, 2 + 13 * n), np.uint8)
    for k in range(n):
        gt[1:11, 1 + 13 * k:13 + 13 * k] = 255
    return gt


def test_three_segments_over_thirteen_rooms():
    gt = strip_of_rooms()
    labels = np.zeros(gt.shape, np.int32)
    labels[1:11, 1:13] = 1            # room 1 exactly
    labels[1:11, 14:91] = 2           # rooms 2..7 and five separators
    labels[1:11, 92:169] = 3          # rooms 8..13
    s = topocut.evaluate(labels, gt)
    assert (s.matches, s.false_positives, s.false_negatives) == (1, 2, 12)
    assert s.f1 == pytest.approx(1 / 8)
    assert s.pq == pytest.approx(1 / 8)
    assert s.segments_per_room == pytest.approx(3 / 13)
    assert s.recall == pytest.approx(1.0)
    assert s.precision == pytest.approx((1 + 2 * 120 / 770) / 3)


def test_free_pixels_and_clipping():
    gt = np.zeros((20, 80), np.uint8)
    gt[5:15, 5:35] = 255                      # one room, 300 px
    labels = np.zeros(gt.shape, np.uint16)
    labels[5:20, 5:45] = 7                    # the room and 300 px of wall
    free = gt > 0
    assert topocut.evaluate(labels, gt).matches == 0          # IoU 300 / 600
    clipped = topocut.evaluate(labels, gt, free=free)
    assert clipped.matches == 1 and clipped.precision == pytest.approx(1.0)
    as_given = topocut.evaluate(labels, gt, free=free, clip_to_free=False)
    assert as_given.matches == 1 and as_given.precision == pytest.approx(0.5)
    assert as_given.precision_inside == pytest.approx(1.0)
    # More than 0.5 m (10 px) from the room: the corner pixels (dy, dx) below and right of it with
    # dx² + dy² > 100: (1..4, 10) and (5, 9..10), 6 of the 600 labelled.
    assert as_given.far_share == pytest.approx(6 / 600)
    far = labels.copy()
    far[0:5, 60:80] = 8                       # 100 px, 26 to 55 px from the room
    assert topocut.evaluate(far, gt).far_share == pytest.approx(106 / 700)


@pytest.mark.parametrize("labels, gt, message", [
    (np.zeros((4, 4), np.float32), np.zeros((4, 4), np.uint8), "integers"),
    (np.zeros((4, 4), np.int32), np.zeros((4, 5), np.uint8), "pixels"),
    (np.zeros((4, 4), np.int32), np.zeros((4, 4), np.int32), "uint8"),
    (np.zeros(4, np.int32), np.zeros((4, 4), np.uint8), "2-D"),
])
def test_bad_input_is_a_value_error(labels, gt, message):
    with pytest.raises(ValueError, match=message):
        topocut.evaluate(labels, gt)


def write_png(path, array, mode=None):
    Image.fromarray(array, mode).save(path) if mode else Image.fromarray(array).save(path)


def cli_rows(cli, dataset, labels, tmp_path):
    out = tmp_path / "scores.csv"
    run = subprocess.run([cli, "evaluate", "--dataset", str(dataset), "--labels", str(labels), "--csv", str(out)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    with open(out) as f:
        return [row for row in csv.DictReader(f) if row["status"] == "ok"]


def assert_same_as_cli(row, scores):
    for column, value in [("recall", scores.recall), ("precision", scores.precision), ("f1", scores.f1),
                          ("pq", scores.pq), ("segments_per_room", scores.segments_per_room),
                          ("precision_inside", scores.precision_inside), ("far_share", scores.far_share)]:
        assert row[column] == f"{value:.6f}", (row["map"], column)
    assert int(row["rooms"]) == scores.segments and int(row["gt_rooms"]) == scores.rooms
    assert int(row["matches"]) == scores.matches


def test_the_same_figures_as_the_command(cli, tmp_path):
    data, labels = tmp_path / "data", tmp_path / "labels"
    data.mkdir()
    labels.mkdir()
    gt = strip_of_rooms(6)
    world = gt.copy()
    world[1:11, 13] = 255                     # the map has a door where the ground truth draws a line
    world[3:6, 20:24] = 0                     # and a table
    for name in ("grey", "wide", "colour"):
        write_png(data / f"{name}.png", world)
        write_png(data / f"{name}_gt_segmentation.png", gt)
    grey = np.zeros(gt.shape, np.uint8)
    grey[0:12, 0:30] = 3                      # over walls and the door, two rooms and a half
    grey[1:11, 30:79] = 9
    write_png(labels / "grey.png", grey)
    write_png(labels / "wide.png", (grey.astype(np.uint16) * 1000), "I;16")
    colour = np.zeros(gt.shape + (3,), np.uint8)
    colour[grey == 3] = (200, 30, 0)
    colour[grey == 9] = (0, 0, 90)
    write_png(labels / "colour.png", colour)
    rows = cli_rows(cli, data, labels, tmp_path)
    assert [r["map"] for r in rows] == ["colour", "grey", "wide"]
    for row in rows:
        scores = topocut.evaluate(str(labels / f"{row['map']}.png"), str(data / f"{row['map']}_gt_segmentation.png"),
                                  free=str(data / f"{row['map']}.png"))
        assert_same_as_cli(row, scores)
    assert rows[0]["f1"] == rows[1]["f1"] == rows[2]["f1"]


def test_the_same_figures_as_the_command_on_a_peer(cli, tmp_path):
    sketches, peer = SHARED_DIR / "datasets" / "sketches" / "lex", SHARED_DIR / "datasets" / "peers" / "sketches" / "voronoi"
    if not peer.is_dir():
        pytest.skip(f"{peer} is absent (the peers' results live in ../shared)")
    rows = cli_rows(cli, sketches, peer, tmp_path)
    assert len(rows) == 12
    for row in rows:
        scores = topocut.evaluate(str(peer / f"{row['map']}.png"), str(sketches / f"{row['map']}_gt_segmentation.png"),
                                  free=str(sketches / f"{row['map']}.png"))
        assert_same_as_cli(row, scores)
