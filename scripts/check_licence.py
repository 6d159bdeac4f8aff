#!/usr/bin/python3
"""The project's licence said one way everywhere a user or a packager reads it: LICENSE, the folder
statement (.reuse/dep5), both ROS package.xml files, the Python metadata (pyproject.toml), the CMake
package (topocut_LICENSE) and the pkg-config file. Exit 1 naming each place that says otherwise.

    check_licence.py SOURCE_DIR
"""
import pathlib
import re
import sys

LICENCE = "GPL-3.0-or-later"

# (file, what must be found in it, where a reader meets it)
PLACES = [
    ("LICENSE", "SPDX-License-Identifier: " + LICENCE, "the licence file"),
    ("LICENSE", "GNU GENERAL PUBLIC LICENSE\n                       Version 3, 29 June 2007", "the licence's full text"),
    (".reuse/dep5", "Files: *\nCopyright: 2026 the topocut authors\nLicense: " + LICENCE, "the folder statement"),
    ("ros/package.xml", "<license>" + LICENCE + "</license>", "the ROS package topocut"),
    ("ros/topocut_msgs/package.xml", "<license>" + LICENCE + "</license>", "the ROS package topocut_msgs"),
    ("pyproject.toml", 'license = {text = "' + LICENCE + '"}', "the Python package's metadata"),
    ("pyproject.toml", "GNU General Public License v3 or later (GPLv3+)", "the Python package's classifier"),
    ("cmake/topocutConfig.cmake.in", 'set(topocut_LICENSE "' + LICENCE + '")', "the CMake package"),
    ("cmake/topocut.pc.in", LICENCE, "the pkg-config file's Description"),
    ("README.md", LICENCE, "the README"),
]


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    wrong = []
    for name, wanted, where in PLACES:
        path = root / name
        text = path.read_text(encoding="utf-8") if path.exists() else ""
        if wanted not in text:
            wrong.append(f"{name} ({where}) does not say {wanted!r}")
    # No place may still say the project has no licence.
    for name in {p[0] for p in PLACES}:
        path = root / name
        if path.exists() and re.search(r"unspecified|states none", path.read_text(encoding="utf-8")):
            wrong.append(f"{name} still says the licence is unspecified")
    for line in wrong:
        print("check_licence: " + line)
    if not wrong:
        print(f"check_licence: {LICENCE} in all {len(PLACES)} places")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
