# One spelling per option: every keyword Python takes from the library's option tables is the flag of
# the command line with '_' for '-', with the same default (the C++ side, tests/cli/option_spelling_test.cpp,
# checks the command line and --config against the tables themselves; ros/test/adapter_test.cpp the node).
import inspect
import subprocess

import numpy as np
import pytest

import topocut

# How an array's cells are read: the row order (no flag) and map_server's thresholds (a map YAML's keys
# on the command line, ROS parameters on the node). The grey thresholds are the commands' flags.
GRID_READING = {"row_order", "free_thresh", "occupied_thresh"}


def shortest(value):
    """A number as the command's help shows it (C++'s shortest round trip: 2.5, 1, 0.0125)."""
    text = repr(float(value))
    return text[:-2] if text.endswith(".0") else text


def help_text(cli, command):
    return subprocess.run([cli, command, "--help"], capture_output=True, text=True, timeout=30, check=True).stdout


def expected_line(name, type_name, default, cli_help):
    flag = "--" + name.replace("_", "-")
    if type_name == "bool":
        # A switch on by default takes true or false; one off by default is a bare flag.
        return f"\n  {flag} true|false (=true)" if default else f"\n  {flag} "
    # The value name is the table's; the default must follow it.
    at = cli_help.find(f"\n  {flag} ")
    assert at >= 0, flag
    value_name = cli_help[at + len(flag) + 4:].split(" ", 1)[0]
    return f"\n  {flag} {value_name} (={shortest(default)})"


def check_keywords_against_help(kind, cli_help):
    walked = 0
    for name, type_name, default, _help in topocut._topocut._keywords(kind):
        if name in GRID_READING:
            continue
        if name == "merge_model":  # a FILE on the command line, the model's text in Python
            assert "\n  --merge-model FILE" in cli_help
            assert default is None
            continue
        line = expected_line(name, type_name, default, cli_help)
        assert cli_help.count(line) == 1, (kind, name, line)
        walked += 1
    return walked


def test_every_segment_keyword_is_the_commands_flag_with_its_default(cli):
    assert check_keywords_against_help("segment", help_text(cli, "segment")) > 60


def test_grid_keywords_are_the_map_flags_and_checked_as_there(cli, bundled_map):
    names = {name for name, *_ in topocut._topocut._keywords("grid")}
    assert {"fixed_thresholds", "free_threshold", "occupied_threshold", "free_thresh", "occupied_thresh"} <= names
    grid = np.full((20, 20), 255, dtype=np.uint8)
    with pytest.raises(ValueError, match="^free_threshold must be a grey level, a whole number in 0..255$"):
        topocut.segment(grid, 0.05, free_threshold=300)
    with pytest.raises(ValueError, match=r"^free_thresh must be a share in \[0, 1\]$"):
        topocut.segment(grid.astype(np.int8), 0.05, free_thresh=1.5)
    done = subprocess.run([cli, "segment", bundled_map, "--free-threshold", "300"], capture_output=True, text=True, timeout=30)
    assert done.returncode == 2 and "--free-threshold must be a grey level, a whole number in 0..255" in done.stderr, done.stderr


def test_every_incremental_keyword_is_the_explore_commands_flag_with_its_default(cli):
    # explore runs the incremental segmenter with IncrementalOptions' defaults, as Python's does.
    walked = check_keywords_against_help("incremental", help_text(cli, "explore"))
    assert walked > 70
    names = [name for name, *_ in topocut._topocut._keywords("incremental")]
    assert len(names) == len(set(names))  # no keyword twice (the incremental and segment tables share none)
    for name in ("split_after", "merge_after", "neighbours_across_doors", "neighbours_across_cuts", "batch_fraction"):
        assert name in names


def test_incremental_keywords_are_checked_as_on_the_command_line(cli, bundled_map):
    with pytest.raises(ValueError, match="^split_after must be a whole number >= 1$"):
        topocut.IncrementalSegmenter(split_after=1.5)
    with pytest.raises(ValueError, match="^neighbours_across_doors is a switch: give true or false, not '0'$"):
        topocut.IncrementalSegmenter(neighbours_across_doors=0)
    done = subprocess.run([cli, "explore", bundled_map, "--split-after", "1.5"], capture_output=True, text=True, timeout=30)
    assert done.returncode == 2 and "--split-after must be a whole number >= 1" in done.stderr, done.stderr


def test_grid_keywords_are_set_in_the_tables_order_whatever_order_they_are_given_in():
    # A grey band (220) between two white rooms: the palette reads it as not free, a fixed free
    # threshold of 200 as free, so the two readings give different rooms.
    grid = np.zeros((60, 100), dtype=np.uint8)
    grid[5:55, 5:95] = 255
    grid[5:55, 48:52] = 220
    grid[0:60, 0:5] = 128
    palette = topocut.segment(grid, 0.05).labels
    fixed = topocut.segment(grid, 0.05, fixed_thresholds=True, free_threshold=200).labels
    assert not np.array_equal(palette, fixed)
    for kwargs in ({"fixed_thresholds": False, "free_threshold": 200}, {"free_threshold": 200, "fixed_thresholds": False}):
        assert np.array_equal(topocut.segment(grid, 0.05, **kwargs).labels, fixed), kwargs


def signature_default(function, name):
    """The default of keyword name in function's signature line (pybind11's docstring), as text."""
    import re
    first = function.__doc__.splitlines()[0]
    found = re.search(r"\b" + name + r": [\w.]+ = ('?[\w.]+'?)", first)
    assert found, (name, first)
    return found.group(1)


def test_functions_without_an_options_struct_take_their_commands_rows(cli):
    # decompose's tau, extract_lines' method and simulate_map's seed are the decompose, lines and
    # simulate-map commands' rows: one name, one default, one check.
    assert f"\n  --tau T (={signature_default(topocut.decompose, 'tau')})" in help_text(cli, "decompose")
    lines = help_text(cli, "lines")
    method = signature_default(topocut.extract_lines, "method").strip("'")
    names = lines.split("\n  --method ", 1)[1].split(" ", 1)[0].split("|")
    assert f"\n  --method {'|'.join(names)} (={method})" in lines
    assert all(callable(getattr(topocut, name)) for name in names)  # one function per name, no other
    seed = signature_default(topocut._topocut.simulate_map, "seed")
    assert f"\n  --seed N (={seed})" in help_text(cli, "simulate-map")
    assert str(inspect.signature(topocut.simulate_map).parameters["seed"].default) == seed  # the package's wrapper
    with pytest.raises(ValueError, match="^--tau must be a positive number$"):
        topocut.decompose([[0, 0], [1, 0], [1, 1]], tau=0.0)
    with pytest.raises(ValueError, match="^--method must be one of 'sef', 'lt', 'iepf', 'smf', 'ale', got 'SMF'$"):
        topocut.extract_lines([0.0, 0.1], [1.0, 1.0], method="SMF")
    done = subprocess.run([cli, "lines", "-", "--method", "SMF"], input="angle,range\n", capture_output=True, text=True, timeout=30)
    assert done.returncode == 2 and "--method must be one of 'sef', 'lt', 'iepf', 'smf', 'ale', got 'SMF'" in done.stderr
