#!/usr/bin/env python3
"""Writes the topocut package's type stubs from their template: every "@KEYWORDS kind@" line becomes
one "name: type = default," line per keyword option of that kind, every "@DOCS kind@" line one
"name: help" line each, from topocut._topocut._keywords(kind) (the option table), so that the stubs
list exactly the keywords the module accepts, with their defaults.

    PYTHONPATH=build/python python3 src/python/generate_stubs.py TEMPLATE OUTPUT
"""
import os
import re
import sys

# The built package from PYTHONPATH, not the sources beside this script (which lack the extension).
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]
from topocut import _topocut  # noqa: E402

MARKER = re.compile(r"^(\s*)@(KEYWORDS|DOCS) (\w+)@\s*$")


def expand(line):
    match = MARKER.match(line)
    if not match:
        return [line]
    indent, what, kind = match.groups()
    rows = _topocut._keywords(kind)
    if what == "KEYWORDS":
        return [f"{indent}{name}: {type_name} = {default!r},\n" for name, type_name, default, _ in rows]
    return [f"{indent}{name}: {help_text}\n" for name, _, _, help_text in rows]


def main():
    template, output = sys.argv[1:3]
    with open(template, encoding="utf-8") as f:
        lines = [expanded for line in f for expanded in expand(line)]
    text = "".join(lines)
    if "@KEYWORDS" in text or "@DOCS" in text:
        sys.exit(f"{template}: a marker was not on a line of its own")
    with open(output, "w", encoding="utf-8") as f:
        f.write("# Generated from __init__.pyi.in by src/python/generate_stubs.py; do not edit.\n" + text)


if __name__ == "__main__":
    main()
